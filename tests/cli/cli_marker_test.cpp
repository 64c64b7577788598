// armmimic-cli synth marker / analyze --engine marker / score, end to end, and exit codes.
#include <cmath>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/synth/truth_file.h"
#include "test_util.h"

namespace armmimic {
namespace {

TEST(CliMarker, SynthAnalyzeScore) {
  test::TempDir dir;
  const std::string scene = dir.file("scene");
  test::CliResult r = test::RunCli({"-q", "synth", "marker", scene, "--seed", "4", "--views", "12",
                                    "--lighting", "normal", "--max-yaw", "40"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string angles = dir.file("angles.tsv");
  r = test::RunCli({"-q", "analyze", scene + "/views", "-o", angles, "--engine", "marker",
                    "--reference", scene + "/reference.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(angles, &f).ok());
  EXPECT_TRUE(f.has_file_column);
  EXPECT_EQ(f.Meta("engine"), "marker");
  ASSERT_EQ(f.rows.size(), 12u);
  EXPECT_EQ(f.rows[0].file, "view_000.png");
  EXPECT_EQ(f.rows[11].file, "view_011.png");
  EXPECT_TRUE(f.has_signed_yaw_column);
  EXPECT_EQ(f.Meta("mode"), "cylinder");
  int ok = 0;
  for (const AngleRow& row : f.rows) {
    ok += row.ok();
    if (row.ok()) {
      EXPECT_DOUBLE_EQ(row.yaw_deg, std::abs(row.yaw_signed_deg));
    }
  }
  EXPECT_GE(ok, 10);
  r = test::RunCli({"score", scene + "/truth.tsv", angles});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("yaw"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bend"), std::string::npos) << r.out;

  // The views plan for the robot with no flags: still images get no low-pass filter and an
  // unreadable view holds the last readable pose.
  r = test::RunCli({"plan", angles, "-o", dir.file("views.val")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string val = test::ReadFile(dir.file("views.val"));
  EXPECT_NE(val.find("; filter cutoff_hz=0.000"), std::string::npos) << val.substr(0, 400);
  EXPECT_NE(r.err.find("without the low-pass filter"), std::string::npos) << r.err;

  // A list of files, in the order given.
  const std::string two = dir.file("two.tsv");
  r = test::RunCli({"-q", "analyze", scene + "/views/view_003.png", scene + "/views/view_001.png",
                    "-o", two, "--engine", "marker", "--reference", scene + "/reference.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(ReadAngleFile(two, &f).ok());
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_EQ(f.rows[0].file, "view_003.png");
  EXPECT_EQ(f.rows[1].file, "view_001.png");
}

TEST(CliMarker, ExitCodes) {
  test::TempDir dir;
  EXPECT_EQ(test::RunCli({"synth", "marker", "--help"}).exit_code, 0);
  test::CliResult r = test::RunCli({"synth", "marker", dir.file("s"), "--lighting", "moon"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--lighting"), std::string::npos) << r.err;
  r = test::RunCli({"synth", "marker", dir.file("s"), "--views", "zero"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--views"), std::string::npos) << r.err;
  r = test::RunCli({"synth", "marker"});
  EXPECT_EQ(r.exit_code, 2);

  ASSERT_EQ(test::RunCli({"-q", "synth", "marker", dir.file("s"), "--views", "2"}).exit_code, 0);
  // A reference that does not exist: a runtime failure naming the file.
  r = test::RunCli({"-q", "analyze", dir.file("s/views"), "-o", dir.file("a.tsv"), "--engine",
                    "marker", "--reference", dir.file("missing.png")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing.png"), std::string::npos) << r.err;
  // A reference without markers.
  r = test::RunCli({"-q", "analyze", dir.file("s/views"), "-o", dir.file("a.tsv"), "--engine",
                    "marker", "--reference", dir.file("s/views/view_000.png"), "--low", "0",
                    "--high", "3"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--reference"), std::string::npos) << r.err;
  // --low above --high is a usage error.
  r = test::RunCli({"-q", "analyze", dir.file("s/views"), "-o", dir.file("a.tsv"), "--engine",
                    "marker", "--reference", dir.file("s/reference.png"), "--low", "90"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--low"), std::string::npos) << r.err;
  EXPECT_EQ(test::RunCli({"-q", "analyze", "--help"}).exit_code, 0);
}

// The second renderer writes the same folder; its truth names the rig, whose lens analyze is
// given. Flags only the first renderer knows are usage errors with it.
TEST(CliMarker, TheRigRendererWritesASceneAnalyzeReads) {
  test::TempDir dir;
  const std::string scene = dir.file("rig");
  test::CliResult r = test::RunCli({"-q", "synth", "marker", scene, "--renderer", "rig", "--set",
                                    "easy", "--seed", "401", "--views", "3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(scene + "/truth.tsv", &truth).ok());
  EXPECT_EQ(truth.Meta("renderer"), "rig");
  EXPECT_EQ(truth.Meta("set"), "easy");
  ASSERT_FALSE(truth.Meta("fov_deg").empty());
  ASSERT_EQ(truth.rows.size(), 3u);
  const std::string angles = dir.file("rig.tsv");
  r = test::RunCli({"-q", "analyze", scene + "/views", "-o", angles, "--engine", "marker",
                    "--reference", scene + "/reference.png", "--fov", truth.Meta("fov_deg")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(angles, &f).ok());
  ASSERT_EQ(f.rows.size(), 3u);
  EXPECT_TRUE(f.has_signed_yaw_column);

  r = test::RunCli({"synth", "marker", dir.file("x"), "--renderer", "rig", "--fov", "50"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--fov does not apply to --renderer rig"), std::string::npos) << r.err;
  r = test::RunCli({"synth", "marker", dir.file("x"), "--set", "hard"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set needs --renderer rig"), std::string::npos) << r.err;
  r = test::RunCli({"synth", "marker", dir.file("x"), "--renderer", "rig", "--set", "odd"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace armmimic
