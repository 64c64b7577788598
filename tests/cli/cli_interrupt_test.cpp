// Nothing lost on output: armmimic-cli is started as a child process, interrupted mid-run
// (SIGINT, SIGTERM, SIGHUP, SIGKILL) or fed a video that breaks mid-stream, and the output left
// behind is either the complete previous file or a complete (possibly complete=no) new one,
// never half, with no temporary beside it.
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

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
  bool created = false;
  const test::TempDir& dir = test::SharedTempDir("cli-interrupt-scene", &created);
  if (created) {
    synth::ArmSceneOptions so;
    so.seed = 11;
    so.size = {240, 180};
    so.background_frames = kBackgroundFrames;
    so.standstill_frames = kStandstillFrames;
    so.motion_frames = kMotionFrames;
    so.motion = synth::ArmMotion::kSwing;
    const Status st = synth::WriteArmScene(so, dir.path(), {});
    if (!st.ok()) ADD_FAILURE() << st.message();
  }
  return dir.path();
}

// armmimic-cli running in the background, its stderr going to a file.
class Child : public test::Child {
 public:
  Child(const std::vector<std::string>& args, const std::string& err_path)
      : test::Child(WithCli(args), "/dev/null", err_path) {}

 private:
  static std::vector<std::string> WithCli(std::vector<std::string> args) {
    args.insert(args.begin(), ARMMIMIC_CLI_PATH);
    return args;
  }
};

// The temporary OutputFile makes beside `target` (".<name>.armmimic-tmp.XXXXXX"), if any.
std::string TempBeside(const std::string& target) {
  const fs::path t(target);
  const std::string prefix = "." + t.filename().string() + ".";
  for (const auto& e : fs::directory_iterator(t.parent_path())) {
    if (e.path().filename().string().rfind(prefix, 0) == 0) return e.path().string();
  }
  return "";
}

// True once a temporary of `target` holds data (rows have been flushed).
bool TempHasData(const std::string& target) {
  const std::string temp = TempBeside(target);
  std::error_code ec;
  return !temp.empty() && fs::file_size(temp, ec) > 0 && !ec;
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

// Ctrl-C, SIGTERM (timeout, systemd, GNU parallel, Slurm) and SIGHUP (a closed terminal) all
// keep the rows, and the message says which signal came.
TEST(CliInterrupt, EverySignalDuringAnalyzeKeepsTheRowsInAFileMarkedIncomplete) {
  for (const auto& [sig, name] : {std::pair<int, std::string>{SIGINT, "SIGINT, Ctrl-C"},
                                  {SIGTERM, "SIGTERM"},
                                  {SIGHUP, "SIGHUP"}}) {
    SCOPED_TRACE(name);
    test::TempDir dir;
    const std::string out = dir.file("angles.tsv");
    Child child(AnalyzeArgs(out), dir.file("err.txt"));
    ASSERT_TRUE(child.started());
    // Wait until rows have reached the temporary (the first buffer flush), then interrupt.
    ASSERT_TRUE(PollUntil(child, [&] { return TempHasData(out); }))
        << "analyze ended or wrote nothing before it could be interrupted: "
        << test::ReadFile(dir.file("err.txt"));
    child.Signal(sig);
    const int status = child.Wait();
    const std::string err = test::ReadFile(dir.file("err.txt"));
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << ": " << err;
    EXPECT_EQ(WEXITSTATUS(status), 1) << err;
    EXPECT_TRUE(Contains(err, "interrupted (" + name + ")")) << err;
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
  ASSERT_TRUE(PollUntil(child, [&] { return TempHasData(out); }))
      << test::ReadFile(dir.file("err.txt"));
  child.Signal(SIGKILL);  // no handler runs: only the rename can protect the file
  const int status = child.Wait();
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(test::ReadFile(out), PreviousAngles());
}

TEST(CliInterrupt, CtrlCOrSigtermDuringBackgroundLeavesThePreviousImageWhole) {
  for (const auto& [sig, name] :
       {std::pair<int, std::string>{SIGINT, "SIGINT, Ctrl-C"}, {SIGTERM, "SIGTERM"}}) {
    SCOPED_TRACE(name);
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
    child.Signal(sig);
    const int status = child.Wait();
    const std::string err = test::ReadFile(dir.file("err.txt"));
    // Never exit 0 with a mean of only some frames presented as the whole.
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << ": " << err;
    EXPECT_EQ(WEXITSTATUS(status), 1) << err;
    EXPECT_TRUE(Contains(err, "interrupted (" + name + ")")) << err;
    EXPECT_TRUE(Contains(err, out + " not written")) << err;
    EXPECT_EQ(test::ReadFile(out), old_png);
    EXPECT_TRUE(TempBeside(out).empty()) << "temporary left: " << TempBeside(out);
  }
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

TEST(CliInterrupt, SighupDuringSynthLeavesNoPartialVideo) {
  test::TempDir dir;
  const std::string out = dir.file("scene");
  Child child({"--no-progress", "synth", "arm", out, "--frames", "3000", "--size", "320x240"},
              dir.file("err.txt"));
  ASSERT_TRUE(child.started());
  // Wait for the video's temporary (".scene.<pid>.tmp.avi") to hold frames.
  auto temp_video = [&] {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out, ec)) {
      const std::string name = e.path().filename().string();
      if (name.rfind(".scene.", 0) == 0 && fs::file_size(e.path(), ec) > 0) return true;
    }
    return false;
  };
  ASSERT_TRUE(PollUntil(child, temp_video)) << test::ReadFile(dir.file("err.txt"));
  child.Signal(SIGHUP);
  const int status = child.Wait();
  const std::string err = test::ReadFile(dir.file("err.txt"));
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << ": " << err;
  EXPECT_EQ(WEXITSTATUS(status), 1) << err;
  EXPECT_TRUE(Contains(err, "interrupted (SIGHUP)")) << err;
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(out)) left.push_back(e.path().filename().string());
  EXPECT_TRUE(left.empty()) << "left in the scene folder: " << left.front();
}

TEST(CliInterrupt, SigtermStopsABatchAfterKeepingTheCurrentRowsAndWritesTheSummary) {
  test::TempDir dir;
  const std::string out_dir = dir.file("out");
  std::vector<std::string> args = AnalyzeArgs("");
  // analyze VIDEO VIDEO2 --output-dir DIR instead of -o.
  args.erase(args.begin() + 3, args.begin() + 5);
  const std::string second = dir.file("second.avi");
  test::WriteFile(second, test::ReadFile(LongScene() + "/scene.avi"));
  args.insert(args.begin() + 3, {second, "--output-dir", out_dir});
  Child child(args, dir.file("err.txt"));
  ASSERT_TRUE(child.started());
  const std::string first_out = out_dir + "/scene.tsv";
  ASSERT_TRUE(PollUntil(child, [&] {
    std::error_code ec;
    return fs::is_directory(out_dir, ec) && TempHasData(first_out);
  })) << test::ReadFile(dir.file("err.txt"));
  child.Signal(SIGTERM);
  const int status = child.Wait();
  const std::string err = test::ReadFile(dir.file("err.txt"));
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << ": " << err;
  EXPECT_EQ(WEXITSTATUS(status), 1) << err;
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(first_out, &angles).ok());
  EXPECT_FALSE(angles.complete);
  ExpectConsecutiveRows(angles);
  EXPECT_FALSE(fs::exists(out_dir + "/second.tsv"));
  const std::string summary = test::ReadFile(out_dir + "/summary.tsv");
  EXPECT_TRUE(Contains(summary, "\t" + std::to_string(angles.rows.size()) + "\t")) << summary;
  EXPECT_TRUE(Contains(summary, "\tinterrupted\tinterrupted (SIGTERM)")) << summary;
  EXPECT_TRUE(
      Contains(summary, second + "\t" + out_dir + "/second.tsv\t0\t0\t0\tnan\tnan\tskipped"))
      << summary;
  EXPECT_TRUE(TempBeside(first_out).empty());
  EXPECT_TRUE(TempBeside(out_dir + "/summary.tsv").empty());
}

TEST(CliInterrupt, PumaSimStopsCleanlyOnSighup) {
  test::TempDir dir;
  Child child({"puma-sim", "--link", dir.file("puma")}, dir.file("err.txt"));
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(PollUntil(child, [&] {
    std::error_code ec;
    return fs::is_symlink(dir.file("puma"), ec);
  })) << test::ReadFile(dir.file("err.txt"));
  child.Signal(SIGHUP);
  const int status = child.Wait();
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << test::ReadFile(dir.file("err.txt"));
}

}  // namespace
}  // namespace armmimic
