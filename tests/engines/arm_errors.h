// The arm engines' tests score an `ok` row against the scene's truth the same way: each
// segment's wrapped direction error, their mean, and whether the row is confidently wrong (its
// worse segment more than 15 degrees off, as docs/accuracy.md and scripts/protocol-eval.sh
// count it).
#pragma once

#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "armmimic/engines/measurement.h"
#include "armmimic/synth/arm_scene_source.h"

namespace armmimic::test {

struct SegmentErrors {
  double upper = 0, fore = 0;  // degrees
  double mean() const { return 0.5 * (upper + fore); }
  bool wrong() const { return std::max(upper, fore) > 15; }
};

inline SegmentErrors ErrorsAgainst(const ArmMeasurement& m, const synth::ArmTruth& truth) {
  return {std::fabs(AngleDiff(m.upper_deg, truth.upper_deg)),
          std::fabs(AngleDiff(m.fore_deg, truth.fore_deg))};
}

}  // namespace armmimic::test
