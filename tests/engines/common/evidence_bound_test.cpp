// The bound on the evidence near a point must hold for every sample within its reach: on a map
// with specks of the arm's colour over a textured wall (values all over [0, 1]), from a region
// off the frame's corner, at points on the map, beside it and far off it, with offsets up to
// the reach on both axes. And it must say something: 0 far off the map, no more than the map's
// largest value anywhere, and low on part of the map (where only the wall is).
#include "common/evidence_bound.h"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "painted_arm.h"

namespace armmimic::arm {
namespace {

TEST(EvidenceBoundTest, HoldsForEverySampleWithinReach) {
  const cv::Size size(160, 120);
  const cv::Mat wall = painted::TiledWall(size);
  ArmJoints joints;
  joints.shoulder = {60.3, 40.7};
  joints.elbow = joints.shoulder + 38 * cv::Point2d(0.5, 0.866);
  joints.wrist = joints.elbow + 32 * cv::Point2d(0.985, -0.174);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(0, 1);
  const cv::Mat arm = painted::Painted(wall, joints);
  const LearntArm learnt = LearnArm(arm, joints, 80);
  const cv::Mat frame = painted::Specked(arm, 80, &rng);
  LearntBackground background;
  background.Reset(wall, cv::Mat::zeros(size, CV_8U));
  const cv::Rect region(9, 6, 131, 97);
  EvidenceMap evidence;
  evidence.Compute(frame, background, learnt.colour, region, cv::Mat::zeros(size, CV_8U));
  double most = 0;
  cv::minMaxLoc(evidence.map(), nullptr, &most);
  ASSERT_GT(most, 0.5);  // the map holds the arm

  const EvidenceBound bound(evidence);
  const pairs::PairSampler map(evidence);
  const double reach = EvidenceBound::kReach;
  int checked = 0, above_zero = 0, low = 0;
  for (int i = 0; i < 4000; ++i) {
    // Points up to three blocks beyond the region on every side.
    const double px = region.x - 24 + unit(rng) * (region.width + 48);
    const double py = region.y - 24 + unit(rng) * (region.height + 48);
    const float b = bound.Near(pairs::PairOf({px, py}));
    EXPECT_LE(b, most * 1.001);
    const bool on_map = region.contains(cv::Point(static_cast<int>(px), static_cast<int>(py)));
    low += on_map && b < 0.25 * most ? 1 : 0;
    for (int j = 0; j < 12; ++j) {
      // Offsets anywhere within the reach, and at its corners.
      const double dx = j < 4 ? (j % 2 ? reach : -reach) : (2 * unit(rng) - 1) * reach;
      const double dy = j < 4 ? (j / 2 ? reach : -reach) : (2 * unit(rng) - 1) * reach;
      const float v = map.At(pairs::PairOf({px + dx, py + dy}));
      ASSERT_LE(v, b) << "point " << px << "," << py << " offset " << dx << "," << dy;
      ++checked;
      above_zero += v > 0 ? 1 : 0;
    }
    // Farther than a block and the reach off the map, nothing is near.
    if (px < region.x - 16 || py < region.y - 16 || px > region.x + region.width + 16 ||
        py > region.y + region.height + 16) {
      EXPECT_EQ(b, 0.f) << "point " << px << "," << py;
    }
  }
  EXPECT_EQ(checked, 48000);
  // Many samples are not 0 (the specks and the arm), and the bound is low on part of the map.
  EXPECT_GT(above_zero, 2000);
  EXPECT_GT(low, 200);
}

}  // namespace
}  // namespace armmimic::arm
