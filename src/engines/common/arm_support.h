// The support rule of the arm engines: an `ok` pose lies on pixels that show an arm now. Along
// each segment of the pose, the share of samples on such pixels (the engine says which: pixels
// that differ from the empty room and from the standstill, pixels of the standstill's own arm
// still in place, pixels in the arm's learnt colour) must reach half the share the standstill's
// own arm had on its own pixels (the same engine's cue, measured on the arm it is sure of). A pose
// on pixels that look like the empty room, or like the unchanged scene, is `lost`. So is a pose
// no pixel of this frame measured (a tracker's held or predicted pose), and a pose whose segment
// has arm pixels on both flanks (it lies in a region wider than the arm, in which it could turn
// by more than the error it may have). Shared by the arm engines (bgsub, lk). Qt-free.
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "common/arm_appearance.h"

namespace armmimic::arm {

// The shares of a pose's samples on pixels that show an arm, per segment (0..1), and of its
// flanks: two lines each side beside the segment, outside its width, over its middle part (less
// what lies on the pose's other segment: a folded arm). A segment's flank share is that of its
// clearer side; `flank` is the worse segment's.
struct PoseSupport {
  double upper = 0, fore = 0;
  int upper_samples = 0, fore_samples = 0;
  double flank = 0;
  double weaker() const { return upper < fore ? upper : fore; }
};

// Samples each segment of `pose` (the upper arm from one half-width past the shoulder, the
// forearm to the wrist) along its axis and on lines at half its half-width either side, and
// counts those where `shows_arm` (CV_8U, nonzero: an arm now) is set; the flanks are counted on
// `flank_mask` (the same size; e.g. only new evidence, as beside an arm at rest lies the
// standstill's own arm or body; empty: the arm's width is not measured, and the flanks are not
// judged). `origin` is the masks' top-left pixel in the pose's
// coordinates; samples outside the mask count as not set.
PoseSupport MeasureSupport(const cv::Mat& shows_arm, const cv::Mat& flank_mask,
                           const cv::Point& origin, const ArmJoints& pose, const ArmShape& shape);

class SupportRule {
 public:
  // The standstill's own arm: its support on the engine's cue. Without a calibration, or when the
  // standstill's arm fails the rule it sets (a segment of it off the person: the calibration does
  // not match the standstill), the rule keeps nothing `ok`.
  void Calibrate(const PoseSupport& rest);
  bool calibrated() const { return required_ > 0; }
  // The share each segment needs: half the standstill arm's weaker share.
  double required() const { return required_; }
  // The flank share over which a segment lies in a region wider than an arm (its direction is
  // not pinned by the pixels): halfway from the room's (none) to the share a segment needs.
  double flank_limit() const { return 0.5 * required_; }
  // Empty when the pose is supported; otherwise why it is `lost`. `fresh` is false for a pose
  // that this frame's pixels did not measure (held or predicted from earlier frames).
  std::string Verdict(const PoseSupport& now, bool fresh) const;

 private:
  double required_ = 0;
  double rest_share_ = 0;
};

}  // namespace armmimic::arm
