// The looks the pose engine takes at one frame (docs/pose.md, "Two looks"):
//  - the body look: MoveNet's crop tracking, a square around the whole person;
//  - the arm look: a square around the upper body (PoseOptions::arm_crop times its extent),
//    where the arm fills about twice as much of the network's 192x192 input, so its joints are
//    placed about twice as finely in image pixels;
//  - with PoseOptions::flip, the mirror image of the closer look's crop.
// The body look's scores say whether a joint is seen: its crop is the one MoveNet's own tracking
// makes. The closer looks' positions, averaged, give the directions. How far the looks disagree
// on a segment's direction is the frame's own measure of how sure the network is.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/engines/pose.h"

namespace armmimic::internal {

struct PoseLooks {
  PoseKeypoints body;                 // decides what is seen (its scores)
  std::vector<PoseKeypoints> closer;  // the arm look and the mirrored look, when taken

  // Positions: the closer looks' mean (the body look's without them); scores: the body look's.
  PoseKeypoints Combined() const;
  // The largest difference between two looks' directions of the segment from -> to, degrees
  // (0 with one look).
  double DisagreementDeg(int from, int to) const;
  void Shift(const cv::Point2d& offset);
};

// Takes the closer looks at `image` after the body look `body`, seen through `body_crop`; none
// when the body look sees none of the arms of `sides` (their rows are lost whatever the looks
// would show). The arm look's square holds the whole upper body, so it serves both arms.
PoseLooks TakeLooks(PoseNetwork* net, const cv::Mat& image, const PoseKeypoints& body,
                    const PoseCrop& body_crop, const std::vector<PoseSide>& sides,
                    const PoseOptions& options);

}  // namespace armmimic::internal
