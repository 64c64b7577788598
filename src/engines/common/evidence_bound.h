// At most what the evidence map (arm_appearance.h) can be near a point: a bound on every bilinear
// sample within EvidenceBound::kReach pixels of it, far cheaper than the samples it bounds. The
// search over every pose (arm_wide_search.cpp) gives up, before taking any sample, a pose whose
// strip lies where the map is low. Qt-free.
#pragma once

#include <vector>

#include "common/arm_appearance.h"
#include "common/pair_sampler.h"

namespace armmimic::arm {

class EvidenceBound {
 public:
  static constexpr int kBlock = 8;
  // A sample within kReach of a point reads pixels at most kReach + 1 = kBlock away.
  static constexpr double kReach = kBlock - 1;

  // The map's largest value in each kBlock x kBlock block, then over each block's 3 x 3
  // neighbourhood, a little raised for the blend's rounding.
  explicit EvidenceBound(const EvidenceMap& evidence);

  // At least PairSampler(evidence).At(q) for every q within kReach of p on each axis; 0 where
  // every such sample lies off the map.
  float Near(pairs::Pair p) const {
    // The padded grid's column and row, counted from the padding: truncation is the floor on
    // the values that are not negative, and the others lie off it.
    const double gx = (pairs::X(p) - x0_) * (1.0 / kBlock) + 1;
    const double gy = (pairs::Y(p) - y0_) * (1.0 / kBlock) + 1;
    if (!(gx >= 0 && gx < nbx_ + 2 && gy >= 0 && gy < nby_ + 2)) return 0.f;
    return near_[static_cast<std::size_t>(static_cast<int>(gy) * (nbx_ + 2) +
                                          static_cast<int>(gx))];
  }

 private:
  double x0_ = 0, y0_ = 0;   // the map's region's corner, frame pixels
  int nbx_ = 0, nby_ = 0;    // blocks across and down the map
  std::vector<float> near_;  // (nby_ + 2) x (nbx_ + 2): padded by a block on every side
};

}  // namespace armmimic::arm
