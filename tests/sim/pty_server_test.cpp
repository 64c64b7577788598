#include "armmimic/sim/pty_server.h"

#include <chrono>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "test_util.h"

namespace armmimic::sim {
namespace {

// Reads from `fd` until `want` shows up or 5 s pass.
std::string ReadUntil(int fd, const std::string& want) {
  std::string got;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  char buf[256];
  while (got.find(want) == std::string::npos && std::chrono::steady_clock::now() < end) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 50) > 0) {
      const ssize_t n = read(fd, buf, sizeof(buf));
      if (n > 0) got.append(buf, static_cast<std::size_t>(n));
    }
  }
  return got;
}

int OpenRaw(const std::string& path) {
  const int fd = open(path.c_str(), O_RDWR | O_NOCTTY);
  if (fd < 0) return fd;
  termios tio{};
  tcgetattr(fd, &tio);
  cfmakeraw(&tio);
  tcsetattr(fd, TCSANOW, &tio);
  return fd;
}

TEST(PtyServer, AnswersOnItsDeviceAndLogsMoves) {
  test::TempDir dir;
  EmulatorOptions o;
  o.time_scale = 0.01;
  PtyServer server(o);
  ASSERT_TRUE(server.Start(dir.file("puma"), dir.file("moves.log")).ok());
  ASSERT_FALSE(server.device_path().empty());
  char target[256] = {0};
  ASSERT_GT(readlink(dir.file("puma").c_str(), target, sizeof(target) - 1), 0);
  EXPECT_EQ(std::string(target), server.device_path());

  const int fd = OpenRaw(dir.file("puma"));
  ASSERT_GE(fd, 0);
  ASSERT_EQ(write(fd, "\r", 1), 1);
  EXPECT_NE(ReadUntil(fd, "."), "");
  const std::string move = "DO MOVE #PPOINT(12.5,-80,1,2,3,4)\r";
  ASSERT_EQ(write(fd, move.data(), move.size()), static_cast<ssize_t>(move.size()));
  const std::string reply = ReadUntil(fd, ")\r\n.");
  EXPECT_NE(reply.find(")\r\n."), std::string::npos) << reply;
  close(fd);
  EXPECT_EQ(server.joints(), (robot::JointArray{12.5, -80, 1, 2, 3, 4}));
  EXPECT_EQ(server.log().size(), 1u);
  server.Stop();
  EXPECT_EQ(test::ReadFile(dir.file("moves.log")),
            "1\t12.500 -80.000 1.000 2.000 3.000 4.000\tDO MOVE #PPOINT(12.5,-80,1,2,3,4)\n");
  struct stat st {};
  EXPECT_NE(lstat(dir.file("puma").c_str(), &st), 0);  // the symlink went with the server
}

TEST(PtyServer, RefusesToReplaceARegularFileWithItsLink) {
  test::TempDir dir;
  test::WriteFile(dir.file("precious"), "keep me");
  PtyServer server;
  const Status s = server.Start(dir.file("precious"));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("precious"), std::string::npos);
  EXPECT_EQ(test::ReadFile(dir.file("precious")), "keep me");
}

TEST(PtyServer, ALineBaudRatePacesEveryByteBothWays) {
  // At 1200 baud a byte takes 1/120 s: "SPEED 50" CR in (9 bytes), its echo CR LF and the
  // prompt out (11 bytes) cannot come back sooner than 20 character times, 167 ms. The bound is
  // a lower one, so a slow machine cannot break it; the answer itself is the emulator's.
  test::TempDir dir;
  EmulatorOptions o;
  o.line_baud = 1200;
  PtyServer server(o);
  ASSERT_TRUE(server.Start(dir.file("puma")).ok());
  const int fd = OpenRaw(dir.file("puma"));
  ASSERT_GE(fd, 0);
  ASSERT_EQ(write(fd, "\r", 1), 1);
  ASSERT_NE(ReadUntil(fd, "."), "");
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(write(fd, "SPEED 50\r", 9), 9);
  const std::string got = ReadUntil(fd, "SPEED 50\r\n.");
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_NE(got.find("SPEED 50\r\n."), std::string::npos) << got;
  EXPECT_GE(s, 20 / 120.0 - 0.002);
  close(fd);
  server.Stop();
}

}  // namespace
}  // namespace armmimic::sim
