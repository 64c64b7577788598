// LevelWarp (docs/marker.md, "A tilted camera"): the levelled image and the map back to the image
// as taken agree, every original row lands inside the levelled image, and the limbs' lean gives
// back the tilt that made it.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "marker/level.h"

namespace armmimic::internal {
namespace {

// The centroid of the dark pixels of `image` (a dark dot on white).
cv::Point2d DarkCentroid(const cv::Mat& image) {
  double sum = 0, sx = 0, sy = 0;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const double w = 255.0 - image.at<uchar>(y, x);
      sum += w, sx += w * x, sy += w * y;
    }
  }
  return {sx / sum, sy / sum};
}

TEST(LevelWarp, ADotLevelledMapsBackToWhereItWas) {
  const cv::Size size(320, 240);
  const MarkerCamera camera = MarkerCamera::FromFov(56, size);
  for (double pitch_deg : {-6.0, 3.0}) {
    const LevelWarp warp(camera, size, RadFromDeg(pitch_deg));
    ASSERT_TRUE(warp.active());
    EXPECT_EQ(warp.level_size().width, size.width);
    EXPECT_NEAR(warp.level_size().height, size.height, 6);
    for (const cv::Point2d dot : {cv::Point2d(60.5, 30.25), cv::Point2d(250, 200.5)}) {
      cv::Mat image(size, CV_8U, cv::Scalar(255));
      cv::circle(image, cv::Point(cvRound(dot.x * 16), cvRound(dot.y * 16)), 4 * 16, cv::Scalar(0),
                 cv::FILLED, cv::LINE_AA, 4);
      cv::Mat level;
      warp.Apply(image, &level);
      const cv::Point2d back = warp.ToOriginal(DarkCentroid(level));
      EXPECT_NEAR(back.x, dot.x, 0.15) << pitch_deg;
      EXPECT_NEAR(back.y, dot.y, 0.15) << pitch_deg;
    }
    // The original image's first and last rows lie within the levelled one.
    for (double x : {0.0, 160.0, 319.0}) {
      for (double y : {0.0, static_cast<double>(warp.level_size().height - 1)}) {
        const cv::Point2d p = warp.ToOriginal({x, y});
        EXPECT_GT(p.y, -1.0) << pitch_deg;
        EXPECT_LT(p.y, size.height) << pitch_deg;
      }
    }
  }
}

// Two vertical lines seen by a camera pitched by p lean by -(x - cx) tan(p) / f columns per
// row; LevelPitch reads p back from them, whatever the roll adds to both.
TEST(LevelPitch, TheLimbsLeanApartByTheTilt) {
  const MarkerCamera camera = MarkerCamera::FromFov(60, cv::Size(320, 240));
  for (double pitch_deg : {-5.0, 2.5}) {
    LowerCalibration cal;
    const double roll_lean = 0.004;
    for (int side = 0; side < 2; ++side) {
      cal.limb_x[side] = side == 0 ? 190 : 262;
      cal.limb_lean[side] = -(cal.limb_x[side] - camera.principal_px.x) *
                                std::tan(RadFromDeg(pitch_deg)) / camera.focal_px +
                            roll_lean;
    }
    EXPECT_NEAR(DegFromRad(LevelPitch(cal, camera)), pitch_deg, 1e-9);
  }
  LowerCalibration unfitted;
  unfitted.limb_x[0] = 100;
  unfitted.limb_lean[0] = 0.01;
  EXPECT_TRUE(std::isnan(LevelPitch(unfitted, camera)));
}

}  // namespace
}  // namespace armmimic::internal
