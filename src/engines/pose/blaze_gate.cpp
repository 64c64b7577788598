#include "pose/blaze_gate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "pose/gate.h"
#include "pose/second_opinion.h"

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

// MediaPipe's filter of the world landmarks (its pose landmark filtering): a cut-off of 0.1 Hz for
// a still joint that rises by 40 Hz per metre per second of speed, and the speed itself
// filtered at 1 Hz. MediaPipe's own world landmarks, which the real-clip check compares with,
// are filtered so.
std::array<cv::Vec3d, 3> BlazeArmGate::Smooth(double time_s,
                                              const std::array<cv::Vec3d, 3>& joints) {
  if (world_filters_.empty()) world_filters_.assign(9, OneEuroFilter(0.1, 40, 1));
  std::array<cv::Vec3d, 3> out;
  for (int j = 0; j < 3; ++j) {
    for (int c = 0; c < 3; ++c) out[j][c] = world_filters_[3 * j + c].Apply(time_s, joints[j][c]);
  }
  return out;
}

void BlazeArmGate::Decide(const BlazeLandmarks& b, const PoseLooks& movenet, const cv::Size& frame,
                          PoseSide side, ArmMeasurement* m) {
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
  std::array<cv::Vec3d, 3> world = {b.world[s], b.world[e], b.world[w]};
  if (b.poseflag >= kMinPoseFlag) world = Smooth(m->time_s, world);
  m->arm_world_m = {world[0], world[1], world[2]};
  m->phase = MeasurementPhase::kLost;
  if (b.poseflag < kMinPoseFlag) {
    // The person is placed afresh: nothing of the lost track is carried over.
    for (OneEuroFilter& f : world_filters_) f.Reset();
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
  if (Mirrored(k, o_.min_score)) {
    m->note = "the shoulders are mirrored: the person faces away, or the network swapped the arms";
    return;
  }
  const double upper_m = cv::norm(world[1] - world[0]);
  const double fore_m = cv::norm(world[2] - world[1]);
  const bool upper_ok = upper_.Accept(upper_m);
  const bool fore_ok = fore_.Accept(fore_m);
  if (!upper_ok || !fore_ok) {
    const BoneLengthGate& gate = upper_ok ? fore_ : upper_;
    m->note = std::string(upper_ok ? "forearm" : "upper arm") + " length jumped to " +
              FormatNumber(upper_ok ? fore_m : upper_m, 3) + " m from a running " +
              FormatNumber(gate.running_m(), 3) + " m";
    return;
  }
  const std::string doubt = SecondOpinion(movenet, k, world, frame, side, o_);
  if (!doubt.empty()) {
    m->note = doubt;
    return;
  }
  m->phase = MeasurementPhase::kOk;
  // The 2-D columns, and the joints drawn, are MoveNet's: its closer looks place the joints at
  // about twice BlazePose's resolution in the image. The 3-D columns are BlazePose's. The two
  // agree within max_network_disagreement_deg (SecondOpinion).
  SetArmDirections(ArmOf(movenet.Combined(), side), m);
  AzimuthElevationDeg(world[0], world[1], &m->upper_az_deg, &m->upper_el_deg);
  AzimuthElevationDeg(world[1], world[2], &m->fore_az_deg, &m->fore_el_deg);
  m->elbow_deg = JointAngleDeg(world[0], world[1], world[2]);
}

}  // namespace armmimic::internal
