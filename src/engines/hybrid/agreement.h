// When lk's and bgsub's rows of one frame bear each other out (docs/hybrid.md, "The second
// opinion"). lk follows the arm from frame to frame (flow and a learnt appearance); bgsub
// measures it afresh in every frame from where the frame differs from the empty room. The two
// err for different reasons, so a pose both place alike is one the pixels show now, and one
// they place apart is not trusted.
#pragma once

#include <string>

#include "armmimic/engines/hybrid_options.h"
#include "armmimic/engines/measurement.h"

namespace armmimic::internal {

// The largest direction difference allowed for a segment `length_px` long: max_disagreement_deg
// plus the angle a joint's pixel uncertainty in each measurement can turn it by,
// atan(2 * joint_px / length) (a short segment's direction is uncertain).
double AllowedDisagreementDeg(double length_px, const HybridOptions& options);

// Empty when the two ok rows agree: each segment's directions (upper_deg, fore_deg) within
// AllowedDisagreementDeg of the segment's length in lk's row (its joints), or the fixed bound
// where lk's row has no joints. Otherwise why not, for the row's note.
// `opinion` names the second measurement in the reason.
std::string Disagreement(const ArmMeasurement& lk, const ArmMeasurement& bgsub,
                         const HybridOptions& options,
                         const std::string& opinion = "the background difference");

// Disagreement for a pose lk withheld because a rival at least `rival_apart_deg` from it
// explains its own evidence about as well (lk/tracker.h, TrackerPose::undecided): bgsub decides
// for it only when it places each segment nearer to it than to any such rival, within half that
// distance, besides the usual bound.
std::string DisagreementWithRival(const ArmMeasurement& lk, const ArmMeasurement& bgsub,
                                  const HybridOptions& options, double rival_apart_deg,
                                  const std::string& opinion = "the background difference");

}  // namespace armmimic::internal
