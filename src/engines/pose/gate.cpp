#include "pose/gate.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"

namespace armmimic::internal {

double TorsoPx(const PoseKeypoints& k, double min_score) {
  for (int j : {kLeftShoulder, kRightShoulder, kLeftHip, kRightHip}) {
    if (k.score[j] < min_score) return 0;
  }
  return cv::norm((k.px[kLeftShoulder] + k.px[kRightShoulder]) * 0.5 -
                  (k.px[kLeftHip] + k.px[kRightHip]) * 0.5);
}

bool Mirrored(const PoseKeypoints& k, double min_score) {
  return k.score[kLeftShoulder] >= min_score && k.score[kRightShoulder] >= min_score &&
         k.px[kLeftShoulder].x <= k.px[kRightShoulder].x;
}

double PoseLengthGate::P90(std::vector<double> v) {
  const auto k = static_cast<std::ptrdiff_t>((v.size() - 1) * 9 / 10);
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<std::size_t>(k)];
}

bool PoseLengthGate::Accept(double length_px, double torso_px, double min_ratio) {
  auto push = [](std::vector<double>& v, double x) {
    if (v.size() >= kWindow) v.erase(v.begin());
    v.push_back(x);
  };
  if (torso_px > 0) {
    push(relative_, length_px / torso_px);
    const double usual = std::max(P90(relative_), floor_ratio_);
    usual_px_ = usual * torso_px;
  } else {
    push(pixels_, length_px);
    usual_px_ = P90(pixels_);
  }
  return length_px >= min_ratio * usual_px_;
}

PoseArmGate::PoseArmGate(const PoseOptions& options)
    : o_(options), upper_(kUpperFloor), fore_(kForeFloor) {}

void PoseArmGate::Decide(const PoseLooks& looks, PoseSide side, ArmMeasurement* m) {
  const PoseKeypoints k = looks.Combined();
  m->pose_keypoints.assign(k.px.begin(), k.px.end());
  m->pose_scores.assign(k.score.begin(), k.score.end());
  const PoseArm arm = ArmOf(k, side);
  m->confidence = std::clamp(arm.score, 0.0, 1.0);
  m->shoulder_px = arm.shoulder;
  m->elbow_px = arm.elbow;
  m->wrist_px = arm.wrist;
  m->phase = MeasurementPhase::kLost;
  if (arm.score < o_.min_score) {
    m->note = "arm not seen (score " + FormatNumber(arm.score, 2) + ")";
    return;
  }
  if (Mirrored(k, o_.min_score)) {
    m->note = "the shoulders are mirrored: the person faces away, or the network swapped the arms";
    return;
  }
  const double torso = TorsoPx(k, o_.crop_score);
  const double upper = cv::norm(arm.elbow - arm.shoulder);
  const double fore = cv::norm(arm.wrist - arm.elbow);
  const bool upper_ok = upper_.Accept(upper, torso, o_.min_length_ratio);
  const bool fore_ok = fore_.Accept(fore, torso, o_.min_length_ratio);
  if (!upper_ok || !fore_ok) {
    const PoseLengthGate& gate = upper_ok ? fore_ : upper_;
    m->note = std::string(upper_ok ? "forearm" : "upper arm") + " points at the camera (" +
              FormatNumber(upper_ok ? fore : upper, 0) + " px of a usual " +
              FormatNumber(gate.usual_px(), 0) + ")";
    return;
  }
  const bool left = side == PoseSide::kLeft;
  const int s = left ? kLeftShoulder : kRightShoulder;
  const int e = left ? kLeftElbow : kRightElbow;
  const int w = left ? kLeftWrist : kRightWrist;
  const double upper_disagree = looks.DisagreementDeg(s, e);
  const double fore_disagree = looks.DisagreementDeg(e, w);
  if (std::max(upper_disagree, fore_disagree) > o_.max_disagreement_deg) {
    const bool is_upper = upper_disagree >= fore_disagree;
    m->note = std::string("the looks disagree on the ") + (is_upper ? "upper arm" : "forearm") +
              "'s direction by " + FormatNumber(is_upper ? upper_disagree : fore_disagree, 0) +
              " degrees";
    return;
  }
  m->phase = MeasurementPhase::kOk;
  SetArmDirections(arm, m);
}

void SetArmDirections(const PoseArm& arm, ArmMeasurement* m) {
  m->shoulder_px = arm.shoulder;
  m->elbow_px = arm.elbow;
  m->wrist_px = arm.wrist;
  m->upper_deg = DirectionDeg(arm.shoulder, arm.elbow);
  m->fore_deg = DirectionDeg(arm.elbow, arm.wrist);
  m->bend_deg = Wrap180(m->fore_deg - m->upper_deg);
  m->upper_com_px = (arm.shoulder + arm.elbow) * 0.5;
  m->fore_com_px = (arm.elbow + arm.wrist) * 0.5;
  m->bent = std::abs(m->bend_deg) > 20;
}

}  // namespace armmimic::internal
