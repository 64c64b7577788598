// BlazePose's crop (MediaPipe's convention), its first placement from MoveNet's keypoints, the
// landmarks in MoveNet's order, and the bone-length gate. None of these needs the model.
#include <gtest/gtest.h>

#include <cmath>

#include "pose/blaze_gate.h"
#include "pose/blazepose.h"

namespace armmimic::internal {
namespace {

void ExpectNear(const cv::Point2d& a, const cv::Point2d& b, double tol = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
}

TEST(BlazeCropTest, AnUprightBodyGivesAnUnturnedCropTwoAndAHalfRadiiWide) {
  const BlazeCrop crop = CropFromAuxiliary({300, 400}, {300, 300});
  ExpectNear(crop.centre, {300, 400});
  EXPECT_DOUBLE_EQ(crop.size, 250);
  EXPECT_NEAR(crop.rotation, 0, 1e-12);
  ExpectNear(CropToImage(crop, 0, 0), {175, 275});
  ExpectNear(CropToImage(crop, 1, 1), {425, 525});
  ExpectNear(CropToImage(crop, 0.5, 0.5), {300, 400});
}

TEST(BlazeCropTest, ABodyLeaningRightTurnsTheCropsUpTowardsTheImagesRight) {
  // The top 100 px to the right of the centre: the body lies along +x.
  const BlazeCrop crop = CropFromAuxiliary({300, 400}, {400, 400});
  EXPECT_NEAR(crop.rotation, M_PI / 2, 1e-12);
  // The crop's top middle (u 0.5, v 0) lies towards the top landmark, 125 px away.
  ExpectNear(CropToImage(crop, 0.5, 0), {425, 400});
  // Its right middle (u 1, v 0.5) lies below the centre in the image.
  ExpectNear(CropToImage(crop, 1, 0.5), {300, 525});
}

TEST(BlazeCropTest, AnUpsideDownBodyTurnsTheCropHalfWayRound) {
  const BlazeCrop crop = CropFromAuxiliary({300, 400}, {300, 500});
  EXPECT_NEAR(std::abs(crop.rotation), M_PI, 1e-12);
  ExpectNear(CropToImage(crop, 0.5, 0), {300, 525});
}

PoseKeypoints StandingPerson() {
  PoseKeypoints k;
  for (double& s : k.score) s = 0.9;
  for (cv::Point2d& p : k.px) p = {200, 300};
  k.px[kLeftShoulder] = {230, 200};
  k.px[kRightShoulder] = {170, 200};
  k.px[kLeftHip] = {220, 300};
  k.px[kRightHip] = {180, 300};
  k.px[kNose] = {200, 150};
  k.px[kLeftAnkle] = {220, 480};  // the farthest keypoint: 180 px from the hips' centre
  return k;
}

TEST(BlazeCropTest, TheFirstCropFromMoveNetHoldsEveryKeypointAroundTheHips) {
  BlazeCrop crop;
  ASSERT_TRUE(CropFromMoveNet(StandingPerson(), 0.3, &crop));
  ExpectNear(crop.centre, {200, 300});
  EXPECT_NEAR(crop.rotation, 0, 1e-12);
  // The radius: 1.1 times the ankle's 180.5 px; the crop 2.5 radii.
  EXPECT_NEAR(crop.size, 2.5 * 1.1 * std::hypot(20, 180), 1e-9);
}

TEST(BlazeCropTest, NoFirstCropWithoutTheHipsAndShoulders) {
  PoseKeypoints k = StandingPerson();
  k.score[kRightHip] = 0.1;
  BlazeCrop crop;
  EXPECT_FALSE(CropFromMoveNet(k, 0.3, &crop));
}

TEST(BlazeCropTest, TheLandmarksInMoveNetsOrderKeepTheirSides) {
  BlazeLandmarks b;
  for (int i = 0; i < kBlazeLandmarkCount; ++i) {
    b.px[i] = {static_cast<double>(i), 0};
    b.visibility[i] = i / 100.0;
  }
  const PoseKeypoints k = AsMoveNetKeypoints(b);
  EXPECT_EQ(k.px[kLeftShoulder].x, kBlazeLeftShoulder);
  EXPECT_EQ(k.px[kRightWrist].x, kBlazeRightWrist);
  EXPECT_EQ(k.px[kRightAnkle].x, kBlazeRightAnkle);
  EXPECT_DOUBLE_EQ(k.score[kLeftElbow], kBlazeLeftElbow / 100.0);
}

TEST(BoneLengthGateTest, ALengthFarFromTheRunningValueIsAJump) {
  BoneLengthGate gate;
  for (double m : {0.25, 0.26, 0.24, 0.25}) EXPECT_TRUE(gate.Accept(m));
  EXPECT_TRUE(gate.Accept(0.30));   // 20 % over the running 0.25 m: the bone wanders
  EXPECT_FALSE(gate.Accept(0.34));  // 36 % over: another bone
  EXPECT_FALSE(gate.Accept(0.17));
  EXPECT_DOUBLE_EQ(gate.running_m(), 0.26);  // the median of the six before it
}

TEST(BoneLengthGateTest, ALengthThatHoldsBecomesTheRunningValue) {
  BoneLengthGate gate;
  for (int i = 0; i < 5; ++i) gate.Accept(0.25);
  int accepted_at = -1;
  for (int i = 0; i < 15 && accepted_at < 0; ++i) {
    if (gate.Accept(0.40)) accepted_at = i;
  }
  EXPECT_EQ(accepted_at, 5);  // once 0.40 is the window's median
}

}  // namespace
}  // namespace armmimic::internal
