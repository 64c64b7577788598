#include "pose/arms.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace armmimic::internal {

std::vector<PoseSide> FollowedSides(PoseSide side) {
  if (side == PoseSide::kBoth) return {PoseSide::kLeft, PoseSide::kRight};
  return {side};
}

double WeakestArmScore(const PoseKeypoints& k, const std::vector<PoseSide>& sides) {
  double weakest = std::numeric_limits<double>::infinity();
  for (PoseSide side : sides) weakest = std::min(weakest, ArmOf(k, side).score);
  return weakest;
}

ArmMeasurement JoinArms(std::vector<ArmMeasurement> arms) {
  if (arms.empty() || arms.size() > 2) {
    throw std::logic_error("a pose engine follows one or two arms");
  }
  ArmMeasurement first = std::move(arms.front());
  if (arms.size() == 2) first.right_arm = std::make_shared<const ArmMeasurement>(arms.back());
  return first;
}

}  // namespace armmimic::internal
