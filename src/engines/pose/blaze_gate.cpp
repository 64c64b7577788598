#include "pose/blaze_gate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"

namespace armmimic::internal {

bool BoneLengthGate::Accept(double length_m) {
  bool ok = true;
  if (recent_.size() >= kMinSeen) {
    std::vector<double> v(recent_.begin(), recent_.end());
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    running_m_ = v[v.size() / 2];
    ok = std::abs(length_m / running_m_ - 1) <= kMaxJump;
  }
  // Every seen length joins the window: a bone that truly measures otherwise (a new person, a
  // first guess that was wrong) is accepted once it has held for half the window.
  recent_.push_back(length_m);
  if (recent_.size() > kWindow) recent_.pop_front();
  return ok;
}

void BlazeArmGate::Decide(const BlazeLandmarks& b, PoseSide side, ArmMeasurement* m) {
  const PoseKeypoints k = AsMoveNetKeypoints(b);
  m->pose_keypoints.assign(k.px.begin(), k.px.end());
  m->pose_scores.assign(k.score.begin(), k.score.end());
  const bool left = side == PoseSide::kLeft;
  const int s = left ? kBlazeLeftShoulder : kBlazeRightShoulder;
  const int e = left ? kBlazeLeftElbow : kBlazeRightElbow;
  const int w = left ? kBlazeLeftWrist : kBlazeRightWrist;
  const double visibility = std::min({b.visibility[s], b.visibility[e], b.visibility[w]});
  m->confidence = std::clamp(visibility, 0.0, 1.0);
  m->shoulder_px = b.px[s];
  m->elbow_px = b.px[e];
  m->wrist_px = b.px[w];
  m->arm_world_m = {b.world[s], b.world[e], b.world[w]};
  m->phase = MeasurementPhase::kLost;
  if (b.poseflag < kMinPoseFlag) {
    m->note = "no person in the crop (person flag " + FormatNumber(b.poseflag, 2) + ")";
    return;
  }
  const double presence = std::min({b.presence[s], b.presence[e], b.presence[w]});
  if (presence < o_.min_score) {
    m->note = "arm outside the crop (presence " + FormatNumber(presence, 2) + ")";
    return;
  }
  if (visibility < o_.min_score) {
    m->note = "arm not seen (visibility " + FormatNumber(visibility, 2) + ")";
    return;
  }
  const double upper_m = cv::norm(b.world[e] - b.world[s]);
  const double fore_m = cv::norm(b.world[w] - b.world[e]);
  const bool upper_ok = upper_.Accept(upper_m);
  const bool fore_ok = fore_.Accept(fore_m);
  if (!upper_ok || !fore_ok) {
    const BoneLengthGate& gate = upper_ok ? fore_ : upper_;
    m->note = std::string(upper_ok ? "forearm" : "upper arm") + " length jumped to " +
              FormatNumber(upper_ok ? fore_m : upper_m, 3) + " m from a running " +
              FormatNumber(gate.running_m(), 3) + " m";
    return;
  }
  m->phase = MeasurementPhase::kOk;
  m->upper_deg = DirectionDeg(b.px[s], b.px[e]);
  m->fore_deg = DirectionDeg(b.px[e], b.px[w]);
  m->bend_deg = Wrap180(m->fore_deg - m->upper_deg);
  m->upper_com_px = (b.px[s] + b.px[e]) * 0.5;
  m->fore_com_px = (b.px[e] + b.px[w]) * 0.5;
  m->bent = std::abs(m->bend_deg) > 20;
  AzimuthElevationDeg(b.world[s], b.world[e], &m->upper_az_deg, &m->upper_el_deg);
  AzimuthElevationDeg(b.world[e], b.world[w], &m->fore_az_deg, &m->fore_el_deg);
  m->elbow_deg = JointAngleDeg(b.world[s], b.world[e], b.world[w]);
}

}  // namespace armmimic::internal
