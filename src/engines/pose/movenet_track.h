// MoveNet's looks at one frame, as the pose engine takes them (docs/pose.md, "Crop tracking" and
// "Two looks"): the body look in a square around the previous frame's keypoints (MoveNet's demo
// tracking; the whole image on the first frame, after the person was lost, and again at once
// when the arm's scores drop inside the crop), then the closer looks (pose/looks.h).
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/engines/pose.h"
#include "armmimic/engines/pose_options.h"
#include "pose/looks.h"

namespace armmimic::internal {

class MoveNetTracker {
 public:
  // `net` is not owned and outlives the tracker.
  MoveNetTracker(PoseNetwork* net, const PoseOptions& options) : net_(net), o_(options) {}
  // The body look, in `image`'s pixels. A crop in which an arm of `sides` dropped below
  // min_score is searched again whole; with a side still kAuto (the first frame, always seen
  // whole) the caller picks it from the keypoints returned.
  PoseKeypoints BodyLook(const cv::Mat& image, const std::vector<PoseSide>& sides);
  // The looks at `image` for the arms of `sides`, after BodyLook on the same image; positions in
  // `image`'s pixels.
  PoseLooks Looks(const cv::Mat& image, const std::vector<PoseSide>& sides);
  // Forgets the track: the next frame is seen whole.
  void Reset() { tracking_ = false; }

 private:
  PoseNetwork* net_;
  PoseOptions o_;
  bool tracking_ = false;
  PoseCrop crop_;
  PoseCrop used_;
  PoseKeypoints body_;
};

}  // namespace armmimic::internal
