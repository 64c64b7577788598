// armmimic-cli synth arm --generator capsule: the scene folder of the thesis protocol (video,
// background, arm-length image, truth with the 3-D columns) that analyze and score take as they
// are, and the flags that cannot go with it.
#include <filesystem>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/image_io.h"
#include "armmimic/core/video_source.h"
#include "armmimic/synth/truth_file.h"
#include "test_util.h"

namespace armmimic {
namespace {

using test::RunCli;

bool Contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(CliSynthCapsule, WritesTheProtocolFilesThatAnalyzeAndScoreTake) {
  test::TempDir dir;
  const std::string s = dir.file("s");
  const test::CliResult r = RunCli({"synth", "arm", s, "--generator", "capsule", "--tier", "medium",
                                    "--seed", "3040", "--size", "160x120", "--no-progress"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "capsule medium scene, seed 3040")) << r.err;
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(s + "/truth.tsv", &truth).ok());
  EXPECT_EQ(truth.Meta("generator"), "capsule");
  EXPECT_EQ(truth.Meta("tier"), "medium");
  EXPECT_EQ(truth.Meta("background_frames"), "45");
  EXPECT_EQ(truth.Meta("standstill_frames"), "60");
  const int n = std::stoi(truth.Meta("motion_frames"));
  ASSERT_EQ(static_cast<int>(truth.rows.size()), 105 + n);
  EXPECT_GE(truth.ExtraColumn("elbow_deg"), 0);
  EXPECT_FALSE(truth.rows[44].HasAngles());
  EXPECT_TRUE(truth.rows[45].HasAngles());
  Status st;
  const auto video = VideoSource::Open(s + "/scene.avi", &st);
  ASSERT_TRUE(video) << st.message();
  EXPECT_EQ(video->info().frame_count, 105 + n);
  EXPECT_EQ(video->info().size, cv::Size(160, 120));
  for (const char* f : {"armlength.png", "background.png"}) {
    cv::Mat img;
    ASSERT_TRUE(ReadImage(s + "/" + f, &img).ok()) << f;
    EXPECT_EQ(img.size(), cv::Size(160, 120)) << f;
  }
  // The thesis protocol runs on the folder as written, and score reads its truth.
  const test::CliResult a =
      RunCli({"-q", "analyze", s + "/scene.avi", "-o", dir.file("a.tsv"), "--engine", "bgsub",
              "--background", s + "/background.png", "--arm-length", s + "/armlength.png",
              "--start", "45", "--standstill-frames", "60"});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(dir.file("a.tsv"), &angles).ok());
  EXPECT_EQ(static_cast<int>(angles.rows.size()), n);
  const test::CliResult sc =
      RunCli({"score", s + "/truth.tsv", dir.file("a.tsv"), "--summary-only"});
  ASSERT_EQ(sc.exit_code, 0) << sc.err;
  EXPECT_TRUE(Contains(sc.out, "coverage")) << sc.out;
  // The same seed and tier write the same truth.
  ASSERT_EQ(RunCli({"-q", "synth", "arm", dir.file("t"), "--generator", "capsule", "--tier",
                    "medium", "--seed", "3040", "--size", "160x120"})
                .exit_code,
            0);
  EXPECT_EQ(test::ReadFile(s + "/truth.tsv"), test::ReadFile(dir.file("t/truth.tsv")));
}

TEST(CliSynthCapsule, FlagsTheSeedDrawsAndTheEasyTierAreUsageErrors) {
  test::TempDir dir;
  struct Case {
    std::vector<std::string> args;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {{"--generator", "capsule", "--fps", "10"}, "--fps"},
      {{"--generator", "capsule", "--side", "left"}, "--side"},
      {{"--generator", "capsule", "--tier", "easy"}, "--tier easy"},
      {{"--generator", "capsule", "--random"}, "--random cannot be combined"},
      {{"--generator", "sketch"}, "--generator"},
      {{"--generator", "capsule", "--size", "160x240"}, "--size"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"synth", "arm", dir.file("out")};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const test::CliResult r = RunCli(args);
    EXPECT_EQ(r.exit_code, 2) << c.expect << ": " << r.err;
    EXPECT_TRUE(Contains(r.err, c.expect)) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("out")));
}

}  // namespace
}  // namespace armmimic
