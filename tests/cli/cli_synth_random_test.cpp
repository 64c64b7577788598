// armmimic-cli synth arm --random: the scene folder of a drawn scene, and the flags that cannot
// go with it.
#include <filesystem>

#include <gtest/gtest.h>

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

TEST(CliSynthRandom, WritesTheSceneFolderWithItsKnobsInTheMetaLine) {
  test::TempDir dir;
  const test::CliResult r = RunCli({"synth", "arm", dir.file("s"), "--random", "--tier", "hard",
                                    "--seed", "1042", "--size", "160x120", "--no-progress"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "random hard scene, seed 1042")) << r.err;
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(dir.file("s/truth.tsv"), &truth).ok());
  EXPECT_EQ(truth.Meta("random"), "1");
  EXPECT_EQ(truth.Meta("tier"), "hard");
  EXPECT_EQ(truth.Meta("seed"), "1042");
  const int k = std::stoi(truth.Meta("background_frames"));
  const int m = std::stoi(truth.Meta("standstill_frames"));
  const int n = std::stoi(truth.Meta("motion_frames"));
  EXPECT_EQ(static_cast<int>(truth.rows.size()), k + m + n);
  EXPECT_FALSE(truth.Meta("upper_length_px").empty());
  EXPECT_FALSE(truth.Meta("camouflage").empty());
  Status st;
  const auto video = VideoSource::Open(dir.file("s/scene.avi"), &st);
  ASSERT_TRUE(video) << st.message();
  EXPECT_EQ(video->info().frame_count, k + m + n);
  EXPECT_EQ(video->info().size, cv::Size(160, 120));
  EXPECT_NEAR(video->info().fps, std::stod(truth.Meta("fps")), 1e-6);
  for (const char* f : {"armlength.png", "background.png"}) {
    cv::Mat img;
    ASSERT_TRUE(ReadImage(dir.file(std::string("s/") + f), &img).ok()) << f;
    EXPECT_EQ(img.size(), cv::Size(160, 120)) << f;
  }
  // The same seed and tier write the same truth.
  ASSERT_EQ(RunCli({"-q", "synth", "arm", dir.file("t"), "--random", "--tier", "hard", "--seed",
                    "1042", "--size", "160x120"})
                .exit_code,
            0);
  EXPECT_EQ(test::ReadFile(dir.file("s/truth.tsv")), test::ReadFile(dir.file("t/truth.tsv")));
}

TEST(CliSynthRandom, FlagsTheSeedDrawsAreUsageErrorsNamingTheFlag) {
  test::TempDir dir;
  struct Case {
    std::vector<std::string> args;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {{"--random", "--fps", "10"}, "--fps"},
      {{"--random", "--side", "left"}, "--side"},
      {{"--random", "--shadow"}, "--shadow"},
      {{"--random", "--tier", "extreme"}, "--tier"},
      {{"--tier", "easy"}, "--tier goes with --random"},
      {{"--random", "--size", "160x240"}, "--size"},
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
