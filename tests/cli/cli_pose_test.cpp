// `analyze --engine pose` and `--auto-calibrate` through armmimic-cli: a generated scene in, an
// angle file with the confidence column out; a missing model exits 1 naming it; flags that do
// not fit the engine are usage errors. The runs that need the model are compiled in only when
// it is there (tests/cli/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

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
  EXPECT_NE(r.err.find("--side 'up': expected left or right"), std::string::npos) << r.err;
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

#if defined(ARMMIMIC_HAVE_POSE_MODEL) && defined(ARMMIMIC_HAVE_BLAZEPOSE_MODEL)
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
