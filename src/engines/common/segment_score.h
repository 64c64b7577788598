// How well one strip of the arm model explains the evidence map: shared by the model's scoring
// (arm_model_fit.h) and the strip sampling under it (arm_strip.h). Qt-free.
#pragma once

namespace armmimic::arm {

struct SegmentScore {
  double inside = 0;  // mean evidence in the strip, 0..1
  double score = 0;   // inside minus the flanks' mean, -1..1
};

}  // namespace armmimic::arm
