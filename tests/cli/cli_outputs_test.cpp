// What -o names is written into, never replaced: a symlink's target, a FIFO's reader, a
// character device. A folder or a socket is refused (exit 2) before any input is read. A killed
// run's temporary is removed by the next run to the same output, and nothing else is.
#include <fcntl.h>
#include <pty.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <future>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/output_file.h"
#include "small_scene.h"

namespace armmimic {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

mode_t KindOf(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

const std::string& Scene() { return test::SmallScene(5, 10); }

// An lk analysis of the small scene writing to `out`.
std::vector<std::string> Analyze(const std::string& video, const std::string& out) {
  return {"--no-progress", "analyze", video,     "-o", out, "--engine", "lk",
          "--shoulder",    "80,40",   "--start", "20"};
}

AngleFile ParseAngles(const std::string& text) {
  AngleFile file;
  std::istringstream in(text);
  const Status st = ParseAngleFile(in, "received", &file);
  EXPECT_TRUE(st.ok()) << st.message() << "\n" << text;
  return file;
}

TEST(CliOutputs, AnalyzeWritesThroughASymlinkAndKeepsTheLink) {
  test::TempDir dir;
  fs::create_directory(dir.file("store"));
  test::WriteFile(dir.file("store/target.tsv"), "old contents\n");
  ASSERT_EQ(::symlink("store/target.tsv", dir.file("link.tsv").c_str()), 0);
  const test::CliResult r = test::RunCli(Analyze(Scene() + "/scene.avi", dir.file("link.tsv")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(KindOf(dir.file("link.tsv")), static_cast<mode_t>(S_IFLNK));
  const AngleFile angles = ParseAngles(test::ReadFile(dir.file("store/target.tsv")));
  EXPECT_GT(angles.rows.size(), 0u);
  // plan and background write through links as well.
  test::WriteFile(dir.file("store/p.val"), "old");
  ASSERT_EQ(::symlink("store/p.val", dir.file("p.val").c_str()), 0);
  const test::CliResult plan =
      test::RunCli({"plan", dir.file("link.tsv"), "-o", dir.file("p.val")});
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_EQ(KindOf(dir.file("p.val")), static_cast<mode_t>(S_IFLNK));
  EXPECT_TRUE(Contains(test::ReadFile(dir.file("store/p.val")), "armmimic VAL program"));
  for (const auto& e : fs::directory_iterator(dir.file("store"))) {
    EXPECT_EQ(e.path().filename().string()[0] == '.', false) << "left: " << e.path();
  }
}

TEST(CliOutputs, AnalyzeIntoAFifoHandsTheReaderTheWholeFile) {
  test::TempDir dir;
  const std::string fifo = dir.file("angles.fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reader = test::ReadFifoInBackground(fifo);
  const test::CliResult r = test::RunCli(Analyze(Scene() + "/scene.avi", fifo));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string received = reader.get();
  // The same bytes a regular file gets.
  const test::CliResult plain = test::RunCli(Analyze(Scene() + "/scene.avi", dir.file("a.tsv")));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(received, test::ReadFile(dir.file("a.tsv")));
  EXPECT_GT(ParseAngles(received).rows.size(), 0u);
  EXPECT_EQ(KindOf(fifo), static_cast<mode_t>(S_IFIFO));
}

// The case: `mknod x c 1 3` (the tests run as root) stays a device after analyze -o x,
// and a node of /dev/full gets the bytes too, which it refuses ("no space left"). A terminal
// reached through its own path (a node outside /dev/pts cannot reach one) receives the file.
TEST(CliOutputs, AnalyzeIntoACharacterDeviceWritesThroughIt) {
  test::TempDir dir;
  const std::string x = dir.file("x");
  ASSERT_EQ(::mknod(x.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0) << std::strerror(errno);
  const test::CliResult r = test::RunCli(Analyze(Scene() + "/scene.avi", x));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(KindOf(x), static_cast<mode_t>(S_IFCHR)) << "the device was replaced";
  const std::string full = dir.file("full");
  ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0) << std::strerror(errno);
  const test::CliResult f = test::RunCli(Analyze(Scene() + "/scene.avi", full));
  EXPECT_EQ(f.exit_code, 1) << f.err;
  EXPECT_TRUE(Contains(f.err, full)) << f.err;
  EXPECT_TRUE(Contains(f.err, "no space left on the device")) << f.err;
  EXPECT_EQ(KindOf(full), static_cast<mode_t>(S_IFCHR));

  int master = -1, slave = -1;
  char name[256] = {0};
  ASSERT_EQ(::openpty(&master, &slave, name, nullptr, nullptr), 0);
  termios raw{};
  ASSERT_EQ(::tcgetattr(slave, &raw), 0);
  ::cfmakeraw(&raw);
  ASSERT_EQ(::tcsetattr(slave, TCSANOW, &raw), 0);
  const int flags = ::fcntl(master, F_GETFL);
  ASSERT_EQ(::fcntl(master, F_SETFL, flags | O_NONBLOCK), 0);
  std::atomic<bool> done{false};
  auto reader = std::async(std::launch::async, [&] {
    std::string got;
    char buf[4096];
    for (;;) {
      const ssize_t n = ::read(master, buf, sizeof buf);
      if (n > 0) {
        got.append(buf, static_cast<std::size_t>(n));
      } else if (done) {
        break;
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    }
    return got;
  });
  const test::CliResult t = test::RunCli(Analyze(Scene() + "/scene.avi", name));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  done = true;
  const std::string received = reader.get();
  EXPECT_EQ(KindOf(name), static_cast<mode_t>(S_IFCHR));
  ::close(slave);
  ::close(master);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const test::CliResult plain = test::RunCli(Analyze(Scene() + "/scene.avi", dir.file("a.tsv")));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(received, test::ReadFile(dir.file("a.tsv")));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 3);
}

// Refused before any input is read: the video named does not even exist, and the message is
// about the output, with exit 2, not about the missing video (exit 1).
TEST(CliOutputs, AFolderOrASocketIsRefusedBeforeAnyInputIsRead) {
  test::TempDir dir;
  fs::create_directory(dir.file("folder.tsv"));
  const std::string sock = dir.file("sock.tsv");
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::strncpy(addr.sun_path, sock.c_str(), sizeof addr.sun_path - 1);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  const std::string missing = dir.file("no-such-video.avi");
  for (const auto& [out, words] :
       {std::pair<std::string, std::string>{dir.file("folder.tsv"), "is a folder"},
        {sock, "is a socket"}}) {
    SCOPED_TRACE(out);
    const test::CliResult r = test::RunCli(Analyze(missing, out));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(Contains(r.err, "-o " + out + ": " + words)) << r.err;
    EXPECT_FALSE(Contains(r.err, missing)) << r.err;
    EXPECT_EQ(test::RunCli({"plan", missing, "-o", out}).exit_code, 2);
  }
  // background's -o must look like an image: a folder named so is refused the same way.
  fs::create_directory(dir.file("bg.png"));
  const test::CliResult bg = test::RunCli({"background", missing, "-o", dir.file("bg.png")});
  EXPECT_EQ(bg.exit_code, 2) << bg.err;
  EXPECT_TRUE(Contains(bg.err, "-o " + dir.file("bg.png") + ": is a folder")) << bg.err;
  const test::CliResult score =
      test::RunCli({"score", missing, missing, "--plot", dir.file("bg.png")});
  EXPECT_EQ(score.exit_code, 2) << score.err;
  EXPECT_TRUE(Contains(score.err, "--plot " + dir.file("bg.png") + ": is a folder")) << score.err;
  // mimic's angle file, and puma-sim's move log.
  const test::CliResult mimic =
      test::RunCli({"mimic", missing, "--realtime", "--engine", "lk", "--shoulder", "80,40",
                    "--dry-run", "-o", dir.file("folder.tsv")});
  EXPECT_EQ(mimic.exit_code, 2) << mimic.err;
  EXPECT_TRUE(Contains(mimic.err, "-o " + dir.file("folder.tsv") + ": is a folder")) << mimic.err;
  const test::CliResult sim = test::RunCli({"puma-sim", "--log", sock});
  EXPECT_EQ(sim.exit_code, 2) << sim.err;
  EXPECT_TRUE(Contains(sim.err, "--log " + sock + ": is a socket")) << sim.err;
  // A batch whose angle file would be a folder.
  test::WriteFile(dir.file("v.avi"), test::ReadFile(Scene() + "/scene.avi"));
  fs::create_directories(dir.file("out/v.tsv"));
  const test::CliResult batch =
      test::RunCli({"--no-progress", "analyze", dir.file("v.avi"), "--output-dir", dir.file("out"),
                    "--engine", "lk", "--shoulder", "80,40", "--start", "20"});
  EXPECT_EQ(batch.exit_code, 2) << batch.err;
  EXPECT_TRUE(Contains(batch.err, dir.file("out/v.tsv") + ": is a folder")) << batch.err;
  EXPECT_FALSE(fs::exists(dir.file("out/summary.tsv")));
  ::close(fd);
}

TEST(CliOutputs, PermissionDeniedSaysSo) {
  ASSERT_TRUE(test::CanRunUnprivileged()) << "cannot drop root here (no /usr/bin/setpriv)";
  test::TempDir dir;
  ::chmod(dir.path().c_str(), 0755);  // others may enter but not write
  test::WriteFile(dir.file("v.avi"), test::ReadFile(Scene() + "/scene.avi"));
  ::chmod(dir.file("v.avi").c_str(), 0644);
  const test::CliResult r = test::RunCliUnprivileged(Analyze(dir.file("v.avi"), dir.file("a.tsv")));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, dir.file("a.tsv") + ": cannot write (permission denied)")) << r.err;
}

// An input that is a folder is called one, not "read error" or "no column header".
TEST(CliOutputs, AFolderGivenAsAnInputFileIsCalledAFolder) {
  test::TempDir dir;
  fs::create_directory(dir.file("list"));
  fs::create_directory(dir.file("old.tsv"));
  const std::string video = Scene() + "/scene.avi";
  const test::CliResult list =
      test::RunCli({"--no-progress", "analyze", "--list", dir.file("list"), "--output-dir",
                    dir.file("out"), "--engine", "lk", "--shoulder", "80,40"});
  EXPECT_EQ(list.exit_code, 1) << list.err;
  EXPECT_TRUE(Contains(list.err, "--list " + dir.file("list") + ": is a folder")) << list.err;
  const test::CliResult params = test::RunCli(
      {"analyze", video, "-o", dir.file("a.tsv"), "--params-from", dir.file("old.tsv")});
  EXPECT_EQ(params.exit_code, 1) << params.err;
  EXPECT_TRUE(Contains(params.err, dir.file("old.tsv") + ": is a folder")) << params.err;
  const test::CliResult plan = test::RunCli({"plan", dir.file("old.tsv"), "-o", dir.file("p.val")});
  EXPECT_EQ(plan.exit_code, 1) << plan.err;
  EXPECT_TRUE(Contains(plan.err, dir.file("old.tsv") + ": is a folder")) << plan.err;
  EXPECT_FALSE(fs::exists(dir.file("a.tsv")));
  EXPECT_FALSE(fs::exists(dir.file("p.val")));
}

// SIGKILL leaves the temporary beside the output (nothing can remove it then); the next run to
// the same output removes it, and keeps a file of the user's with a similar name.
TEST(CliOutputs, AKilledRunsTemporaryIsRemovedByTheNextRunAndNothingElse) {
  test::TempDir dir;
  const std::string out = dir.file("a.tsv");
  const std::string prefix = dir.file(OutputTempPrefix(out));
  test::WriteFile(dir.file(".a.tsv.backup"), "the user's");
  test::WriteFile(dir.file(".a.tsv.armmimic-tmp.notes"), "the user's too (five letters)");
  const std::string video = test::SmallScene(7, 2000) + "/scene.avi";
  std::vector<std::string> argv = Analyze(video, out);
  argv.insert(argv.begin(), ARMMIMIC_CLI_PATH);
  test::Child child(argv, "/dev/null", dir.file("err.txt"));
  ASSERT_TRUE(child.started());
  auto temp = [&] {
    for (const auto& e : fs::directory_iterator(dir.path())) {
      const std::string p = e.path().string();
      if (p.rfind(prefix, 0) == 0 && p.size() == prefix.size() + 6) return p;
    }
    return std::string();
  };
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (temp().empty() && !child.Exited() && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  child.Signal(SIGKILL);
  const int status = child.Wait();
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  const std::string left = temp();
  ASSERT_FALSE(left.empty()) << "no temporary after SIGKILL";

  const test::CliResult again = test::RunCli(Analyze(Scene() + "/scene.avi", out));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_FALSE(fs::exists(left)) << left;
  EXPECT_EQ(test::ReadFile(dir.file(".a.tsv.backup")), "the user's");
  EXPECT_TRUE(fs::exists(dir.file(".a.tsv.armmimic-tmp.notes")));
  EXPECT_TRUE(temp().empty());
}

}  // namespace
}  // namespace armmimic
