// armmimic-cli synth arm and score: exit codes, messages and outputs.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/image_io.h"
#include "armmimic/synth/truth_file.h"
#include "test_util.h"

namespace armmimic {
namespace {

using test::RunCli;

bool Contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// A small scene shared by the tests of this file.
std::string SceneDir() {
  bool created = false;
  const test::TempDir& dir = test::SharedTempDir("cli-synth-score-scene", &created);
  if (created) {
    const test::CliResult r = RunCli({"synth", "arm", dir.file("s"), "--seed", "5", "--size",
                                      "160x120", "--background-frames", "3", "--standstill-frames",
                                      "3", "--frames", "20", "--motion", "swing", "--no-progress"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
  }
  return dir.file("s");
}

// Writes an angle file from the truth with a constant error on the upper arm.
void WriteAnglesFromTruth(const std::string& truth_path, const std::string& out,
                          double upper_offset) {
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(truth_path, &truth).ok());
  AngleFileWriter w;
  ASSERT_TRUE(w.Open(out, {{"engine", "bgsub"}}, false).ok());
  for (const synth::TruthRow& t : truth.rows) {
    if (!std::isfinite(t.upper_deg)) continue;
    AngleRow a;
    a.frame = t.frame;
    a.time_s = t.time_s;
    a.status = RowStatus::kOk;
    a.upper_deg = Wrap180(t.upper_deg + upper_offset);
    a.fore_deg = t.fore_deg;
    a.bend_deg = AngleDiff(a.fore_deg, a.upper_deg);
    ASSERT_TRUE(w.Write(a).ok());
  }
  ASSERT_TRUE(w.Commit().ok());
}

TEST(CliSynthArm, HelpListsTheFlags) {
  const test::CliResult r = RunCli({"synth", "arm", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* flag : {"--seed", "--size", "--fps", "--background-frames",
                           "--standstill-frames", "--frames", "--noise", "--codec", "--contrast",
                           "--drift", "--shadow", "--head-motion", "--motion", "--side"}) {
    EXPECT_TRUE(Contains(r.out, flag)) << flag;
  }
}

TEST(CliSynthArm, WritesTheSceneFolder) {
  const std::string dir = SceneDir();
  for (const char* f : {"scene.avi", "armlength.png", "background.png", "truth.tsv"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  }
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(dir + "/truth.tsv", &truth).ok());
  EXPECT_EQ(truth.rows.size(), 26u);
  EXPECT_EQ(truth.Meta("motion"), "swing");
  cv::Mat bg;
  ASSERT_TRUE(ReadImage(dir + "/background.png", &bg).ok());
  EXPECT_EQ(bg.size(), cv::Size(160, 120));
}

TEST(CliSynthArm, BadFlagsAreUsageErrorsNamingTheFlag) {
  test::TempDir dir;
  struct Case {
    std::vector<std::string> args;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {{"--size", "10x10"}, "--size"},        {{"--motion", "dance"}, "--motion"},
      {{"--codec", "DIVX"}, "--codec"},       {{"--frames", "0"}, "--frames"},
      {{"--no-such-flag"}, "--no-such-flag"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"synth", "arm", dir.file("out")};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const test::CliResult r = RunCli(args);
    EXPECT_EQ(r.exit_code, 2) << c.expect << ": " << r.err;
    EXPECT_TRUE(Contains(r.err, c.expect)) << r.err;
  }
  EXPECT_EQ(RunCli({"synth", "arm"}).exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.file("out")));
}

TEST(CliSynthArm, UnwritableFolderIsARuntimeFailure) {
  test::TempDir dir;
  test::WriteFile(dir.file("file"), "x");
  const test::CliResult r = RunCli({"synth", "arm", dir.file("file"), "--frames", "2"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(Contains(r.err, dir.file("file"))) << r.err;
}

TEST(CliScore, ReportsKnownErrorsAndDrawsThePlot) {
  const std::string dir = SceneDir();
  test::TempDir tmp;
  WriteAnglesFromTruth(dir + "/truth.tsv", tmp.file("a.tsv"), 3.0);
  const test::CliResult r =
      RunCli({"score", dir + "/truth.tsv", tmp.file("a.tsv"), "--plot", tmp.file("err.png")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.out, "coverage: 100.0% (23/23 rows ok)")) << r.out;
  EXPECT_TRUE(Contains(r.out, "upper  : MAE 3.00")) << r.out;
  EXPECT_TRUE(Contains(r.out, "fore   : MAE 0.00")) << r.out;
  EXPECT_TRUE(Contains(r.out, "t_upper")) << r.out;
  cv::Mat plot;
  ASSERT_TRUE(ReadImage(tmp.file("err.png"), &plot).ok());
  EXPECT_EQ(plot.size(), cv::Size(800, 400));

  const test::CliResult s =
      RunCli({"score", dir + "/truth.tsv", tmp.file("a.tsv"), "--summary-only"});
  EXPECT_EQ(s.exit_code, 0);
  EXPECT_FALSE(Contains(s.out, "t_upper"));
  EXPECT_TRUE(Contains(s.out, "coverage"));
}

TEST(CliScore, BadInputsNameTheFileAndLine) {
  const std::string dir = SceneDir();
  test::TempDir tmp;
  WriteAnglesFromTruth(dir + "/truth.tsv", tmp.file("a.tsv"), 0.0);
  test::WriteFile(tmp.file("bad_truth.tsv"), std::string(synth::kTruthFileMagic) + "\nframe\n");
  test::WriteFile(tmp.file("bad_angles.tsv"), "not an angle file\n");

  test::CliResult r = RunCli({"score", tmp.file("bad_truth.tsv"), tmp.file("a.tsv")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(Contains(r.err, tmp.file("bad_truth.tsv") + ":2:")) << r.err;

  r = RunCli({"score", dir + "/truth.tsv", tmp.file("bad_angles.tsv")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(Contains(r.err, tmp.file("bad_angles.tsv") + ":1")) << r.err;

  r = RunCli({"score", tmp.file("missing.tsv"), tmp.file("a.tsv")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(Contains(r.err, "missing.tsv")) << r.err;

  r = RunCli({"score", dir + "/truth.tsv"});
  EXPECT_EQ(r.exit_code, 2);
  r = RunCli({"score", dir + "/truth.tsv", tmp.file("a.tsv"), "--plot", tmp.file("err.txt")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "--plot")) << r.err;
  r = RunCli({"score", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_TRUE(Contains(r.out, "--summary-only"));
}

}  // namespace
}  // namespace armmimic
