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

// The angle file's 3-D convention: x to the image's right, y down, z away from the camera.
TEST(Angles, AzimuthAndElevationFollowTheCameraFrame) {
  const cv::Vec3d o(1, 2, 3);
  double az = 0, el = 0;
  AzimuthElevationDeg(o, o + cv::Vec3d(1, 0, 0), &az, &el);  // to the image's right
  EXPECT_NEAR(az, 0, 1e-12);
  EXPECT_NEAR(el, 0, 1e-12);
  AzimuthElevationDeg(o, o + cv::Vec3d(0, 0, -2), &az, &el);  // at the camera
  EXPECT_NEAR(az, 90, 1e-12);
  EXPECT_NEAR(el, 0, 1e-12);
  AzimuthElevationDeg(o, o + cv::Vec3d(0, 0, 2), &az, &el);  // away from it
  EXPECT_NEAR(az, -90, 1e-12);
  AzimuthElevationDeg(o, o + cv::Vec3d(-1, -1, 0), &az, &el);  // up and to the left
  EXPECT_NEAR(az, 180, 1e-12);
  EXPECT_NEAR(el, 45, 1e-12);
  AzimuthElevationDeg(o, o + cv::Vec3d(0, 3, 0), &az, &el);  // straight down
  EXPECT_NEAR(el, -90, 1e-12);
}

TEST(Angles, TheJointAngleIs180ForAStraightArm) {
  const cv::Vec3d shoulder(0, 0, 0), elbow(0, 0.25, 0);
  EXPECT_NEAR(JointAngleDeg(shoulder, elbow, {0, 0.5, 0}), 180, 1e-9);
  EXPECT_NEAR(JointAngleDeg(shoulder, elbow, {0, 0.25, -0.2}), 90, 1e-9);  // forearm at the camera
  EXPECT_NEAR(JointAngleDeg(shoulder, elbow, {0.1, 0.15, 0}), 45, 1e-9);
}

}  // namespace
}  // namespace armmimic
