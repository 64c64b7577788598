// When a pose row is lost (docs/pose.md, "When a row is lost"): never `ok` on a guess.
//  - PoseLengthGate: is a segment much shorter than its usual length over the clip (pointing at
//    the camera, so its 2-D direction means nothing)? Lengths are taken relative to the torso
//    (shoulders' centre to hips' centre) when the torso is seen, so walking towards or away from
//    the camera changes nothing; in pixels otherwise. The usual length is the 90th percentile of
//    the lengths seen so far (the last kWindow frames), never less than an anthropometric floor.
//  - PoseArmGate: one arm's row from a frame's looks: lost when a joint is not seen, the
//    shoulders are mirrored (the network's left is not the person's), a segment points at the
//    camera, or the looks disagree on a segment's direction.
#pragma once

#include <vector>

#include "armmimic/engines/measurement.h"
#include "armmimic/engines/pose_options.h"
#include "pose/looks.h"

namespace armmimic::internal {

// The smallest in-plane segment lengths, in torso lengths (anthropometric tables put the upper
// arm near 0.6 and the forearm near 0.5 of the shoulder-to-hip distance).
inline constexpr double kUpperFloor = 0.45;
inline constexpr double kForeFloor = 0.4;

// The distance from the shoulders' centre to the hips' centre in `k`, pixels; 0 when one of the
// four is scored below `min_score`.
double TorsoPx(const PoseKeypoints& k, double min_score);

// A person facing the camera, as the operator does, has their left shoulder on the image's right.
// Both shoulders seen the other way round say that the network's left and right are not the
// person's: they face away, or (on figures the network reads badly) it put the named arm's
// joints on the other arm. Either way the row would name the wrong arm.
bool Mirrored(const PoseKeypoints& k, double min_score);

// An ok row's joints and 2-D columns from `arm`.
void SetArmDirections(const PoseArm& arm, ArmMeasurement* m);

class PoseLengthGate {
 public:
  // floor_ratio: the segment's smallest plausible in-plane length in torso lengths.
  explicit PoseLengthGate(double floor_ratio) : floor_ratio_(floor_ratio) {}
  // Adds the segment's length for a frame where its joints were seen, and says whether it is at
  // least `min_ratio` of its usual length. torso_px <= 0: torso not seen.
  bool Accept(double length_px, double torso_px, double min_ratio);
  // The last usual length (px) the gate compared against, for notes.
  double usual_px() const { return usual_px_; }

 private:
  static constexpr std::size_t kWindow = 900;
  static double P90(std::vector<double> v);
  double floor_ratio_;
  std::vector<double> relative_;  // length / torso
  std::vector<double> pixels_;    // lengths where the torso was not seen
  double usual_px_ = 0;
};

class PoseArmGate {
 public:
  explicit PoseArmGate(const PoseOptions& options);
  // Fills m's keypoints, joints and confidence from `looks`, then either the arm's angles
  // (phase ok) or phase lost with a note saying which rule decided.
  void Decide(const PoseLooks& looks, PoseSide side, ArmMeasurement* m);

 private:
  PoseOptions o_;
  PoseLengthGate upper_;
  PoseLengthGate fore_;
};

}  // namespace armmimic::internal
