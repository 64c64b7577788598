// The arms a pose engine follows (PoseOptions::side): one, or with side both the person's left
// and right arm from the same inferences. Each arm keeps its own gate (its running segment
// lengths), so each arm's row is decided by the rules a run with that side alone applies.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "armmimic/engines/measurement.h"
#include "armmimic/engines/pose.h"
#include "armmimic/engines/pose_options.h"
#include "common/engine_internal.h"  // FollowedSides

namespace armmimic::internal {

// The lowest joint score of the arms of `sides` in `k` (ArmOf): the arm a crop must still hold.
double WeakestArmScore(const PoseKeypoints& k, const std::vector<PoseSide>& sides);

// One measurement per followed side, in FollowedSides' order, as the engine's one: the first,
// with the second as its right_arm.
ArmMeasurement JoinArms(std::vector<ArmMeasurement> arms);

// Each side's gate decides its arm's row from the frame's `inputs` (the looks; or the landmarks
// and MoveNet's looks); `frame` carries the frame's index, time and notes into every arm's
// measurement.
template <typename Gate, typename... Inputs>
ArmMeasurement DecideArms(std::vector<Gate>& gates, const std::vector<PoseSide>& sides,
                          const ArmMeasurement& frame, const Inputs&... inputs) {
  std::vector<ArmMeasurement> arms(sides.size(), frame);
  for (std::size_t i = 0; i < sides.size(); ++i) gates[i].Decide(inputs..., sides[i], &arms[i]);
  return JoinArms(std::move(arms));
}

}  // namespace armmimic::internal
