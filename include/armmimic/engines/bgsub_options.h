// Options of the background-subtraction engine (thesis chapter 5), with thesis defaults.
#pragma once

#include "armmimic/core/status.h"

namespace armmimic {

struct BgsubOptions {
  int threshold = 45;              // grey-level difference threshold (5.2.2, 5.2.4)
  int standstill_frames = 60;      // frames averaged into the standstill image (5.2.2)
  double straight_ratio = 0.30;    // defect depth < 30 % of the semi-major axis: straight arm
  int closing_size = 5;            // morphological closing kernel (pixels)
  bool thesis_mode = false;        // true: the thesis path only, none of the improvements
  Status Check() const;
};

}  // namespace armmimic
