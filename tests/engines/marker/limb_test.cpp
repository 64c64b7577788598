// FitLimb (docs/marker.md, "Calibration", step 2) on drawn profiles with a known limb: a line
// leaning with the rows, a surface whose grey level runs like p + q sqrt(d) + r d inside it (the
// same in every row), a wall whose level changes from row to row (once as dark as the limb), the
// lens' blur and noise.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "marker/limb.h"

namespace armmimic::internal {
namespace {

constexpr double kLimbX = 50.3, kLean = 0.02, kRefRow = 50;

// The image of a limb at kLimbX + kLean (y - kRefRow); `inside` +1: the joint to its right.
cv::Mat DrawLimb(int inside) {
  cv::Mat f(100, 120, CV_32F);
  const double walls[4] = {72, 125, 40, 95};  // the first as dark as the limb (70)
  for (int y = 0; y < f.rows; ++y) {
    const double t = kLimbX + kLean * (y - kRefRow), wall = walls[(y / 10) % 4];
    for (int x = 0; x < f.cols; ++x) {
      double sum = 0;
      constexpr int kSub = 16;
      for (int k = 0; k < kSub; ++k) {
        const double d = inside * (x - 0.5 + (k + 0.5) / kSub - t);
        sum += d > 0 ? 70 + 12 * std::sqrt(d) + 1.5 * d : wall + 0.4 * d;
      }
      f.at<float>(y, x) = static_cast<float>(sum / kSub);
    }
  }
  cv::GaussianBlur(f, f, cv::Size(0, 0), 0.5);
  cv::Mat noise(f.size(), CV_32F);
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::NORMAL, 0, 1.5);
  cv::Mat out;
  cv::Mat(f + noise).convertTo(out, CV_8U);
  return out;
}

std::vector<int> Rows() {
  std::vector<int> rows;
  for (int y = 10; y < 90; ++y) rows.push_back(y);
  return rows;
}

TEST(MarkerLimb, FindsALeaningLimbOnEitherSide) {
  for (int inside : {1, -1}) {
    const cv::Mat gray = DrawLimb(inside);
    const LimbFit fit = FitLimb(gray, Rows(), kLimbX + 1.2, kRefRow, inside, 2);
    ASSERT_TRUE(fit.ok) << "inside " << inside;
    EXPECT_NEAR(fit.x, kLimbX, 0.15) << "inside " << inside;
    EXPECT_NEAR(fit.lean, kLean, 0.003) << "inside " << inside;
  }
}

TEST(MarkerLimb, ALimbJustBeyondReachIsNotFitted) {
  // The limb 2.6 pixels from the guess, 2 allowed: the best fit runs to the end of the search,
  // which is no limb (the surface's own shading fitted as the wall).
  for (int inside : {1, -1}) {
    const cv::Mat gray = DrawLimb(inside);
    const LimbFit fit = FitLimb(gray, Rows(), kLimbX + inside * 2.6, kRefRow, inside, 2);
    EXPECT_FALSE(fit.ok) << "inside " << inside << ": " << fit.x;
  }
}

}  // namespace
}  // namespace armmimic::internal
