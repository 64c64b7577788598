// Private: the signed yaw from the lower markers' angles on the cylinder (docs/marker.md,
// "Yaw").
#pragma once

#include <string>
#include <vector>

#include "marker/lower.h"

namespace armmimic::internal {

// A yaw the lower markers allow, with the markers it rests on (either may be null).
struct YawHypothesis {
  double yaw = 0;    // radians, signed, (-pi, pi]
  double sigma = 0;  // expected spread, radians
  const LowerMarker* left = nullptr;
  const LowerMarker* right = nullptr;
  // One marker read as this side: the other one would show, and the image has no dark patch
  // there.
  bool other_missing = false;
};

struct YawSolution {
  // None: the view is lost (`note` says why). One: the yaw from two markers. Two: a single
  // marker shows, read as the left and as the right one (other_missing says where the image
  // contradicts that); the upper marker must decide.
  std::vector<YawHypothesis> hypotheses;
  std::string note;
};

// `agreement_sigmas`: the two markers' yaws must agree within this many expected spreads
// (plus one degree). A view is read only when a marker it rests on faces the camera within
// `max_turn` (radians).
YawSolution SolveYaw(const LowerScan& scan, const LowerCalibration& cal, double agreement_sigmas,
                     double max_turn);

}  // namespace armmimic::internal
