// The moving arm's pose over time: keyframes joined by minimum-jerk segments (smooth, zero
// velocity at each keyframe, like a person's reaching movements). Private to the synth layer.
// Poses are for an arm on the right of the image; the renderer mirrors them for the left side.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "armmimic/synth/arm_scene.h"

namespace armmimic::synth {

struct ArmPose {
  double upper_deg = -90;  // direction of the upper arm (hanging = -90)
  double bend_deg = 0;     // elbow flexion, forearm = upper + bend (counter-clockwise)
  double yaw_deg = 0;      // out of the image plane (straight arm only)
};

class ArmMotionPlan {
 public:
  // `valid(pose)` says whether a pose keeps the arm inside the frame and off the head.
  ArmMotionPlan(ArmMotion motion, int frames, uint64_t seed,
                const std::function<bool(const ArmPose&)>& valid);
  // Pose at motion frame `i` (0 = first frame after the standstill), hanging before.
  ArmPose At(int i) const;
  const std::vector<ArmPose>& keyframes() const { return keys_; }

 private:
  std::vector<ArmPose> keys_;
  std::vector<double> key_frame_;  // motion frame of each keyframe, increasing
};

}  // namespace armmimic::synth
