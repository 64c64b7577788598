// `analyze --engine pose` and `--auto-calibrate` through armmimic-cli: a generated scene in, an
// angle file with the confidence column out; a missing model exits 1 naming it; flags that do
// not fit the engine are usage errors. The runs that need the model are compiled in only when
// it is there (tests/cli/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "test_util.h"

namespace armmimic {
namespace {

class CliPose : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir();
    const test::CliResult r =
        test::RunCli({"synth", "arm", dir_->path(), "--seed", "2", "--frames", "12", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static test::TempDir* dir_;
};
test::TempDir* CliPose::dir_ = nullptr;

TEST_F(CliPose, AMissingModelExitsOneNamingTheFileAndHowToGetIt) {
  const std::string none = dir_->file("no-model");
  const test::CliResult r =
      test::RunCli({"analyze", dir_->file("scene.avi"), "-o", dir_->file("m.tsv"), "--engine",
                    "pose", "--model", none, "-q"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "armmimic-cli analyze: --model: " + none +
                       "/movenet-lightning.json not found; install the package armmimic-models, "
                       "or fetch the model with scripts/deps.sh --with-model in armmimic's "
                       "source tree, or name the folder holding it\n");
  EXPECT_FALSE(std::ifstream(dir_->file("m.tsv")).good());  // nothing written
}

TEST_F(CliPose, FlagsThatDoNotFitAreUsageErrors) {
  const std::string video = dir_->file("scene.avi"), out = dir_->file("u.tsv");
  test::CliResult r = test::RunCli({"analyze", video, "-o", out, "--engine", "lk",
                                    "--background-frames", "45", "--side", "left"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--side is used by --engine lk only with --auto-calibrate"),
            std::string::npos)
      << r.err;
  r = test::RunCli({"analyze", video, "-o", out, "--engine", "pose", "--side", "up"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--side 'up': expected left, right or both"), std::string::npos) << r.err;
  r = test::RunCli(
      {"analyze", video, "-o", out, "--engine", "lk", "--auto-calibrate", "--shoulder", "10,10"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--auto-calibrate: auto-calibration finds the joints itself"),
            std::string::npos)
      << r.err;
  r = test::RunCli({"analyze", video, "-o", out, "--engine", "bgsub", "--auto-calibrate",
                    "--background-frames", "45", "--arm-length", dir_->file("armlength.png")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--auto-calibrate is not used by --engine bgsub"), std::string::npos)
      << r.err;
}

TEST_F(CliPose, TheNetworkFlagIsThePoseEnginesAndNamesItsChoices) {
  const std::string video = dir_->file("scene.avi"), out = dir_->file("n.tsv");
  test::CliResult r = test::RunCli({"analyze", video, "-o", out, "--engine", "lk",
                                    "--background-frames", "45", "--network", "blazepose"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--network is not used by --engine lk"), std::string::npos) << r.err;
  r = test::RunCli({"analyze", video, "-o", out, "--engine", "pose", "--network", "openpose"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--network"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("blazepose"), std::string::npos) << r.err;
}

TEST_F(CliPose, AMissingBlazePoseModelExitsOneNamingItsFile) {
  const std::string none = dir_->file("no-model");
  const test::CliResult r =
      test::RunCli({"analyze", dir_->file("scene.avi"), "-o", dir_->file("b.tsv"), "--engine",
                    "pose", "--network", "blazepose", "--side", "left", "--model", none, "-q"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "armmimic-cli analyze: --model: " + none +
                       "/blazepose-full.json not found; install the package armmimic-models, "
                       "or fetch the model with scripts/deps.sh --with-model in armmimic's "
                       "source tree, or name the folder holding it\n");
}

TEST_F(CliPose, SideBothIsThePoseEnginesAndMimicFollowsOneArm) {
  const std::string video = dir_->file("scene.avi"), out = dir_->file("sb.tsv");
  test::CliResult r = test::RunCli(
      {"analyze", video, "-o", out, "--engine", "lk", "--auto-calibrate", "--side", "both"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--side both is for --engine pose only"), std::string::npos) << r.err;
  r = test::RunCli(
      {"mimic", video, "--realtime", "--engine", "pose", "--side", "both", "--dry-run"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--side both: the robot follows one arm"), std::string::npos) << r.err;
  EXPECT_FALSE(std::ifstream(dir_->file("sb.left.tsv")).good());
  EXPECT_FALSE(std::ifstream(dir_->file("sb.right.tsv")).good());
}

TEST_F(CliPose, SideBothRefusesAnOutputThatIsNotAFile) {
  const test::CliResult r = test::RunCli({"analyze", dir_->file("scene.avi"), "-o", "/dev/null",
                                          "--engine", "pose", "--side", "both"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("-o /dev/null is not a file: --side both writes a file per arm"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::ifstream("/dev/null.left").good());
}

TEST_F(CliPose, SideBothRefusesAnArmsFileThatIsAnInput) {
  // -o o.avi with side both would write o.left.avi: the input itself.
  const std::string input = dir_->file("o.left.avi");
  std::ofstream(input, std::ios::binary) << test::ReadFile(dir_->file("scene.avi"));
  const test::CliResult r = test::RunCli(
      {"analyze", input, "-o", dir_->file("o.avi"), "--engine", "pose", "--side", "both"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("-o " + input + " is the same file as INPUT"), std::string::npos) << r.err;
}

#if defined(ARMMIMIC_HAVE_POSE_MODEL) && defined(ARMMIMIC_HAVE_BLAZEPOSE_MODEL)
// BlazePose's crop does not depend on the arm, and on these frames MoveNet's looks (the 2-D
// columns) come out the same with both arms as with one: each arm's file is the one-arm run's,
// byte for byte.
TEST_F(CliPose, SideBothWithBlazePoseWritesTheOneArmRunsFiles) {
  const std::string video = dir_->file("scene.avi");
  const std::vector<std::string> pose = {"--engine", "pose", "--network", "blazepose",
                                         "--start",  "105",  "-q"};
  auto run = [&](const std::string& out, const std::string& side) {
    std::vector<std::string> args = {"analyze", video, "-o", out, "--side", side};
    args.insert(args.end(), pose.begin(), pose.end());
    const test::CliResult r = test::RunCli(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
  };
  run(dir_->file("bb.tsv"), "both");
  run(dir_->file("bl.tsv"), "left");
  run(dir_->file("br.tsv"), "right");
  EXPECT_EQ(test::ReadFile(dir_->file("bb.left.tsv")), test::ReadFile(dir_->file("bl.tsv")));
  EXPECT_EQ(test::ReadFile(dir_->file("bb.right.tsv")), test::ReadFile(dir_->file("br.tsv")));
  EXPECT_FALSE(std::ifstream(dir_->file("bb.tsv")).good());
}

TEST_F(CliPose, BlazePoseWritesThe3dColumnsAndNamesItsNetwork) {
  const std::string out = dir_->file("blazepose.tsv");
  const test::CliResult r =
      test::RunCli({"analyze", dir_->file("scene.avi"), "-o", out, "--engine", "pose", "--network",
                    "blazepose", "--side", "left", "--start", "105"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(out, &f).ok());
  EXPECT_EQ(f.Meta("model"), "blazepose-full-ghum");
  EXPECT_EQ(f.Meta("pose.network"), "blazepose");
  EXPECT_TRUE(f.has_confidence_column);
  EXPECT_TRUE(f.has_3d_columns);
  ASSERT_EQ(f.rows.size(), 12u);
  int ok = 0;
  for (const AngleRow& row : f.rows) {
    if (!row.ok()) continue;
    ++ok;
    // An ok row carries all five 3-D values, the elbow's within [0, 180].
    EXPECT_FALSE(std::isnan(row.upper_az_deg + row.upper_el_deg + row.fore_az_deg +
                            row.fore_el_deg + row.elbow_deg))
        << row.frame;
    EXPECT_GE(row.elbow_deg, 0);
    EXPECT_LE(row.elbow_deg, 180);
  }
  EXPECT_GT(ok, 0);
}
#endif

#ifdef ARMMIMIC_HAVE_POSE_MODEL
TEST_F(CliPose, PoseWritesEveryFrameFromTheStartWithAConfidence) {
  const std::string out = dir_->file("pose.tsv");
  const test::CliResult r = test::RunCli({"analyze", dir_->file("scene.avi"), "-o", out, "--engine",
                                          "pose", "--side", "left", "--start", "105"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(out, &f).ok());
  EXPECT_EQ(f.Meta("engine"), "pose");
  EXPECT_TRUE(f.has_confidence_column);
  ASSERT_EQ(f.rows.size(), 12u);
  EXPECT_EQ(f.rows.front().frame, 105);
  for (const AngleRow& row : f.rows) {
    EXPECT_TRUE(row.ok()) << row.frame;
    EXPECT_GE(row.confidence, 0.4);
    EXPECT_LE(row.confidence, 1.0);
  }
}

// --side both with `network` (and `--start 105`): one file per arm, each a whole angle file whose
// header is the one-arm run's of that side, and whose rows are close to it (MoveNet's crop, also
// BlazePose's second opinion, is searched again when either arm drops in it).
void ExpectEachArmLikeItsOneArmRun(const std::string& video, const std::string& dir,
                                   const std::string& network) {
  auto run = [&](const std::string& out, const std::string& side) {
    return test::RunCli({"analyze", video, "-o", out, "--engine", "pose", "--network", network,
                         "--side", side, "--start", "105"});
  };
  const test::CliResult r = run(dir + "/arms.tsv", "both");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("12 rows per arm from scene.avi"), std::string::npos) << r.err;
  EXPECT_FALSE(std::ifstream(dir + "/arms.tsv").good());
  for (const std::string side : {"left", "right"}) {
    ASSERT_EQ(run(dir + "/one." + side + ".tsv", side).exit_code, 0);
    AngleFile both, one;
    ASSERT_TRUE(ReadAngleFile(dir + "/arms." + side + ".tsv", &both).ok()) << side;
    ASSERT_TRUE(ReadAngleFile(dir + "/one." + side + ".tsv", &one).ok()) << side;
    EXPECT_EQ(both.meta, one.meta) << side;
    EXPECT_EQ(both.Meta("pose.side"), side);
    EXPECT_EQ(both.Meta("pose.network"), network);
    EXPECT_TRUE(both.has_confidence_column);
    ASSERT_EQ(both.rows.size(), 12u) << side;
    ASSERT_EQ(one.rows.size(), 12u) << side;
    int same_status = 0;
    for (std::size_t i = 0; i < both.rows.size(); ++i) {
      const AngleRow &a = both.rows[i], &b = one.rows[i];
      EXPECT_EQ(a.frame, b.frame);
      same_status += a.status == b.status ? 1 : 0;
      if (!a.ok() || !b.ok()) continue;
      EXPECT_LE(std::abs(a.upper_deg - b.upper_deg), 5.0) << side << " frame " << a.frame;
      EXPECT_LE(std::abs(a.fore_deg - b.fore_deg), 5.0) << side << " frame " << a.frame;
    }
    EXPECT_GE(same_status, 11) << side;
  }
}

TEST_F(CliPose, SideBothWritesOneFilePerArmLikeTheOneArmRuns) {
  const std::string dir = dir_->file("movenet-arms");
  std::filesystem::create_directories(dir);
  ExpectEachArmLikeItsOneArmRun(dir_->file("scene.avi"), dir, "movenet");
}

// A batch with --side both: NAME.left.tsv and NAME.right.tsv, a summary line for each.
TEST_F(CliPose, SideBothInABatchWritesAndSummarisesEachArm) {
  const std::string out = dir_->file("batch-both");
  const test::CliResult r =
      test::RunCli({"analyze", dir_->file("scene.avi"), "--output-dir", out, "--engine", "pose",
                    "--side", "both", "--start", "110", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile left, right;
  ASSERT_TRUE(ReadAngleFile(out + "/scene.left.tsv", &left).ok());
  ASSERT_TRUE(ReadAngleFile(out + "/scene.right.tsv", &right).ok());
  EXPECT_EQ(left.rows.size(), 7u);
  EXPECT_EQ(right.rows.size(), 7u);
  std::istringstream summary(test::ReadFile(out + "/summary.tsv"));
  std::string line;
  std::vector<std::string> angles;
  std::getline(summary, line);  // the header
  while (std::getline(summary, line)) {
    std::istringstream cells(line);
    std::string video, file, frames;
    std::getline(cells, video, '\t');
    std::getline(cells, file, '\t');
    std::getline(cells, frames, '\t');
    angles.push_back(file);
    EXPECT_EQ(frames, "7") << line;
  }
  EXPECT_EQ(angles, (std::vector<std::string>{out + "/scene.left.tsv", out + "/scene.right.tsv"}));
}

TEST_F(CliPose, AutoCalibrateGivesLkItsJointsAndPrintsThem) {
  const std::string out = dir_->file("lk.tsv");
  const test::CliResult r = test::RunCli({"analyze", dir_->file("scene.avi"), "-o", out, "--engine",
                                          "lk", "--auto-calibrate", "--start", "105"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("analyze: estimated: auto-calibrate: the person's "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(" arm in frame 105: shoulder "), std::string::npos) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(out, &f).ok());
  ASSERT_EQ(f.rows.size(), 12u);  // frame 105 already gets a row, as with clicked joints
  EXPECT_EQ(f.rows.front().frame, 105);
}
#endif

}  // namespace
}  // namespace armmimic
