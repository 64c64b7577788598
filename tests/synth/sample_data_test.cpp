// The bundled sample (data/sample, made by scripts/make-sample.sh) stays consistent with the
// generator: same frame count, same truth as a fresh render with the documented options.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/videoio.hpp>

#include "armmimic/core/image_io.h"
#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

namespace armmimic::synth {
namespace {

TEST(SampleData, MatchesTheGeneratorAndStaysSmall) {
  const std::string dir = test::SourcePath("data/sample");
  TruthFile truth;
  const Status st = ReadTruthFile(dir + "/truth.tsv", &truth);
  ASSERT_TRUE(st.ok()) << st.message();
  ArmSceneOptions o;  // the options scripts/make-sample.sh passes
  o.seed = 2026;
  o.noise_sigma = 3;
  o.motion = ArmMotion::kMixed;
  EXPECT_EQ(truth.Meta("seed"), "2026");
  const ArmSceneRenderer scene(o);
  ASSERT_EQ(static_cast<int>(truth.rows.size()), scene.frame_count());
  for (const TruthRow& row : truth.rows) {
    const ArmTruth t = scene.Truth(row.frame);
    if (!t.person) {
      EXPECT_FALSE(row.HasAngles()) << row.frame;
      continue;
    }
    EXPECT_NEAR(row.upper_deg, t.upper_deg, 1e-3) << row.frame;
    EXPECT_NEAR(row.fore_deg, t.fore_deg, 1e-3) << row.frame;
    EXPECT_NEAR(row.elbow_x, t.elbow_px.x, 1e-2) << row.frame;
  }
  cv::VideoCapture cap(dir + "/scene.avi");
  ASSERT_TRUE(cap.isOpened());
  EXPECT_EQ(static_cast<int>(cap.get(cv::CAP_PROP_FRAME_COUNT)), scene.frame_count());
  cv::Mat frame;
  ASSERT_TRUE(cap.read(frame));
  EXPECT_EQ(frame.size(), cv::Size(320, 240));
  // The first frame is the empty room: close to background.png up to noise and compression.
  cv::Mat bg;
  ASSERT_TRUE(ReadImage(dir + "/background.png", &bg).ok());
  EXPECT_GT(cv::PSNR(frame, bg), 30);
  std::uintmax_t bytes = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) bytes += e.file_size();
  EXPECT_LT(bytes, 5u * 1000 * 1000);
}

}  // namespace
}  // namespace armmimic::synth
