// The straight arm of the arm-length image continued past where a fixed difference threshold
// lost it (common/straight_arm.h, ContinueStraightArm): an arm held out across a door (found)
// and on over a wall of nearly its own colour (20 grey levels off, under the threshold of 45, over
// the noise), in the light of the standstill and in a brighter one, to either side.
#include "common/straight_arm.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace armmimic {
namespace {

constexpr int kWidth = 200, kHeight = 120;
constexpr int kDoorFrom = 60, kDoorTo = 110;  // the door's columns
constexpr int kArmTop = 50, kArmThick = 12;

// The room: a wall with a green door in it, with noise (sigma 4) drawn from `seed`.
cv::Mat Room(uint64_t seed, double light) {
  cv::Mat room(kHeight, kWidth, CV_8UC3, cv::Scalar(150, 160, 170));
  room(cv::Rect(kDoorFrom, 0, kDoorTo - kDoorFrom, kHeight)).setTo(cv::Scalar(40, 160, 40));
  cv::Mat f;
  room.convertTo(f, CV_32FC3, light);
  cv::Mat noise(room.size(), CV_32FC3);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, 4);
  f += noise;
  f.convertTo(room, CV_8UC3);
  return room;
}

// The arm-length image: the room in `light`, and an arm from the door's near edge to `tip`.
cv::Mat ArmLength(int tip, double light) {
  cv::Mat image = Room(2, light);
  cv::Mat arm(kArmThick, tip - kDoorFrom + 1, CV_8UC3, cv::Scalar(140, 170, 190));
  cv::Mat noise(arm.size(), CV_8UC3);
  cv::RNG(3).fill(noise, cv::RNG::UNIFORM, 0, 6);
  arm += noise;
  arm.copyTo(image(cv::Rect(kDoorFrom, kArmTop, arm.cols, kArmThick)));
  return image;
}

// The columns the masks found: the arm over the door only.
StraightArmColumns OverTheDoor() {
  StraightArmColumns cols;
  cols.ok = true;
  cols.inner_x = kDoorFrom;
  cols.outer_x = kDoorTo - 1;
  cols.thick_px = kArmThick;
  cols.axis_y = kArmTop + 0.5 * (kArmThick - 1);
  return cols;
}

TEST(ContinueStraightArm, FollowsTheArmOverAWallOfNearlyItsColour) {
  const cv::Mat standstill = Room(1, 1.0);
  EXPECT_NEAR(ContinueStraightArm(ArmLength(170, 1.0), standstill, OverTheDoor(), 1), 170, 1);
  // The arm-length image taken in a 10 % brighter light: the room there still is the room.
  EXPECT_NEAR(ContinueStraightArm(ArmLength(170, 1.1), standstill, OverTheDoor(), 1), 170, 1);
}

TEST(ContinueStraightArm, AnArmThatEndsWhereItWasFoundStaysAsItIs) {
  const cv::Mat standstill = Room(1, 1.0);
  EXPECT_EQ(ContinueStraightArm(ArmLength(kDoorTo - 1, 1.0), standstill, OverTheDoor(), 1),
            kDoorTo - 1);
  EXPECT_EQ(ContinueStraightArm(ArmLength(kDoorTo - 1, 1.1), standstill, OverTheDoor(), 1),
            kDoorTo - 1);
}

TEST(ContinueStraightArm, FollowsAnArmHeldOutToTheLeft) {
  cv::Mat standstill, arm_length;
  cv::flip(Room(1, 1.0), standstill, 1);
  cv::flip(ArmLength(170, 1.0), arm_length, 1);
  StraightArmColumns cols = OverTheDoor();
  cols.inner_x = kWidth - 1 - kDoorFrom;
  cols.outer_x = kWidth - 1 - (kDoorTo - 1);
  EXPECT_NEAR(ContinueStraightArm(arm_length, standstill, cols, -1), kWidth - 1 - 170, 1);
}

}  // namespace
}  // namespace armmimic
