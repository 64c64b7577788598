// Eq. 6-16 and the 2-means split of the LK engine on points with known motion.
#include "lk/fit.h"

#include <cmath>

#include <gtest/gtest.h>

#include "armmimic/core/angles.h"

namespace armmimic::lk {
namespace {

TEST(LkFit, RecoversKnownRotationAndTranslation) {
  const double ccw_deg = 23;
  Motion2D truth;
  const double phi = -RadFromDeg(ccw_deg);  // image axes: clockwise is positive
  truth.a = std::cos(phi);
  truth.b = std::sin(phi);
  truth.t = {12.5, -4};
  std::vector<cv::Point2d> from, to;
  for (int i = 0; i < 12; ++i) {
    const cv::Point2d p(3.0 * i - 10, 0.5 * i * i - 7);
    from.push_back(p);
    to.push_back(truth.Apply(p));
  }
  Motion2D m;
  ASSERT_TRUE(FitMotion(from, to, {}, &m));
  EXPECT_NEAR(m.RotationCcwDeg(), ccw_deg, 1e-6);
  EXPECT_NEAR(m.Scale(), 1.0, 1e-9);
  EXPECT_NEAR(m.t.x, 12.5, 1e-6);
  EXPECT_NEAR(m.t.y, -4, 1e-6);
}

TEST(LkFit, RigidFitIgnoresAnOutlierWithZeroWeight) {
  std::vector<cv::Point2d> from = {{0, 0}, {10, 0}, {0, 10}, {5, 5}};
  std::vector<cv::Point2d> to = {{1, 1}, {1, 11}, {-9, 1}, {100, 100}};  // 90 deg CW in image
  Motion2D m;
  ASSERT_TRUE(FitRigidMotion(from, to, {1, 1, 1, 0}, &m));
  EXPECT_NEAR(m.RotationCcwDeg(), -90, 1e-6);
  EXPECT_NEAR(m.Scale(), 1, 1e-9);
  EXPECT_NEAR(m.Apply({0, 0}).x, 1, 1e-6);
}

TEST(LkFit, DegenerateInputIsRejected) {
  Motion2D m;
  EXPECT_FALSE(FitMotion({{1, 1}}, {{2, 2}}, {}, &m));
  EXPECT_FALSE(FitMotion({{1, 1}, {1, 1}}, {{2, 2}, {2, 2}}, {}, &m));
}

TEST(LkFit, TwoMeansSplitsTwoMotions) {
  std::vector<cv::Point2f> pts, motion;
  for (int i = 0; i < 6; ++i) {
    pts.emplace_back(10.f + i, 10.f);
    motion.emplace_back(0.f, 1.f);
    pts.emplace_back(60.f + i, 40.f);
    motion.emplace_back(3.f, -2.f);
  }
  const std::vector<int> labels = TwoMeans(pts, motion);
  for (std::size_t i = 0; i < pts.size(); i += 2) {
    EXPECT_NE(labels[i], labels[i + 1]);
    EXPECT_EQ(labels[i], labels[0]);
  }
}

}  // namespace
}  // namespace armmimic::lk
