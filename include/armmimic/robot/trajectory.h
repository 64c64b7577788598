// Trajectory: the planner's output, a list of timed joint keyframes for the PUMA's six joints.
#pragma once

#include <vector>

#include "armmimic/robot/limits.h"

namespace armmimic::robot {

struct Keyframe {
  double time_s = 0;       // when the robot should reach the target, from the first keyframe
  JointArray joint_deg{};  // J1..J6 targets
  int frame = -1;          // the angle file's frame this keyframe came from (-1: none)
};

struct Trajectory {
  std::vector<Keyframe> keyframes;
  double duration_s() const { return keyframes.empty() ? 0 : keyframes.back().time_s; }
};

}  // namespace armmimic::robot
