// When a BlazePose row is lost (docs/pose.md, "BlazePose: when a row is lost"), and the arm's
// world landmarks smoothed over time as MediaPipe smooths them. A row is lost when the person flag
// is low, a joint of the arm is outside the crop or not visible, the shoulders are mirrored, a
// bone's 3-D length jumps far from its running value (the network has mistaken a joint), or
// MoveNet, the second opinion, does not bear the arm out. Otherwise the row carries the 2-D
// directions of MoveNet's looks and the 3-D ones of BlazePose's world landmarks.
#pragma once

#include <array>
#include <deque>

#include "armmimic/engines/measurement.h"
#include "armmimic/engines/pose_options.h"
#include "pose/blazepose.h"
#include "pose/looks.h"
#include "pose/one_euro.h"

namespace armmimic::internal {

// A bone's running length: the median of its last kWindow lengths; a length more than
// kMaxJump (a share) from it is a jump. The first kMinSeen lengths are taken as they come.
class BoneLengthGate {
 public:
  static constexpr std::size_t kWindow = 15;
  static constexpr std::size_t kMinSeen = 3;
  // The lengths of BlazePose's own reference wander by about 8 % over a clip; three times that
  // is no longer the same bone.
  static constexpr double kMaxJump = 0.25;
  // Adds `length_m` and says whether it stays within kMaxJump of the running value before it.
  bool Accept(double length_m);
  double running_m() const { return running_m_; }

 private:
  std::deque<double> recent_;
  double running_m_ = 0;
};

class BlazeArmGate {
 public:
  explicit BlazeArmGate(const PoseOptions& options) : o_(options) {}
  // Fills m from the landmarks of one frame for `side`'s arm (image pixels already in the full
  // frame): keypoints, joints and confidence always; then the angles (phase ok) or phase lost
  // with a note saying which rule decided. `movenet`: MoveNet's looks at the same frame, in the
  // same pixels (pose/second_opinion.h); `frame`: the whole frame's size.
  void Decide(const BlazeLandmarks& b, const PoseLooks& movenet, const cv::Size& frame,
              PoseSide side, ArmMeasurement* m);

 private:
  // The arm's world landmarks smoothed over time (MediaPipe's filter: see blaze_gate.cpp).
  std::array<cv::Vec3d, 3> Smooth(double time_s, const std::array<cv::Vec3d, 3>& joints);

  PoseOptions o_;
  std::vector<OneEuroFilter> world_filters_;
  BoneLengthGate upper_;
  BoneLengthGate fore_;
};

}  // namespace armmimic::internal
