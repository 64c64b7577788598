// MoveNet's looks as the second opinion on BlazePose's arm (pose/second_opinion.h), from
// hand-made keypoints (no network): an arm both place alike is borne out; a forearm turned 40
// degrees, the other arm, or an arm MoveNet does not see are not; a segment foreshortened
// towards the camera is compared by where its joints are; BlazePose's 3-D direction must turn the
// same way as the image segment, unless it points at the camera or a camera's perspective turns
// it so.
#include "pose/second_opinion.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

#include "hand_made_person.h"

namespace armmimic::internal {
namespace {

PoseLooks Looks(const PoseKeypoints& k) {
  PoseLooks looks;
  looks.body = k;
  looks.closer = {k};
  return looks;
}

// The world joints of Person()'s left arm (0.3 m segments) with the image's axes: the upper arm
// hangs (y down), the forearm points at `fore_deg` in the image plane, turned `toward_camera_deg`
// out of it (towards the camera: -z).
std::array<cv::Vec3d, 3> World(double fore_deg, double toward_camera_deg = 0) {
  const double a = fore_deg * M_PI / 180, t = toward_camera_deg * M_PI / 180;
  const cv::Vec3d shoulder(0.2, -0.5, 0), elbow = shoulder + cv::Vec3d(0, 0.3, 0);
  const cv::Vec3d fore(std::cos(t) * std::cos(a), -std::cos(t) * std::sin(a), -std::sin(t));
  return {shoulder, elbow, elbow + 0.3 * fore};
}

std::string Opinion(const PoseKeypoints& movenet, const PoseKeypoints& blaze,
                    const std::array<cv::Vec3d, 3>& world, cv::Size frame = cv::Size(400, 300)) {
  return SecondOpinion(Looks(movenet), blaze, world, frame, PoseSide::kLeft, PoseOptions());
}

TEST(SecondOpinionTest, AnArmBothNetworksPlaceAlikeIsBorneOut) {
  EXPECT_EQ(Opinion(Person(-45), TurnForearm(Person(-45), 10), World(-40)), "");
}

TEST(SecondOpinionTest, AForearmTurnedFortyDegreesIsNot) {
  const std::string why = Opinion(Person(-45), TurnForearm(Person(-45), 40), World(-5));
  EXPECT_NE(why.find("forearm"), std::string::npos) << why;
}

TEST(SecondOpinionTest, TheOtherArmInTheSamePoseIsNot) {
  // BlazePose's left arm drawn where MoveNet sees the right one: the same shape, 65 px away.
  PoseKeypoints blaze = Person(-90);
  const cv::Point2d shift = blaze.px[kRightShoulder] - blaze.px[kLeftShoulder];
  for (int j : {kLeftShoulder, kLeftElbow, kLeftWrist}) blaze.px[j] += shift;
  const std::string why = Opinion(Person(-90), blaze, World(-90));
  EXPECT_NE(why.find("shoulder"), std::string::npos) << why;
}

TEST(SecondOpinionTest, AnArmMoveNetDoesNotSeeIsNot) {
  PoseKeypoints movenet = Person(-45);
  movenet.score[kLeftWrist] = 0.1;
  const std::string why = Opinion(movenet, Person(-45), World(-45));
  EXPECT_NE(why.find("does not see"), std::string::npos) << why;
}

TEST(SecondOpinionTest, AForeshortenedForearmIsComparedByItsJointsPlaces) {
  // The forearm points nearly at the camera: 8 px long in the image, where each network gives
  // it another direction (90 degrees apart). Its wrist is within a few pixels in both.
  PoseKeypoints movenet = Person(-45), blaze = Person(-45);
  movenet.px[kLeftWrist] = movenet.px[kLeftElbow] + cv::Point2d(8, 0);
  blaze.px[kLeftWrist] = blaze.px[kLeftElbow] + cv::Point2d(0, 8);
  EXPECT_EQ(Opinion(movenet, blaze, World(0, 85)), "");
}

TEST(SecondOpinionTest, A3dDirectionThatTurnsAnotherWayInTheImageIsNot) {
  // Both networks' image landmarks agree on a forearm at -45; BlazePose's world landmarks point
  // it at +20 in the image plane.
  const std::string why = Opinion(Person(-45), Person(-45), World(20));
  EXPECT_NE(why.find("3-D"), std::string::npos) << why;
  // Turned 80 degrees towards the camera, that in-plane direction is a small part of it.
  EXPECT_EQ(Opinion(Person(-45), Person(-45), World(20, 80)), "");
}

TEST(SecondOpinionTest, PerspectiveTurnsASegmentThatReachesTowardsTheCameraOffTheAxis) {
  // The forearm points right and 70 degrees towards the camera. Its elbow is 570 px left of the
  // centre of a 1600 px wide frame; through a camera with a 60 degree field of view across it,
  // the forearm's short image segment points left. BlazePose's world frame has no perspective,
  // so its in-plane direction (right) is 180 degrees from the image's, and that is no
  // disagreement.
  const std::string off_axis = Opinion(Person(180), Person(180), World(0, 70), cv::Size(1600, 300));
  EXPECT_EQ(off_axis, "");
  // With the elbow on the optical axis no camera turns it: the same two disagree.
  const std::string on_axis = Opinion(Person(180), Person(180), World(0, 70), cv::Size(460, 320));
  EXPECT_NE(on_axis.find("forearm's 3-D direction"), std::string::npos) << on_axis;
}

}  // namespace
}  // namespace armmimic::internal
