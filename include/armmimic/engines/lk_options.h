// Options of the Lucas-Kanade tracking engine (thesis chapter 6), with thesis defaults.
#pragma once

#include "armmimic/core/status.h"

namespace armmimic {

struct LkOptions {
  int standstill_frames = 60;      // used only to locate the shoulder (6.1)
  double initial_upper_deg = -90;  // known starting directions (the hanging arm)
  double initial_fore_deg = -90;
  int still_frames_drop = 10;      // a feature still for more than this many frames is dropped
  bool thesis_mode = false;        // true: integrate increments only, as in the thesis
  Status Check() const;
};

}  // namespace armmimic
