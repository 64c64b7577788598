// Nothing lost on output: armmimic-cli is started as a child process, interrupted mid-run
// (SIGINT, SIGKILL) or fed a video that breaks mid-stream, and the output left behind is either
// the complete previous file or a complete (possibly complete=no) new one, never half.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

extern char** environ;

namespace armmimic {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A scene long enough that an analysis is still running when the test interrupts it:
// 20 empty, 20 standstill and 600 moving frames of 240x180.
constexpr int kBackgroundFrames = 20;
constexpr int kStandstillFrames = 20;
constexpr int kMotionFrames = 600;

const std::string& LongScene() {
  static test::TempDir* dir = [] {
    auto* d = new test::TempDir();
    synth::ArmSceneOptions so;
    so.seed = 11;
    so.size = {240, 180};
    so.background_frames = kBackgroundFrames;
    so.standstill_frames = kStandstillFrames;
    so.motion_frames = kMotionFrames;
    so.motion = synth::ArmMotion::kSwing;
    const Status st = synth::WriteArmScene(so, d->path(), {});
    if (!st.ok()) ADD_FAILURE() << st.message();
    return d;
  }();
  return dir->path();
}

// armmimic-cli running in the background, its stderr going to a file.
class Child {
 public:
  Child(const std::vector<std::string>& args, const std::string& err_path) {
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> argv_s = {ARMMIMIC_CLI_PATH};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    // The child gets SIGINT's default action and no blocked signals, whatever this process
    // inherited (a shell starts background jobs with SIGINT ignored).
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t defaults, none;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    const int rc = posix_spawn(&pid_, ARMMIMIC_CLI_PATH, &fa, &attr, argv.data(), environ);
    posix_spawnattr_destroy(&attr);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) pid_ = -1;
  }
  ~Child() {
    if (pid_ > 0 && !done_) {
      kill(pid_, SIGKILL);
      Wait();
    }
  }
  bool started() const { return pid_ > 0; }
  // True once the process has ended (reaps it).
  bool Exited() {
    if (done_) return true;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      done_ = true;
      status_ = status;
    }
    return done_;
  }
  int Wait() {
    if (!done_) {
      int status = 0;
      waitpid(pid_, &status, 0);
      status_ = status;
      done_ = true;
    }
    return status_;
  }
  void Signal(int sig) { kill(pid_, sig); }
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  bool done_ = false;
  int status_ = 0;
};

// The temporary AtomicFile makes beside `target` (".<name>.XXXXXX"), if any.
std::string TempBeside(const std::string& target) {
  const fs::path t(target);
  const std::string prefix = "." + t.filename().string() + ".";
  for (const auto& e : fs::directory_iterator(t.parent_path())) {
    if (e.path().filename().string().rfind(prefix, 0) == 0) return e.path().string();
  }
  return "";
}

// Polls until `ready()` or the child ends or 20 s pass. Returns whether `ready()` held.
template <typename F>
bool PollUntil(Child& child, F ready) {
  const auto until = Clock::now() + std::chrono::seconds(20);
  while (Clock::now() < until) {
    if (ready()) return true;
    if (child.Exited()) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

// True once the child holds `path` open.
bool HasOpen(pid_t pid, const std::string& path) {
  std::error_code ec;
  const std::string want = fs::canonical(path, ec).string();
  for (const auto& e : fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
    std::error_code ec2;
    if (fs::read_symlink(e.path(), ec2).string() == want) return true;
  }
  return false;
}

std::vector<std::string> AnalyzeArgs(const std::string& out) {
  const std::string dir = LongScene();
  return {"--no-progress",
          "analyze",
          dir + "/scene.avi",
          "-o",
          out,
          "--engine",
          "bgsub",
          "--background-frames",
          std::to_string(kBackgroundFrames),
          "--start",
          std::to_string(kBackgroundFrames),
          "--standstill-frames",
          std::to_string(kStandstillFrames),
          "--arm-length",
          dir + "/armlength.png"};
}

// A small valid angle file standing for the result of an earlier run.
std::string PreviousAngles() {
  return std::string(kAngleFileMagic) + "\n# engine=bgsub source=old.avi fps=30\n" +
         kAngleFileUnits +
         "\nframe\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\tupper_cx\tupper_cy\t"
         "fore_cx\tfore_cy\n0\t0\tok\t-90\t-90\tnan\t0\tnan\tnan\tnan\tnan\n";
}

// Rows are consecutive frames from the first motion frame on.
void ExpectConsecutiveRows(const AngleFile& angles) {
  const int first = kBackgroundFrames + kStandstillFrames;
  for (std::size_t i = 0; i < angles.rows.size(); ++i) {
    ASSERT_EQ(angles.rows[i].frame, first + static_cast<int>(i)) << "row " << i;
  }
}

TEST(CliInterrupt, CtrlCDuringAnalyzeKeepsTheRowsInAFileMarkedIncomplete) {
  test::TempDir dir;
  const std::string out = dir.file("angles.tsv");
  Child child(AnalyzeArgs(out), dir.file("err.txt"));
  ASSERT_TRUE(child.started());
  // Wait until rows have reached the temporary (the first buffer flush), then interrupt.
  std::string temp;
  ASSERT_TRUE(PollUntil(child,
                        [&] {
                          temp = TempBeside(out);
                          std::error_code ec;
                          return !temp.empty() && fs::file_size(temp, ec) > 0 && !ec;
                        }))
      << "analyze ended or wrote nothing before it could be interrupted: "
      << test::ReadFile(dir.file("err.txt"));
  child.Signal(SIGINT);
  const int status = child.Wait();
  const std::string err = test::ReadFile(dir.file("err.txt"));
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << ": " << err;
  EXPECT_EQ(WEXITSTATUS(status), 1) << err;
  EXPECT_TRUE(Contains(err, "interrupted")) << err;
  EXPECT_TRUE(Contains(err, out)) << err;
  EXPECT_TRUE(Contains(err, "complete=no")) << err;
  AngleFile angles;
  const Status st = ReadAngleFile(out, &angles);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_FALSE(angles.complete);
  EXPECT_EQ(angles.Meta("complete"), "no");
  EXPECT_GT(angles.rows.size(), 0u);
  EXPECT_LT(angles.rows.size(), static_cast<std::size_t>(kMotionFrames));
  ExpectConsecutiveRows(angles);
  EXPECT_TRUE(TempBeside(out).empty()) << "temporary left: " << TempBeside(out);
  // The message's row count is the file's.
  EXPECT_TRUE(Contains(err, std::to_string(angles.rows.size()) + " rows kept")) << err;
  // An incomplete file is still a valid input for the next step.
  const test::CliResult plan = test::RunCli({"plan", out, "-o", dir.file("p.val")});
  EXPECT_EQ(plan.exit_code, 0) << plan.err;
}

TEST(CliInterrupt, CtrlCBeforeAnyRowReplacesAnEarlierFileOnlyWithAValidOne) {
  test::TempDir dir;
  const std::string out = dir.file("angles.tsv");
  test::WriteFile(out, PreviousAngles());
  Child child(AnalyzeArgs(out), dir.file("err.txt"));
  ASSERT_TRUE(child.started());
  // Interrupt as soon as the video is open (background and standstill phase: no rows yet).
  ASSERT_TRUE(PollUntil(child, [&] { return HasOpen(child.pid(), LongScene() + "/scene.avi"); }))
      << test::ReadFile(dir.file("err.txt"));
  child.Signal(SIGINT);
  const int status = child.Wait();
  const std::string err = test::ReadFile(dir.file("err.txt"));
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << ": " << err;
  EXPECT_EQ(WEXITSTATUS(status), 1) << err;
  EXPECT_TRUE(Contains(err, "interrupted")) << err;
  AngleFile angles;
  const Status st = ReadAngleFile(out, &angles);
  ASSERT_TRUE(st.ok()) << st.message();
  const std::string now = test::ReadFile(out);
  if (now != PreviousAngles()) {  // replaced: then by a valid file marked incomplete
    EXPECT_FALSE(angles.complete);
    ExpectConsecutiveRows(angles);
  }
  EXPECT_TRUE(TempBeside(out).empty()) << "temporary left: " << TempBeside(out);
}

TEST(CliInterrupt, KilledAnalyzeLeavesThePreviousFileWhole) {
  test::TempDir dir;
  const std::string out = dir.file("angles.tsv");
  test::WriteFile(out, PreviousAngles());
  Child child(AnalyzeArgs(out), dir.file("err.txt"));
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(PollUntil(child, [&] {
    const std::string temp = TempBeside(out);
    std::error_code ec;
    return !temp.empty() && fs::file_size(temp, ec) > 0 && !ec;
  })) << test::ReadFile(dir.file("err.txt"));
  child.Signal(SIGKILL);  // no handler runs: only the rename can protect the file
  const int status = child.Wait();
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(test::ReadFile(out), PreviousAngles());
}

TEST(CliInterrupt, CtrlCDuringBackgroundLeavesThePreviousImageWhole) {
  test::TempDir dir;
  const std::string out = dir.file("bg.png");
  const std::string old_png = test::ReadFile(LongScene() + "/background.png");
  test::WriteFile(out, old_png);
  Child child({"--no-progress", "background", LongScene() + "/scene.avi", "-o", out, "--frames",
               std::to_string(kBackgroundFrames + kStandstillFrames + kMotionFrames)},
              dir.file("err.txt"));
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(PollUntil(child, [&] { return HasOpen(child.pid(), LongScene() + "/scene.avi"); }))
      << test::ReadFile(dir.file("err.txt"));
  child.Signal(SIGINT);
  const int status = child.Wait();
  const std::string err = test::ReadFile(dir.file("err.txt"));
  // Either the command ends itself (exit 1) or SIGINT's default action ends it; never exit 0
  // with a mean of only some frames presented as the whole.
  if (WIFEXITED(status)) {
    EXPECT_EQ(WEXITSTATUS(status), 1) << err;
    EXPECT_TRUE(Contains(err, "interrupted") || Contains(err, out)) << err;
  } else {
    EXPECT_EQ(WTERMSIG(status), SIGINT);
  }
  EXPECT_EQ(test::ReadFile(out), old_png);
  EXPECT_TRUE(TempBeside(out).empty()) << "temporary left: " << TempBeside(out);
}

TEST(CliInterrupt, VideoDamagedMidStreamKeepsOutputWholeAndNamesTheFrame) {
  // Overwrite a stretch in the middle of the motion with zeros: a decode failure mid-video.
  test::TempDir dir;
  std::string bytes = test::ReadFile(LongScene() + "/scene.avi");
  const std::size_t from = bytes.size() / 2;
  for (std::size_t i = from; i < from + 20000 && i < bytes.size(); ++i) bytes[i] = '\0';
  const std::string video = dir.file("damaged.avi");
  test::WriteFile(video, bytes);
  const std::string out = dir.file("angles.tsv");
  test::WriteFile(out, PreviousAngles());
  std::vector<std::string> args = AnalyzeArgs(out);
  args[2] = video;
  const test::CliResult r = test::RunCli(args);
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.exit_code << ": " << r.err;
  AngleFile angles;
  const Status st = ReadAngleFile(out, &angles);
  ASSERT_TRUE(st.ok()) << st.message();
  if (r.exit_code == 1) {
    EXPECT_TRUE(Contains(r.err, video)) << r.err;
    EXPECT_TRUE(Contains(r.err, "frame")) << r.err;
    EXPECT_EQ(test::ReadFile(out), PreviousAngles()) << "a failed run replaced the file";
  } else {
    // Went on past the damage: a complete new file whose frame indices stay the file's.
    EXPECT_TRUE(angles.complete);
    EXPECT_NE(test::ReadFile(out), PreviousAngles());
    for (std::size_t i = 1; i < angles.rows.size(); ++i) {
      EXPECT_GT(angles.rows[i].frame, angles.rows[i - 1].frame);
    }
  }
  EXPECT_TRUE(TempBeside(out).empty()) << "temporary left: " << TempBeside(out);
}

TEST(CliInterrupt, FailedPlanLeavesThePreviousProgramWhole) {
  test::TempDir dir;
  const std::string val = dir.file("p.val");
  const std::string old_val = "; armmimic VAL program v1\nSPEED 50\n";
  test::WriteFile(val, old_val);
  const std::string bad = dir.file("bad.tsv");
  test::WriteFile(bad, PreviousAngles() + "1\tinf\tok\t-90\t-90\tnan\t0\tnan\tnan\tnan\tnan\n");
  const test::CliResult r = test::RunCli({"plan", bad, "-o", val});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, bad + ":6")) << r.err;
  EXPECT_EQ(test::ReadFile(val), old_val);
  EXPECT_TRUE(TempBeside(val).empty());
}

}  // namespace
}  // namespace armmimic
