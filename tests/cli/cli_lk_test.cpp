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

// The operator's three clicks on the start frame (here the truth's joints at frame 104): the
// starting directions and both segment lengths are measured, so the region of interest no longer
// sets the arm's length and two very different boxes give the same rows.
TEST_F(CliLk, ClickedJointsMakeTheRowsIndependentOfTheRoi) {
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(dir_->file("truth.tsv"), &truth).ok());
  const synth::TruthRow* start = nullptr;
  for (const synth::TruthRow& row : truth.rows) {
    if (row.frame == 104) start = &row;
  }
  ASSERT_NE(start, nullptr);
  auto xy = [](double x, double y) { return FormatNumber(x, 1) + "," + FormatNumber(y, 1); };
  const std::string shoulder = xy(start->shoulder_x, start->shoulder_y);
  const std::string elbow = xy(start->elbow_x, start->elbow_y);
  const std::string wrist = xy(start->wrist_x, start->wrist_y);
  std::vector<synth::ScoreSummary> scores;
  std::vector<std::string> files;
  for (const std::string roi : {"100,20,210,215", "130,60,170,130"}) {
    const std::string out = dir_->file("joints_" + std::to_string(files.size()) + ".tsv");
    const test::CliResult r = test::RunCli(
        {"analyze", dir_->file("scene.avi"), "-o", out, "--engine", "lk", "--shoulder", shoulder,
         "--elbow", elbow, "--wrist", wrist, "--roi", roi, "--start", "104"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("estimated"), std::string::npos) << "nothing is estimated: " << r.err;
    AngleFile angles;
    ASSERT_TRUE(ReadAngleFile(out, &angles).ok());
    EXPECT_EQ(angles.Meta("calibration"), "joints");
    scores.push_back(synth::ScoreAngles(truth, angles).summary);
    files.push_back(out);
  }
  for (const synth::ScoreSummary& s : scores) {
    EXPECT_GE(s.ok_frames, 0.95 * s.matched_frames);
    EXPECT_LE(s.overall.mae, 3.0) << "upper " << s.upper.mae << ", fore " << s.fore.mae;
  }
  EXPECT_NEAR(scores[0].overall.mae, scores[1].overall.mae, 0.5);
}

// With a shoulder only, the arm length is a guess from the analysed height: it is printed.
TEST_F(CliLk, AnEstimatedArmLengthIsPrinted) {
  const test::CliResult r =
      test::RunCli({"analyze", dir_->file("scene.avi"), "-o", dir_->file("est.tsv"), "--engine",
                    "lk", "--shoulder", "190,100", "--roi", "130,60,170,130", "--start", "104"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("estimated: lk: arm length 52 px"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("region of interest"), std::string::npos) << r.err;
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(dir_->file("est.tsv"), &angles).ok());
  EXPECT_EQ(angles.Meta("calibration"), "shoulder");
}

TEST_F(CliLk, CalibrationFlagsThatContradictEachOtherAreUsageErrors) {
  const std::string video = dir_->file("scene.avi"), out = dir_->file("bad.tsv");
  struct Case {
    std::vector<std::string> flags;
    std::string expect;
  } cases[] = {
      {{"--background-frames", "45", "--elbow", "190,144", "--wrist", "190,182"}, "--shoulder"},
      {{"--shoulder", "190,100", "--elbow", "190,144"}, "--wrist"},
      {{"--shoulder", "190,100", "--standstill-frames", "30"}, "--standstill-frames"},
      {{"--shoulder", "190,100", "--elbow", "190,144", "--wrist", "190,182", "--initial-upper",
        "-80"},
       "--initial-upper"},
      {{"--shoulder", "190,100", "--elbow", "191,101", "--wrist", "190,182"}, "--elbow"},
      {{"--shoulder", "190,100", "--elbow", "190,144", "--wrist", "190,999"}, "--wrist"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"analyze", video, "-o", out, "--engine", "lk"};
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    const test::CliResult r = test::RunCli(args);
    EXPECT_NE(r.exit_code, 0) << c.expect;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
  }
  const test::CliResult bgsub =
      test::RunCli({"analyze", video, "-o", out, "--engine", "bgsub", "--background-frames", "45",
                    "--arm-length", dir_->file("armlength.png"), "--elbow", "190,144"});
  EXPECT_EQ(bgsub.exit_code, 2);
  EXPECT_NE(bgsub.err.find("--elbow is not used by --engine bgsub"), std::string::npos)
      << bgsub.err;
}

}  // namespace
}  // namespace armmimic
