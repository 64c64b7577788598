// What either pose engine (MoveNet's, BlazePose's) settles before and on its first frame: the
// part of the frame it looks at, and with --side auto the arm it follows.
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"
#include "armmimic/engines/engine.h"
#include "armmimic/engines/pose.h"

namespace armmimic::internal {

// The whole frame, or the region of interest inside it; an error for a video with no frame size.
Status PoseArea(const EngineContext& context, cv::Rect* area);

// With no side named: the arm better seen in `k` (its lowest joint score), and the estimate line
// that says so.
PoseSide BetterSeenSide(const PoseKeypoints& k, std::string* estimate);

}  // namespace armmimic::internal
