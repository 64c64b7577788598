#include "armmimic/core/angles.h"

#include <gtest/gtest.h>

namespace armmimic {
namespace {

TEST(Angles, ContractDirections) {
  const cv::Point2d shoulder(100, 100);
  EXPECT_DOUBLE_EQ(DirectionDeg(shoulder, {100, 150}), -90);  // hanging down
  EXPECT_DOUBLE_EQ(DirectionDeg(shoulder, {150, 100}), 0);    // screen right
  EXPECT_DOUBLE_EQ(DirectionDeg(shoulder, {100, 50}), 90);    // raised up
  EXPECT_DOUBLE_EQ(DirectionDeg(shoulder, {50, 100}), 180);   // left: +180, never -180
}

TEST(Angles, WrapAndFold) {
  EXPECT_DOUBLE_EQ(Wrap180(-180), 180);
  EXPECT_DOUBLE_EQ(Wrap180(190), -170);
  EXPECT_DOUBLE_EQ(Wrap180(540), 180);
  EXPECT_DOUBLE_EQ(FoldToAxis(-90), 90);
  EXPECT_DOUBLE_EQ(FoldToAxis(135), -45);
  EXPECT_DOUBLE_EQ(AngleDiff(170, -170), -20);
  EXPECT_DOUBLE_EQ(AxisDiff(10, -170), 0);
}

TEST(Angles, ResolveDirectionPointsAwayFromShoulder) {
  EXPECT_DOUBLE_EQ(ResolveDirection(90, {100, 100}, {100, 150}), -90);
  EXPECT_DOUBLE_EQ(ResolveDirection(-45, {0, 0}, {-10, -10}), 135);
  const cv::Point2d v = DirectionVector(-90);
  EXPECT_NEAR(v.x, 0, 1e-12);
  EXPECT_NEAR(v.y, 1, 1e-12);
}

}  // namespace
}  // namespace armmimic
