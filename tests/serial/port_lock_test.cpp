// One lock per device: two sends to one pseudo-terminal under two names (the link puma-sim makes
// and /dev/pts/N) cannot both run; the second is refused before it writes a byte and names the
// first one's process. Port paths resolve like any path.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "armmimic/serial/port_lock.h"
#include "armmimic/sim/pty_server.h"
#include "test_program.h"
#include "test_util.h"

namespace armmimic {
namespace {

using Clock = std::chrono::steady_clock;
using robot::JointArray;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

template <typename F>
bool WaitFor(F ready, double seconds = 20) {
  const auto until = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < until) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return ready();
}

// Runs from `dir` for the lifetime of the object.
class InFolder {
 public:
  explicit InFolder(const std::string& dir) : saved_(std::filesystem::current_path()) {
    std::filesystem::current_path(dir);
  }
  ~InFolder() { std::filesystem::current_path(saved_); }

 private:
  std::filesystem::path saved_;
};

TEST(PortLock, TwoNamesOfOneDeviceShareOneLockNamingTheHolder) {
  test::TempDir dir;
  // Program A moves J2 upwards from -90; program B's targets are all J1 = 77, which A never has.
  const test::Program a = test::MakeTimedProgram(
      8, "a", [](int i) -> JointArray { return {0, -90 + i * 2.0, 0, 0, 0, 0}; });
  const test::Program b = test::MakeTimedProgram(
      3, "b", [](int i) -> JointArray { return {77, -60 - i * 2.0, 0, 0, 0, 0}; });
  test::WriteFile(dir.file("a.val"), a.text);
  test::WriteFile(dir.file("b.val"), b.text);
  sim::PtyServer server(test::Fast());
  ASSERT_TRUE(server.Start(dir.file("puma")).ok());
  // The first send, through the link, held mid-stream by the controller.
  test::Child first({ARMMIMIC_CLI_PATH, "--no-progress", "send", dir.file("a.val"), "--port",
                     dir.file("puma"), "--timeout", "120"},
                    dir.file("a.out"), dir.file("a.err"));
  ASSERT_TRUE(first.started());
  ASSERT_TRUE(WaitFor([&] { return !server.log().empty(); })) << test::ReadFile(dir.file("a.err"));
  server.Hold(true);  // the first send now waits on its line in flight
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const int lines_before = server.lines_received();

  // The second, through the device's own name.
  const test::CliResult second =
      test::RunCli({"--no-progress", "send", dir.file("b.val"), "--port", server.device_path()});
  EXPECT_EQ(second.exit_code, 1) << second.err;
  EXPECT_TRUE(Contains(second.err, "--port: " + server.device_path())) << second.err;
  EXPECT_TRUE(Contains(second.err, "in use by process " + std::to_string(first.pid())))
      << second.err;
  EXPECT_EQ(server.lines_received(), lines_before) << "the refused send wrote to the device";
  // The other way round: a name the first one did not use, and the same name, are refused too.
  const test::CliResult third =
      test::RunCli({"--no-progress", "send", dir.file("b.val"), "--port", dir.file("puma")});
  EXPECT_EQ(third.exit_code, 1) << third.err;
  EXPECT_TRUE(Contains(third.err, "busy")) << third.err;

  server.Hold(false);
  const int status = first.Wait();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << test::ReadFile(dir.file("a.err"));
  // The controller ran A's moves, each once, and none of B's.
  const std::vector<sim::LoggedMove> log = server.log();
  ASSERT_EQ(log.size(), a.targets.size());
  for (std::size_t i = 0; i < log.size(); ++i) {
    EXPECT_NEAR(log[i].target_deg[0], 0.0, 0.01) << "move " << i + 1;
    EXPECT_NEAR(log[i].target_deg[1], a.targets[i][1], 0.01) << "move " << i + 1;
  }
  // Released with the process: the device is free for the next run.
  const test::CliResult after =
      test::RunCli({"--no-progress", "send", dir.file("b.val"), "--port", server.device_path()});
  EXPECT_EQ(after.exit_code, 0) << after.err;
  EXPECT_EQ(server.log().size(), a.targets.size() + b.targets.size());
  EXPECT_FALSE(std::filesystem::exists(serial::PortLock::LockPathFor(server.device_path())));
}

// A holder that dies (SIGKILL: no chance to let go) holds nothing: the next send runs.
TEST(PortLock, ALockOfAKilledSendIsNoLock) {
  test::TempDir dir;
  const test::Program a = test::MakeTimedProgram(
      4, "a", [](int i) -> JointArray { return {0, -90 + i * 2.0, 0, 0, 0, 0}; });
  test::WriteFile(dir.file("a.val"), a.text);
  test::WriteFile(dir.file("b.val"), a.text);
  sim::PtyServer server(test::Fast());
  ASSERT_TRUE(server.Start().ok());
  test::Child first({ARMMIMIC_CLI_PATH, "--no-progress", "send", dir.file("a.val"), "--port",
                     server.device_path(), "--timeout", "120"},
                    dir.file("a.out"), dir.file("a.err"));
  ASSERT_TRUE(first.started());
  ASSERT_TRUE(WaitFor([&] { return !server.log().empty(); })) << test::ReadFile(dir.file("a.err"));
  server.Hold(true);
  first.Signal(SIGKILL);
  first.Wait();
  server.Hold(false);
  const test::CliResult next =
      test::RunCli({"--no-progress", "send", dir.file("b.val"), "--port", server.device_path()});
  EXPECT_EQ(next.exit_code, 0) << next.err;
}

TEST(PortPaths, ARelativePathWithAFolderAndABareNameBothResolve) {
  test::TempDir dir;
  std::filesystem::create_directory(dir.file("s6"));
  const test::Program p = test::MakeTimedProgram(
      2, "p", [](int i) -> JointArray { return {5.0 * i, -80, 0, 0, 0, 0}; });
  test::WriteFile(dir.file("p.val"), p.text);
  test::WriteFile(dir.file("q.val"), p.text);
  sim::PtyServer server(test::Fast());
  ASSERT_TRUE(server.Start(dir.file("s6/puma")).ok());
  ASSERT_EQ(::symlink("s6/puma", dir.file("bare").c_str()), 0);
  test::CliResult relative, bare, missing;
  {
    InFolder here(dir.path());
    relative = test::RunCli({"--no-progress", "send", "p.val", "--port", "s6/puma"});
    bare = test::RunCli({"--no-progress", "send", "q.val", "--port", "bare"});
    missing = test::RunCli({"--no-progress", "send", "p.val", "--port", "no-such-puma"});
  }
  EXPECT_EQ(relative.exit_code, 0) << relative.err;
  EXPECT_EQ(bare.exit_code, 0) << bare.err;
  EXPECT_EQ(server.log().size(), 2 * p.targets.size());
  EXPECT_EQ(missing.exit_code, 1) << missing.err;
  EXPECT_TRUE(Contains(missing.err, "tried ./no-such-puma and /dev/no-such-puma")) << missing.err;
}

}  // namespace
}  // namespace armmimic
