// The support rule (common/arm_support.h) on masks with a known arm: a pose on the arm's pixels is
// supported, one on empty pixels or in a region wider than the arm is not, a folded arm's own
// segments are no clutter, a held pose is never a measurement, and a calibration whose hanging arm
// is off the person checks nothing.
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "common/arm_support.h"

namespace armmimic::arm {
namespace {

ArmShape Shape() {
  ArmShape s;
  s.upper_px = 40;
  s.fore_px = 36;
  s.upper_hw = s.fore_hw = 5;
  return s;
}

ArmJoints Pose(double upper_deg, double fore_deg, const ArmShape& s = Shape()) {
  ArmJoints j;
  j.shoulder = {100, 60};
  j.elbow = j.shoulder + DirectionVector(upper_deg) * s.upper_px;
  j.wrist = j.elbow + DirectionVector(fore_deg) * s.fore_px;
  return j;
}

// A 200x200 mask with the arm of Shape() at these directions painted.
cv::Mat ArmMask(double upper_deg, double fore_deg) {
  cv::Mat m = cv::Mat::zeros(200, 200, CV_8UC1);
  DrawArm(m, Pose(upper_deg, fore_deg), Shape(), 0);
  return m;
}

SupportRule Calibrated() {
  SupportRule rule;
  const cv::Mat rest = ArmMask(-90, -90);
  rule.Calibrate(MeasureSupport(rest, rest, cv::Point(), Pose(-90, -90), Shape()));
  return rule;
}

TEST(ArmSupport, APoseOnTheArmsPixelsIsSupported) {
  const cv::Mat arm = ArmMask(-30, 20);
  const PoseSupport s = MeasureSupport(arm, arm, cv::Point(), Pose(-30, 20), Shape());
  EXPECT_GE(s.upper, 0.95);
  EXPECT_GE(s.fore, 0.95);
  EXPECT_LE(s.flank, 0.05);
  EXPECT_EQ(Calibrated().Verdict(s, true), "");
}

TEST(ArmSupport, APoseOnPixelsThatShowNoArmIsLost) {
  // The arm is raised; the pose hangs where the mask shows nothing (the empty room).
  const cv::Mat arm = ArmMask(60, 100);
  const PoseSupport s = MeasureSupport(arm, arm, cv::Point(), Pose(-90, -90), Shape());
  EXPECT_LE(s.weaker(), 0.1);
  const std::string why = Calibrated().Verdict(s, true);
  EXPECT_NE(why.find("show no arm"), std::string::npos) << why;
}

TEST(ArmSupport, AForearmFiftyDegreesOffKeepsTooLittleOfItsLength) {
  const cv::Mat arm = ArmMask(-90, -90);
  const PoseSupport s = MeasureSupport(arm, arm, cv::Point(), Pose(-90, -40), Shape());
  EXPECT_LT(s.fore, Calibrated().required());
  EXPECT_NE(Calibrated().Verdict(s, true), "");
}

TEST(ArmSupport, ASegmentInARegionWiderThanTheArmIsLost) {
  // A flooded patch (light, a shadow, a textured shirt swaying) around the whole arm.
  cv::Mat flooded = cv::Mat::zeros(200, 200, CV_8UC1);
  cv::rectangle(flooded, cv::Rect(40, 40, 130, 120), cv::Scalar(255), cv::FILLED);
  const PoseSupport s = MeasureSupport(flooded, flooded, cv::Point(), Pose(-30, 20), Shape());
  EXPECT_GE(s.weaker(), 0.95);
  EXPECT_GE(s.flank, 0.9);
  const std::string why = Calibrated().Verdict(s, true);
  EXPECT_NE(why.find("wider than the arm"), std::string::npos) << why;
}

TEST(ArmSupport, AFoldedArmsOwnSegmentsAreNoClutter) {
  // The forearm folded back up beside the upper arm: each covers one flank of the other.
  const cv::Mat arm = ArmMask(-90, 75);
  const PoseSupport s = MeasureSupport(arm, arm, cv::Point(), Pose(-90, 75), Shape());
  EXPECT_LE(s.flank, Calibrated().flank_limit());
  EXPECT_EQ(Calibrated().Verdict(s, true), "");
}

TEST(ArmSupport, AHeldPoseIsNeverAMeasurement) {
  const cv::Mat arm = ArmMask(-90, -90);
  const PoseSupport s = MeasureSupport(arm, arm, cv::Point(), Pose(-90, -90), Shape());
  const std::string why = Calibrated().Verdict(s, false);
  EXPECT_NE(why.find("held"), std::string::npos) << why;
}

TEST(ArmSupport, TheRequiredShareFollowsTheStandstillsOwnArm) {
  // The standstill's arm seen on 80 % of its samples: a segment needs 40 %; seen on less than
  // half, it is taken as seen on half (a quarter needed).
  SupportRule rule;
  PoseSupport rest;
  rest.upper = 0.8;
  rest.fore = 0.9;
  rule.Calibrate(rest);
  EXPECT_NEAR(rule.required(), 0.4, 1e-9);
  rest.upper = 0.3;
  rule.Calibrate(rest);
  EXPECT_NEAR(rule.required(), 0.25, 1e-9);
}

TEST(ArmSupport, ACalibrationWhoseHangingArmIsOffThePersonChecksNothing) {
  // The calibrated shoulder is far from the person: its hanging arm has no support at all.
  const cv::Mat person = ArmMask(-90, -90);
  ArmJoints off = Pose(-90, -90);
  for (cv::Point2d* p : {&off.shoulder, &off.elbow, &off.wrist}) p->x += 60;
  SupportRule rule;
  rule.Calibrate(MeasureSupport(person, person, cv::Point(), off, Shape()));
  EXPECT_FALSE(rule.calibrated());
  const PoseSupport s = MeasureSupport(person, person, cv::Point(), Pose(-90, -90), Shape());
  EXPECT_NE(rule.Verdict(s, true).find("calibration"), std::string::npos);
}

TEST(ArmSupport, TheMasksOriginPlacesThem) {
  // The same arm in a mask that starts at (50, 20): the pose keeps its image coordinates.
  const cv::Mat full = ArmMask(-30, 20);
  const cv::Mat part = full(cv::Rect(50, 20, 150, 180)).clone();
  const PoseSupport s = MeasureSupport(part, part, cv::Point(50, 20), Pose(-30, 20), Shape());
  EXPECT_GE(s.weaker(), 0.95);
}

TEST(ArmSupport, WithoutAMeasuredWidthTheFlanksAreNotJudged) {
  cv::Mat flooded(200, 200, CV_8UC1, cv::Scalar(255));
  const PoseSupport s = MeasureSupport(flooded, cv::Mat(), cv::Point(), Pose(-30, 20), Shape());
  EXPECT_EQ(s.flank, 0);
}

}  // namespace
}  // namespace armmimic::arm
