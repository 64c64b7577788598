// `analyze --engine lk` end to end through armmimic-cli: a rendered scene in, an angle file out;
// usage errors name the flag.
#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/synth/score.h"
#include "armmimic/synth/truth_file.h"
#include "test_util.h"

namespace armmimic {
namespace {

class CliLk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir();
    const test::CliResult r =
        test::RunCli({"synth", "arm", dir_->path(), "--seed", "3", "--frames", "30", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static test::TempDir* dir_;
};
test::TempDir* CliLk::dir_ = nullptr;

TEST_F(CliLk, BackgroundFramesGiveOneOkRowPerFrameAfterTheStandstill) {
  const std::string out = dir_->file("bg.tsv");
  const test::CliResult r =
      test::RunCli({"analyze", dir_->file("scene.avi"), "-o", out, "--engine", "lk",
                    "--background-frames", "45", "--start", "45", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(out, &f).ok());
  EXPECT_EQ(f.Meta("engine"), "lk");
  ASSERT_EQ(f.rows.size(), 30u);  // 45 + 60 + 30 frames: rows for the 30 after the standstill
  EXPECT_EQ(f.rows.front().frame, 105);
  for (const AngleRow& row : f.rows) EXPECT_TRUE(row.ok()) << row.frame;
}

TEST_F(CliLk, ShoulderAloneStartsAtTheFirstFrame) {
  const std::string out = dir_->file("sh.tsv");
  const test::CliResult r = test::RunCli({"analyze", dir_->file("scene.avi"), "-o", out, "--engine",
                                          "lk", "--shoulder", "190,100", "--start", "100",
                                          "--initial-upper", "-90", "--initial-fore", "-90", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(out, &f).ok());
  ASSERT_EQ(f.rows.size(), 35u);
  EXPECT_EQ(f.rows.front().frame, 100);
  EXPECT_NEAR(f.rows.front().upper_deg, -90, 1e-6);
}

// Footage with no empty-background stretch: a person already in view, one arm moving, analysed
// from the given shoulder within a region of interest. Angles must hold the target and every
// position must come back in full-image pixels.
TEST_F(CliLk, ShoulderAndRoiWithoutBackgroundHoldTheTarget) {
  const std::string out = dir_->file("roi.tsv");
  const test::CliResult r =
      test::RunCli({"analyze", dir_->file("scene.avi"), "-o", out, "--engine", "lk", "--shoulder",
                    "190,100", "--roi", "130,40,170,190", "--start", "104", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  synth::TruthFile truth;
  AngleFile angles;
  ASSERT_TRUE(synth::ReadTruthFile(dir_->file("truth.tsv"), &truth).ok());
  ASSERT_TRUE(ReadAngleFile(out, &angles).ok());
  const synth::ScoreSummary s = synth::ScoreAngles(truth, angles).summary;
  EXPECT_EQ(s.ok_frames, s.matched_frames);
  EXPECT_LE(s.overall.mae, 4.0) << "upper " << s.upper.mae << ", fore " << s.fore.mae;
  for (const AngleRow& row : angles.rows) {
    EXPECT_GE(row.fore_cx, 130) << row.frame;  // inside the ROI, in full-image pixels
    EXPECT_LE(row.fore_cx, 300) << row.frame;
    EXPECT_GE(row.upper_cy, 40) << row.frame;
  }
}

TEST_F(CliLk, MissingShoulderAndBackgroundIsAUsageError) {
  const test::CliResult r = test::RunCli(
      {"analyze", dir_->file("scene.avi"), "-o", dir_->file("x.tsv"), "--engine", "lk"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--shoulder"), std::string::npos) << r.err;
}

TEST_F(CliLk, ShoulderOutsideTheFrameNamesTheFlag) {
  const test::CliResult r =
      test::RunCli({"analyze", dir_->file("scene.avi"), "-o", dir_->file("y.tsv"), "--engine", "lk",
                    "--shoulder", "900,100"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--shoulder"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace armmimic
