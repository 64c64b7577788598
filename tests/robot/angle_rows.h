// A row of an angle file at frame `frame` of a `fps` video, for the robot layer's tests.
#pragma once

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"

namespace armmimic::test {

inline AngleRow MakeRow(int frame, double fps, double upper, double bend, double yaw, bool lost) {
  AngleRow r;
  r.frame = frame;
  r.time_s = frame / fps;
  r.status = lost ? RowStatus::kLost : RowStatus::kOk;
  if (!lost) {
    r.upper_deg = Wrap180(upper);
    r.bend_deg = Wrap180(bend);
    r.fore_deg = Wrap180(upper + bend);
    r.yaw_deg = yaw;
  }
  return r;
}

}  // namespace armmimic::test
