// Options of the hybrid engine (docs/hybrid.md): lk's model tracker carries the arm and bgsub's
// background difference is a second, independent measurement of every frame. The hybrid engine
// also takes every lk and bgsub option (EngineOptions::lk, ::bgsub); these are its own.
#pragma once

#include "armmimic/core/status.h"

namespace armmimic {

struct HybridOptions {
  // A frame is `ok` only when both measurements place each segment within this many degrees of
  // each other, plus the direction a joint's pixel uncertainty gives the segment.
  double max_disagreement_deg = 12;
  // The pixel uncertainty of a joint in each measurement (the direction term above:
  // atan(2 * joint_px / the segment's length)).
  double joint_px = 2;
  // The tracker restarts from the second opinion's joints once it has had no pose of its own
  // for restart_frames frames in a row (lost, or its calibration was refused) while the second
  // opinion has been `ok` for confirm_frames frames in a row, each within max_disagreement_deg
  // of the last. A tracker that tracks and disagrees with the background difference is not
  // restarted; one that disagrees with the pose network (no empty room) counts as lost.
  int restart_frames = 5;
  int confirm_frames = 5;
  Status Check() const;  // the table's ranges; errors carry "hybrid.KEY"
};

}  // namespace armmimic
