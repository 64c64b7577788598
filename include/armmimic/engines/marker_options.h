// Options of the marker-joint engine (thesis chapter 4), with thesis defaults.
#pragma once

#include "armmimic/core/status.h"

namespace armmimic {

struct MarkerOptions {
  int median_size = 5;             // median filter window
  int low = 20;                    // two-level threshold: markers are in [low, high]
  int high = 80;
  int flood_range = 10;            // flood-fill value range (+/-)
  bool thesis_mode = false;        // true: the three largest survivors, no geometry check
  Status Check() const;
};

}  // namespace armmimic
