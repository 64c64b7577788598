// `analyze --engine lk` end to end through armmimic-cli: a rendered scene in, an angle file out;
// usage errors name the flag.
#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
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
