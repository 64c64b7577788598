// The planner tests' scenes: an angle file drawn from a pose function at 30 fps (frames from
// 100), the default arm options, and the check of keyframes against the mapped truth. Shared by
// planner_test.cpp and planner_limits_test.cpp.
#pragma once

#include <functional>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "armmimic/robot/planner.h"

namespace armmimic::robot::planner_scene {

constexpr double kFps = 30;

struct Pose {
  double upper = -90, bend = 0, yaw = 0;
  bool lost = false;
};

inline AngleFile MakeFile(int n, const std::function<Pose(int, double)>& pose) {
  AngleFile f;
  f.meta = {{"engine", "bgsub"}, {"fps", "30"}};
  for (int i = 0; i < n; ++i) {
    const double t = i / kFps;
    const Pose p = pose(i, t);
    AngleRow r;
    r.frame = i + 100;
    r.time_s = t;
    r.status = p.lost ? RowStatus::kLost : RowStatus::kOk;
    if (!p.lost) {
      r.upper_deg = Wrap180(p.upper);
      r.bend_deg = Wrap180(p.bend);
      r.fore_deg = Wrap180(p.upper + p.bend);
      r.yaw_deg = p.yaw;
    }
    f.rows.push_back(r);
  }
  return f;
}

inline PlannerOptions Options() {
  PlannerOptions o;
  o.mapping = MappingOptions::Default(SourceKind::kArm);
  return o;
}

// The joints at the source frame of each keyframe must match the mapped truth within `tol`.
inline void ExpectKeyframesNearTruth(const Trajectory& tr, const MappingOptions& m,
                                     const std::function<Pose(int, double)>& truth, double tol) {
  for (const Keyframe& kf : tr.keyframes) {
    const int i = kf.frame - 100;
    const Pose p = truth(i, i / kFps);
    const JointArray q = m.Map(p.upper, p.bend, p.yaw);
    for (int j = 0; j < kJoints; ++j) {
      EXPECT_NEAR(kf.joint_deg[j], q[j], tol) << "frame " << kf.frame << " J" << j + 1;
    }
  }
}

}  // namespace armmimic::robot::planner_scene
