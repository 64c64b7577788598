#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/geometry.h"

namespace armmimic {
namespace {

// Folds an axis angle in degrees into (-90, 90].
double FoldAxis(double deg) {
  while (deg <= -90) deg += 180;
  while (deg > 90) deg -= 180;
  return deg;
}

// Independent cross-check: the axis from atan2, y flipped to the contract's convention.
double Atan2OrientationDeg(const RegionMoments& m) {
  return FoldAxis(-0.5 * std::atan2(2 * m.mu11, m.mu20 - m.mu02) * 180.0 / CV_PI);
}

double AxisDiff(double a, double b) { return std::abs(FoldAxis(a - b)); }

int Sign(double v) { return v > 1e-9 ? 1 : (v < -1e-9 ? -1 : 0); }

// A filled ellipse whose major axis points `contract_deg` CCW on screen from +x.
cv::Mat EllipseMask(cv::Size size, cv::Point centre, cv::Size axes, double contract_deg) {
  cv::Mat mask(size, CV_8UC1, cv::Scalar(0));
  // cv::ellipse rotates clockwise on screen (from +x towards +y, image y down).
  cv::ellipse(mask, centre, axes, -contract_deg, 0, 360, cv::Scalar(255), cv::FILLED, cv::LINE_8);
  return mask;
}

// A two-pixel-thick diagonal made symmetric under the reflection that swaps the x and y
// spreads, so mu20 == mu02 exactly. `down_right`: the line goes down-right on screen.
cv::Mat DiagonalMask(bool down_right) {
  const int k = 40;
  cv::Mat mask(k + 10, k + 10, CV_8UC1, cv::Scalar(0));
  for (int i = 5; i < k; ++i) {
    if (down_right) {  // symmetric under (x, y) -> (y, x)
      mask.at<uint8_t>(i, i) = 255;
      mask.at<uint8_t>(i, i + 1) = 255;
      mask.at<uint8_t>(i + 1, i) = 255;
    } else {  // symmetric under (x, y) -> (k - y, k - x)
      mask.at<uint8_t>(k - i, i) = 255;
      mask.at<uint8_t>(k - i, i + 1) = 255;
      mask.at<uint8_t>(k - i - 1, i) = 255;
    }
  }
  return mask;
}

TEST(Moments, RectangleHasExactMoments) {
  cv::Mat mask(60, 80, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(10, 20, 30, 8)).setTo(1);  // any non-zero value counts 1
  const RegionMoments m = ComputeMoments(mask);
  EXPECT_DOUBLE_EQ(m.m00, 240);
  EXPECT_DOUBLE_EQ(m.cx, 24.5);
  EXPECT_DOUBLE_EQ(m.cy, 23.5);
  EXPECT_DOUBLE_EQ(m.m10, 240 * 24.5);
  EXPECT_DOUBLE_EQ(m.m01, 240 * 23.5);
  EXPECT_NEAR(m.mu20, 240 * (30.0 * 30 - 1) / 12, 1e-9);  // discrete variance of 0..29
  EXPECT_NEAR(m.mu02, 240 * (8.0 * 8 - 1) / 12, 1e-9);
  EXPECT_DOUBLE_EQ(m.mu11, 0);
}

TEST(Moments, AgreeWithOpenCvOnARotatedBlob) {
  cv::Mat mask = EllipseMask({320, 240}, {170, 110}, {70, 20}, 33);
  cv::circle(mask, {120, 150}, 15, cv::Scalar(255), cv::FILLED);
  const RegionMoments m = ComputeMoments(mask);
  const cv::Moments cvm = cv::moments(mask, true);
  EXPECT_NEAR(m.m00, cvm.m00, 1e-9 * cvm.m00);
  EXPECT_NEAR(m.m10, cvm.m10, 1e-9 * cvm.m10);
  EXPECT_NEAR(m.m01, cvm.m01, 1e-9 * cvm.m01);
  EXPECT_NEAR(m.mu20, cvm.mu20, 1e-7 * cvm.mu20);
  EXPECT_NEAR(m.mu02, cvm.mu02, 1e-7 * cvm.mu02);
  EXPECT_NEAR(m.mu11, cvm.mu11, 1e-7 * std::abs(cvm.mu11));
}

TEST(Moments, RoiKeepsFullImageCoordinates) {
  cv::Mat mask = EllipseMask({200, 150}, {100, 75}, {50, 12}, -25);
  mask(cv::Rect(0, 0, 30, 30)).setTo(255);  // clutter outside the ROI
  const cv::Rect roi(40, 40, 130, 80);
  cv::Mat only_roi(mask.size(), CV_8UC1, cv::Scalar(0));
  mask(roi).copyTo(only_roi(roi));
  const RegionMoments a = ComputeMoments(mask, roi);
  const RegionMoments b = ComputeMoments(only_roi);
  EXPECT_DOUBLE_EQ(a.m00, b.m00);
  EXPECT_DOUBLE_EQ(a.cx, b.cx);
  EXPECT_DOUBLE_EQ(a.cy, b.cy);
  EXPECT_DOUBLE_EQ(a.mu20, b.mu20);
  EXPECT_DOUBLE_EQ(a.mu11, b.mu11);
  // A ROI reaching past the image is clipped.
  const RegionMoments c = ComputeMoments(mask, cv::Rect(-50, -50, 1000, 1000));
  EXPECT_DOUBLE_EQ(c.m00, ComputeMoments(mask).m00);
}

TEST(Moments, EmptyRegionIsAllZero) {
  const RegionMoments m = ComputeMoments(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)));
  EXPECT_EQ(m.m00, 0);
  EXPECT_EQ(m.cx, 0);
  EXPECT_EQ(ComputeSemiAxes(m).major, 0);
  EXPECT_EQ(ComputeMoments(cv::Mat()).m00, 0);
  EXPECT_THROW(ComputeMoments(cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(0))), std::invalid_argument);
}

// The nine sign cases of Table 3-1: sign(mu20 - mu02) x sign(mu11).
struct OrientationCase {
  const char* name;
  int sign_d;
  int sign_mu11;
  double expected_deg;
  cv::Mat mask;
};

TEST(Orientation, AllNineSignCasesOfTable31) {
  const cv::Size size(320, 240);
  const cv::Point c(160, 120);
  cv::Mat square(size, CV_8UC1, cv::Scalar(0));
  square(cv::Rect(140, 100, 41, 41)).setTo(255);
  cv::Mat hbar(size, CV_8UC1, cv::Scalar(0));
  hbar(cv::Rect(60, 115, 200, 9)).setTo(255);
  cv::Mat vbar(size, CV_8UC1, cv::Scalar(0));
  vbar(cv::Rect(155, 20, 9, 200)).setTo(255);
  const std::vector<OrientationCase> cases = {
      {"d>0 mu11=0 (horizontal)", 1, 0, 0, hbar},
      {"d<0 mu11=0 (vertical)", -1, 0, 90, vbar},
      {"d=0 mu11=0 (square)", 0, 0, 0, square},
      {"d=0 mu11>0 (down-right diagonal)", 0, 1, -45, DiagonalMask(true)},
      {"d=0 mu11<0 (up-right diagonal)", 0, -1, 45, DiagonalMask(false)},
      {"d>0 mu11>0 (shallow, down-right)", 1, 1, -20, EllipseMask(size, c, {90, 8}, -20)},
      {"d>0 mu11<0 (shallow, up-right)", 1, -1, 20, EllipseMask(size, c, {90, 8}, 20)},
      {"d<0 mu11>0 (steep, down-right)", -1, 1, -70, EllipseMask(size, c, {90, 8}, -70)},
      {"d<0 mu11<0 (steep, up-right)", -1, -1, 70, EllipseMask(size, c, {90, 8}, 70)},
  };
  for (const auto& oc : cases) {
    SCOPED_TRACE(oc.name);
    const RegionMoments m = ComputeMoments(oc.mask);
    ASSERT_GT(m.m00, 0);
    // The mask really exercises the case it is named after.
    ASSERT_EQ(Sign(m.mu20 - m.mu02), oc.sign_d);
    ASSERT_EQ(Sign(m.mu11), oc.sign_mu11);
    const double deg = OrientationDeg(m);
    EXPECT_GT(deg, -90);
    EXPECT_LE(deg, 90);
    EXPECT_NEAR(deg, oc.expected_deg, 1.0);
    if (oc.sign_d != 0 || oc.sign_mu11 != 0) {
      EXPECT_NEAR(AxisDiff(deg, Atan2OrientationDeg(m)), 0, 1e-9);
    }
  }
}

TEST(Orientation, MatchesAtan2FormulaAndDrawnAngleAllAround) {
  cv::RNG rng(7);
  for (int i = 0; i < 72; ++i) {
    const double truth = -87.5 + i * 2.5 + rng.uniform(0.0, 2.0);  // sweeps (-90, 90]
    const cv::Mat mask = EllipseMask({320, 240}, {160, 120}, {80, 10}, truth);
    const RegionMoments m = ComputeMoments(mask);
    const double deg = OrientationDeg(m);
    SCOPED_TRACE(truth);
    EXPECT_NEAR(AxisDiff(deg, Atan2OrientationDeg(m)), 0, 1e-9);
    EXPECT_LT(AxisDiff(deg, truth), 1.0);
    EXPECT_GT(deg, -90);
    EXPECT_LE(deg, 90);
  }
}

TEST(Orientation, VerticalAxisIsPlusNinetyNotMinus) {
  RegionMoments m;
  m.m00 = 10;
  m.mu20 = 1;
  m.mu02 = 50;
  m.mu11 = 0;
  EXPECT_EQ(OrientationDeg(m), 90);
}

TEST(SemiAxes, FilledEllipseWithinTwoPercent) {
  for (double angle : {0.0, 30.0, -65.0, 90.0}) {
    SCOPED_TRACE(angle);
    const cv::Mat mask = EllipseMask({320, 240}, {160, 120}, {80, 30}, angle);
    const SemiAxes s = ComputeSemiAxes(ComputeMoments(mask));
    EXPECT_NEAR(s.major, 80, 0.02 * 80);
    EXPECT_NEAR(s.minor, 30, 0.02 * 30);
  }
  cv::Mat disc(200, 200, CV_8UC1, cv::Scalar(0));
  cv::circle(disc, {100, 100}, 50, cv::Scalar(255), cv::FILLED);
  const SemiAxes s = ComputeSemiAxes(ComputeMoments(disc));
  EXPECT_NEAR(s.major, 50, 1.0);
  EXPECT_NEAR(s.minor, 50, 1.0);
}

}  // namespace
}  // namespace armmimic
