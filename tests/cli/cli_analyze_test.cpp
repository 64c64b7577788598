// armmimic-cli background / analyze: exit codes, messages that name the file or flag, and an
// end-to-end run through a real MJPG encode scored against the scene's truth.
#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/synth/arm_scene.h"
#include "armmimic/synth/score.h"
#include "armmimic/synth/truth_file.h"
#include "test_util.h"

namespace armmimic {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// One short MJPG scene shared by the tests of this file (written once).
const std::string& SceneDir() {
  bool created = false;
  const test::TempDir& dir = test::SharedTempDir("cli-analyze-scene", &created);
  if (created) {
    synth::ArmSceneOptions so;
    so.seed = 7;
    so.motion = synth::ArmMotion::kSwing;
    so.motion_frames = 90;
    so.noise_sigma = 3;
    so.codec = "MJPG";
    const Status st = synth::WriteArmScene(so, dir.path(), {});
    if (!st.ok()) ADD_FAILURE() << st.message();
  }
  return dir.path();
}

TEST(CliAnalyze, MjpgSceneMeetsTheAccuracyTarget) {
  const std::string dir = SceneDir();
  const std::string out = dir + "/angles.tsv";
  const test::CliResult r = test::RunCli({"analyze", dir + "/scene.avi", "-o", out, "--engine",
                                          "bgsub", "--background-frames", "45", "--arm-length",
                                          dir + "/armlength.png", "--start", "45"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "analyze: 90 rows (")) << r.err;
  EXPECT_TRUE(Contains(r.err, "-> " + out)) << r.err;
  // A run with every row ok names no reason.
  EXPECT_EQ(Contains(r.err, "lost rows:"), !Contains(r.err, " 0 lost)")) << r.err;
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(out, &angles).ok());
  EXPECT_EQ(angles.Meta("engine"), "bgsub");
  EXPECT_EQ(angles.Meta("source"), "scene.avi");
  EXPECT_EQ(angles.Meta("start"), "45");
  EXPECT_EQ(angles.Meta("threshold"), "45");
  EXPECT_EQ(angles.Meta("width"), "320");
  EXPECT_TRUE(angles.complete);
  ASSERT_EQ(angles.rows.size(), 90u);
  EXPECT_EQ(angles.rows.front().frame, 45 + 60);  // frame indices are those of the file
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(dir + "/truth.tsv", &truth).ok());
  const synth::ScoreReport report = synth::ScoreAngles(truth, angles);
  EXPECT_GE(report.summary.coverage, 0.98);
  EXPECT_LE(report.summary.overall.mae, 3.0) << synth::FormatScoreSummary(report);
}

// The report names why rows were lost, with their count: here an arm-length image that shows
// no arm (the scene's empty room) leaves bgsub without a calibration on every row.
TEST(CliAnalyze, TheReportSaysWhyRowsWereLost) {
  const std::string dir = SceneDir();
  const std::string bg = dir + "/background.png";
  const test::CliResult r =
      test::RunCli({"analyze", dir + "/scene.avi", "-o", dir + "/no-arm.tsv", "--engine", "bgsub",
                    "--background", bg, "--arm-length", bg, "--start", "45", "--no-progress"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "analyze: 90 rows (0 ok, 90 lost)")) << r.err;
  EXPECT_TRUE(Contains(r.err,
                       "analyze: lost rows: arm-length image: no arm differs from the "
                       "standstill (90)\n"))
      << r.err;
}

// Every parameter is recorded in the header under its --param name, and a run with exactly
// those recorded settings makes the same file: the header says how to redo it.
TEST(CliAnalyze, ChangedParametersAreRecordedAndReproduceTheFile) {
  const std::string dir = SceneDir();
  const std::vector<std::string> base = {
      "analyze", dir + "/scene.avi", "--engine", "lk", "--background-frames",
      "45",      "--start",          "45",       "-q"};
  std::vector<std::string> first = base;
  for (const char* a : {"--param", "lk.max_corners=150", "--param", "lk.bar_min_score=0.35",
                        "--param", "lk.use_bar=false", "-o"}) {
    first.push_back(a);
  }
  first.push_back(dir + "/p1.tsv");
  test::CliResult r = test::RunCli(first);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(dir + "/p1.tsv", &f).ok());
  EXPECT_EQ(f.Meta("lk.max_corners"), "150");
  EXPECT_EQ(f.Meta("lk.bar_min_score"), "0.35");
  EXPECT_EQ(f.Meta("lk.use_bar"), "false");
  EXPECT_EQ(f.Meta("lk.window_px", "unset"), "15");  // the defaults too
  // Redo from the header: every "lk.*" entry becomes a --param.
  std::vector<std::string> again = base;
  for (const auto& kv : f.meta) {
    if (kv.first.rfind("lk.", 0) == 0) again.push_back("--param=" + kv.first + "=" + kv.second);
  }
  again.push_back("-o");
  again.push_back(dir + "/p2.tsv");
  r = test::RunCli(again);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::ReadFile(dir + "/p1.tsv"), test::ReadFile(dir + "/p2.tsv"));
}

TEST(CliAnalyze, BackgroundCommandWritesTheMeanImage) {
  const std::string dir = SceneDir();
  const std::string bg = dir + "/bg_cli.png";
  const test::CliResult r = test::RunCli({"-q", "background", dir + "/scene.avi", "-o", bg});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(test::ReadFile(bg).empty());
  const test::CliResult with_bg =
      test::RunCli({"-q", "analyze", dir + "/scene.avi", "-o", dir + "/a2.tsv", "--engine", "bgsub",
                    "--background", bg, "--arm-length", dir + "/armlength.png", "--start", "45"});
  EXPECT_EQ(with_bg.exit_code, 0) << with_bg.err;
  EXPECT_TRUE(with_bg.err.empty()) << "-q must silence the summary: " << with_bg.err;
}

TEST(CliAnalyze, MissingVideoIsARuntimeErrorNamingIt) {
  const std::string dir = SceneDir();
  const test::CliResult r =
      test::RunCli({"analyze", "/nonexistent/clip.avi", "-o", dir + "/x.tsv", "--engine", "bgsub",
                    "--background-frames", "45", "--arm-length", dir + "/armlength.png"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(Contains(r.err, "/nonexistent/clip.avi")) << r.err;
  const test::CliResult b =
      test::RunCli({"background", "/nonexistent/clip.avi", "-o", dir + "/bg.png"});
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_TRUE(Contains(b.err, "/nonexistent/clip.avi")) << b.err;
}

TEST(CliAnalyze, UsageErrorsNameTheFlag) {
  const std::string dir = SceneDir();
  const std::string video = dir + "/scene.avi";
  const std::string arm = dir + "/armlength.png";
  struct Case {
    std::vector<std::string> args;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {{"analyze", video, "-o", "a.tsv", "--engine", "bgsub", "--background-frames", "45"},
       "armmimic-cli analyze: --arm-length: the bgsub engine needs an arm-length image"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "bgsub", "--arm-length", arm},
       "--background-frames"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "bgsub", "--arm-length", arm,
        "--background-frames", "45", "--threshold", "999"},
       "--threshold"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "bgsub", "--arm-length", arm,
        "--background-frames", "45", "--bogus"},
       "--bogus"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "bgsub", "--arm-length", arm,
        "--background-frames", "45", "--reference", arm},
       "--reference"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "lk"}, "--shoulder"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "marker"}, "--reference"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "nope"}, "--engine"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "bgsub", "--arm-length", arm,
        "--background-frames", "45", "--roi", "1,2,3"},
       "--roi"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "bgsub", "--arm-length", arm,
        "--background-frames", "45", "--param", "bgsub.min_arm_area_px=0"},
       "--param: bgsub.min_arm_area_px '0': expected a whole number in [1, 100000]"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "bgsub", "--arm-length", arm,
        "--background-frames", "45", "--param", "lk.max_corners=100"},
       "--param lk.max_corners=100 is not used by --engine bgsub"},
      {{"analyze", video, "-o", "a.tsv", "--engine", "marker", "--reference", arm, "--param",
        "marker.low=90"},
       "--low: low threshold 90 is above the high threshold 80"},
      {{"background", video}, "-o"},
      {{"background", video, "-o", dir + "/bg.png", "--frames", "0"}, "--frames"},
  };
  for (const Case& c : cases) {
    const test::CliResult r = test::RunCli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.expect << ": " << r.err;
    EXPECT_TRUE(Contains(r.err, c.expect)) << c.expect << ": " << r.err;
  }
}

TEST(CliAnalyze, RuntimeErrorsNameTheFile) {
  const std::string dir = SceneDir();
  const std::string video = dir + "/scene.avi";
  test::WriteFile(dir + "/small.pgm", "P5\n4 4\n255\n" + std::string(16, '\x80'));
  const test::CliResult size =
      test::RunCli({"analyze", video, "-o", dir + "/x.tsv", "--engine", "bgsub",
                    "--background-frames", "45", "--arm-length", dir + "/small.pgm"});
  EXPECT_EQ(size.exit_code, 1);
  EXPECT_TRUE(Contains(size.err, "small.pgm")) << size.err;
  EXPECT_TRUE(Contains(size.err, "scene.avi")) << size.err;
  const test::CliResult past = test::RunCli({"analyze", video, "-o", dir + "/x.tsv", "--engine",
                                             "bgsub", "--background-frames", "45", "--arm-length",
                                             dir + "/armlength.png", "--start", "100000"});
  EXPECT_EQ(past.exit_code, 1);
  EXPECT_TRUE(Contains(past.err, "--start")) << past.err;
  const test::CliResult outdir = test::RunCli(
      {"analyze", video, "-o", "/nonexistent-dir/a.tsv", "--engine", "bgsub", "--background-frames",
       "45", "--arm-length", dir + "/armlength.png", "--start", "45"});
  EXPECT_EQ(outdir.exit_code, 1);
  EXPECT_TRUE(Contains(outdir.err, "/nonexistent-dir")) << outdir.err;
}

TEST(CliAnalyze, HelpWorks) {
  for (const char* cmd : {"analyze", "background"}) {
    const test::CliResult r = test::RunCli({cmd, "--help"});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_TRUE(Contains(r.out, "Usage:")) << cmd;
  }
}

}  // namespace
}  // namespace armmimic
