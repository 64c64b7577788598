// When a pose row is lost (pose/gate.cpp), from hand-made looks (no network): an unseen joint, a
// segment pointing at the camera, and looks (the arm look, the mirrored look) that disagree on a
// segment's direction; and what an ok row carries. Also the looks it is fed (pose/looks.cpp's
// PoseLooks) and the arm look's crop (pose/crop.cpp).
#include "pose/gate.h"

#include <gtest/gtest.h>

#include <utility>

#include "armmimic/core/angles.h"
#include "hand_made_person.h"

namespace armmimic::internal {
namespace {

ArmMeasurement Decide(PoseArmGate* gate, const PoseLooks& looks) {
  ArmMeasurement m;
  gate->Decide(looks, PoseSide::kLeft, &m);
  return m;
}

TEST(PoseGateTest, AgreeingLooksGiveTheArmsDirections) {
  PoseArmGate gate{PoseOptions()};
  PoseLooks looks;
  looks.body = TurnForearm(Person(), 6);  // the body look is coarser
  looks.closer = {TurnForearm(Person(), 2), TurnForearm(Person(), -2)};
  const ArmMeasurement m = Decide(&gate, looks);
  ASSERT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
  EXPECT_NEAR(m.upper_deg, -90, 1e-9);
  EXPECT_NEAR(m.fore_deg, -45, 1e-6);  // the closer looks' mean, not the body look
  EXPECT_NEAR(m.bend_deg, 45, 1e-6);
  EXPECT_DOUBLE_EQ(m.confidence, 0.9);
  ASSERT_EQ(m.pose_keypoints.size(), static_cast<std::size_t>(kPoseKeypointCount));
}

TEST(PoseGateTest, MirroredShouldersMakeTheRowLostUnlessOneIsUnseen) {
  // The named arm's joints put on the other side of the body: its shoulder on the image's left
  // of the other shoulder, as for a person facing away.
  PoseKeypoints k = Person();
  std::swap(k.px[kLeftShoulder], k.px[kRightShoulder]);
  std::swap(k.px[kLeftElbow], k.px[kRightElbow]);
  std::swap(k.px[kLeftWrist], k.px[kRightWrist]);
  PoseArmGate gate{PoseOptions()};
  PoseLooks looks;
  looks.body = k;
  ArmMeasurement m = Decide(&gate, looks);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost);
  EXPECT_EQ(m.note,
            "the shoulders are mirrored: the person faces away, or the network swapped the arms");
  // With the other shoulder unseen there is nothing to compare: the row is decided as before.
  looks.body.score[kRightShoulder] = 0.1;
  m = Decide(&gate, looks);
  EXPECT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
  // Shoulders the right way round (the facing person) stay ok.
  looks.body = Person();
  EXPECT_EQ(Decide(&gate, looks).phase, MeasurementPhase::kOk);
}

TEST(PoseGateTest, AMirroredLookThatDisagreesMakesTheRowLost) {
  PoseOptions o;
  PoseArmGate gate{o};
  PoseLooks looks;
  looks.body = Person();
  looks.closer = {Person(), TurnForearm(Person(), 20)};  // the mirrored look: 20 degrees apart
  ArmMeasurement m = Decide(&gate, looks);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost);
  EXPECT_EQ(m.note, "the looks disagree on the forearm's direction by 20 degrees");
  EXPECT_TRUE(std::isnan(m.fore_deg));
  o.max_disagreement_deg = 25;  // a bound past the disagreement keeps the row
  PoseArmGate lenient{o};
  m = Decide(&lenient, looks);
  EXPECT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
  EXPECT_NEAR(m.fore_deg, -35, 1e-6);  // the two closer looks averaged
}

TEST(PoseGateTest, ABodyLookThatDisagreesWithTheArmLookMakesTheRowLost) {
  PoseArmGate gate{PoseOptions()};
  PoseLooks looks;
  looks.body = Person();
  looks.body.px[kLeftElbow].x += 20;  // the upper arm about 18 degrees off
  looks.body.px[kLeftWrist].x += 20;
  looks.closer = {Person()};
  const ArmMeasurement m = Decide(&gate, looks);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost);
  EXPECT_EQ(m.note, "the looks disagree on the upper arm's direction by 18 degrees");
}

TEST(PoseGateTest, AnUnseenJointOrAForeshortenedSegmentIsLost) {
  PoseArmGate gate{PoseOptions()};
  PoseLooks looks;
  looks.body = Person();
  looks.body.score[kLeftWrist] = 0.3;
  ArmMeasurement m = Decide(&gate, looks);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost);
  EXPECT_EQ(m.note, "arm not seen (score 0.30)");
  EXPECT_DOUBLE_EQ(m.confidence, 0.3);
  looks.body = Person();
  for (int i = 0; i < 10; ++i) EXPECT_EQ(Decide(&gate, looks).phase, MeasurementPhase::kOk);
  // The forearm at a fifth of its usual length: it points at the camera.
  looks.body.px[kLeftWrist] = looks.body.px[kLeftElbow] + cv::Point2d(7, 7);
  m = Decide(&gate, looks);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost);
  EXPECT_EQ(m.note, "forearm points at the camera (10 px of a usual 50)");
}

TEST(PoseLooksTest, CombinedTakesTheCloserLooksPositionsAndTheBodyLooksScores) {
  PoseLooks looks;
  looks.body = Person();
  EXPECT_EQ(looks.Combined().px[kLeftWrist], looks.body.px[kLeftWrist]);
  PoseKeypoints a = Person(), b = Person();
  a.px[kLeftWrist] += cv::Point2d(4, 0);
  b.px[kLeftWrist] += cv::Point2d(0, 6);
  a.score.fill(0.1);
  looks.closer = {a, b};
  const PoseKeypoints k = looks.Combined();
  EXPECT_EQ(k.px[kLeftWrist], Person().px[kLeftWrist] + cv::Point2d(2, 3));
  EXPECT_DOUBLE_EQ(k.score[kLeftWrist], 0.9);
  looks.Shift({10, -5});
  EXPECT_EQ(looks.closer[1].px[kLeftWrist], b.px[kLeftWrist] + cv::Point2d(10, -5));
  EXPECT_EQ(looks.body.px[kNose], cv::Point2d(10, -5));
}

TEST(PoseLooksTest, DisagreementIsTheWidestGapBetweenAnyTwoLooks) {
  PoseLooks looks;
  looks.body = Person();
  EXPECT_DOUBLE_EQ(looks.DisagreementDeg(kLeftElbow, kLeftWrist), 0);
  looks.closer = {TurnForearm(Person(), 5), TurnForearm(Person(), -7)};
  EXPECT_NEAR(looks.DisagreementDeg(kLeftElbow, kLeftWrist), 12, 1e-6);
  EXPECT_NEAR(looks.DisagreementDeg(kLeftShoulder, kLeftElbow), 0, 1e-9);
  // Across the +-180 seam the gap is the short way round.
  looks.body = Person(179);
  looks.closer = {Person(-179)};
  EXPECT_NEAR(looks.DisagreementDeg(kLeftElbow, kLeftWrist), 2, 1e-6);
}

TEST(PoseCropTest, TheArmLookFramesTheUpperBodyWithAMargin) {
  const PoseKeypoints k = Person();
  PoseCrop crop;
  ASSERT_TRUE(ArmLookCrop(k, 1.5, 0.2, &crop));
  // Upper body: x 165..265 (the left wrist at 230 + 50 cos 45), y 100..210; 110 px tall.
  const double top = 100, bottom = 210;
  EXPECT_NEAR(crop.size, 1.5 * (bottom - top), 1e-9);
  EXPECT_NEAR(crop.y + crop.size / 2, (top + bottom) / 2, 1e-9);
  PoseKeypoints unseen = k;
  for (int j = kLeftShoulder; j <= kRightHip; ++j) unseen.score[j] = j < kLeftWrist ? 0.9 : 0.1;
  EXPECT_TRUE(ArmLookCrop(unseen, 1.5, 0.2, &crop));  // shoulders and elbows: four
  unseen.score[kLeftElbow] = 0.1;
  EXPECT_FALSE(ArmLookCrop(unseen, 1.5, 0.2, &crop));
}

}  // namespace
}  // namespace armmimic::internal
