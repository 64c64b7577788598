// PoseLengthGate: is a segment much shorter than its usual length over the clip (pointing at
// the camera, so its 2-D direction means nothing)? Lengths are taken relative to the torso
// (shoulders' centre to hips' centre) when the torso is seen, so walking towards or away from
// the camera changes nothing; in pixels otherwise. The usual length is the 90th percentile of the
// lengths seen so far (the last kWindow frames), never less than the anthropometric floor (an
// upper arm is about 0.55 torso lengths, a forearm about 0.45).
#pragma once

#include <vector>

namespace armmimic::internal {

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

}  // namespace armmimic::internal
