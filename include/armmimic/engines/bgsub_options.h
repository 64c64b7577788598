// Options of the background-subtraction engine (thesis chapter 5), with thesis defaults.
// thesis_mode=true runs the thesis path only; the default path of docs/bgsub.md (a per-pixel
// model and a two-segment fit) is the default. The switches of the blob path's former
// improvements are gone: removed_options.h says what took their place.
#pragma once

#include "armmimic/core/status.h"

namespace armmimic {

struct BgsubOptions {
  // --- The thesis path (chapter 5) ---
  int threshold = 45;              // grey-level difference threshold (5.2.2, 5.2.4)
  int standstill_frames = 60;      // frames averaged into the standstill image (5.2.2)
  double straight_ratio = 0.30;    // defect depth < 30 % of the semi-major axis: straight arm
  int closing_size = 5;            // morphological closing kernel (pixels; 0 or 1: none)
  int min_arm_area_px = 40;        // a smaller moving region is no arm (lost)
  double shoulder_height = 0.6;    // shoulder at 3/5 of the body box height, from its bottom
  double shoulder_side = 1.0 / 6;  // ... and 1/6 of its width in from the moving arm's side
  bool thesis_mode = false;        // true: the thesis path only, none of the improvements

  // --- The default path (docs/bgsub.md), used only when thesis_mode is false ---
  double rest_deg = -90;             // the standstill pose: arms hanging (thesis 5.2.2)
  double upper_arm_fraction = 0.45;  // upper arm / (shoulder-to-fingertip reach)
  int max_bend_deg = 150;            // forearms searched within this of the upper arm's direction

  // --- Honest status (arm_gate.h), used only when thesis_mode is false ---
  double max_speed_deg_s = 600;  // a segment turning faster than this is a wrong pick: lost
  double min_support = 0.5;      // share of the fitted arm lying on the person mask, at least
  int confirm_frames = 3;        // agreeing frames before a new pick is trusted

  Status Check() const;  // the table's ranges (option_fields.h); errors carry "bgsub.KEY"
};

}  // namespace armmimic
