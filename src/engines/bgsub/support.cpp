#include "bgsub/support.h"

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "bgsub/fit.h"

namespace armmimic::bgsub {
namespace {

// How far out from rest_deg the standstill's arm is looked for when the line along it leaves the
// standstill's person (kMaxHangFromDownDeg of the standstill calibration allows more, but there
// the line is fitted to the arm's rows).
constexpr int kMaxOutwardLeanDeg = 20;

}  // namespace

void FitSupport::Begin(const ArmCalibration& cal, double upper_px, double rest_deg,
                       const cv::Rect& rect, const cv::Mat& standstill_person,
                       const cv::Mat& uncovered) {
  shoulder_ = cal.shoulder_px;
  tl_ = rect.tl();
  shape_ = arm::ArmShape();
  shape_.upper_px = upper_px;
  shape_.fore_px = cal.reach_px - upper_px;
  shape_.upper_hw = shape_.fore_hw = cal.half_width_px;
  // The standstill's arm along rest_deg; where that line leaves the standstill's person (a thin
  // arm hanging a few degrees out from the body), along the outward lean the person supports
  // best. Only outward: inward the line runs onto the torso, which would support any calibration.
  auto support_at = [&](double deg) {
    return arm::MeasureSupport(standstill_person, standstill_person, cv::Point(), Joints(deg, deg),
                               shape_);
  };
  double hang_deg = rest_deg;
  arm::PoseSupport rest_support = support_at(rest_deg);
  rule_.Calibrate(rest_support);
  if (!rule_.calibrated()) {
    for (int lean = 1; lean <= kMaxOutwardLeanDeg; ++lean) {
      const double deg = rest_deg + cal.side * lean;
      const arm::PoseSupport s = support_at(deg);
      if (s.weaker() > rest_support.weaker()) {
        rest_support = s;
        hang_deg = deg;
      }
    }
    rule_.Calibrate(rest_support);
  }
  const arm::ArmJoints rest = Joints(hang_deg, hang_deg);
  rest_region_ = cv::Mat::zeros(rect.size(), CV_8UC1);
  const cv::Point2d o(tl_);
  arm::DrawArm(rest_region_, {rest.shoulder - o, rest.elbow - o, rest.wrist - o}, shape_, 0);
  rest_mask_ = rest_region_.clone();
  // Only where the arm-length image, its arm raised, showed something else does an unchanged
  // pixel say the arm is still there.
  rest_mask_ &= uncovered(rect);
}

arm::ArmJoints FitSupport::Joints(double upper_deg, double fore_deg, double scale,
                                  double split) const {
  const SplitLengths lengths(shape_.upper_px, shape_.fore_px, split);
  arm::ArmJoints j;
  j.shoulder = shoulder_;
  j.elbow = j.shoulder + DirectionVector(upper_deg) * (scale * lengths.upper);
  j.wrist = j.elbow + DirectionVector(fore_deg) * (scale * lengths.fore);
  return j;
}

std::string FitSupport::Check(const arm::ArmJoints& pose, const cv::Mat& person,
                              const cv::Mat& moved, const cv::Mat& not_uncovered) {
  // New arm: the person where the standstill was not, less what the hanging arm uncovered.
  cv::bitwise_not(not_uncovered, revealed_);
  revealed_ &= rest_region_;
  cv::bitwise_and(person, moved, new_arm_);
  new_arm_ &= ~revealed_;
  // Or the standstill's arm in place, unchanged.
  cv::bitwise_and(person, rest_mask_, shows_arm_);
  shows_arm_ &= ~moved;
  shows_arm_ |= new_arm_;
  return rule_.Verdict(arm::MeasureSupport(shows_arm_, new_arm_, tl_, pose, shape_), true);
}

}  // namespace armmimic::bgsub
