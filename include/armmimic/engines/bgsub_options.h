// Options of the background-subtraction engine (thesis chapter 5), with thesis defaults.
// thesis_mode=true runs the thesis path only; the improvements of docs/bgsub.md are the default.
#pragma once

#include "armmimic/core/status.h"

namespace armmimic {

struct BgsubOptions {
  // --- The thesis path (chapter 5) ---
  int threshold = 45;              // grey-level difference threshold (5.2.2, 5.2.4)
  int background_frames = 45;      // frames averaged into the background image (5.2.1)
  int standstill_frames = 60;      // frames averaged into the standstill image (5.2.2)
  double straight_ratio = 0.30;    // defect depth < 30 % of the semi-major axis: straight arm
  int closing_size = 5;            // morphological closing kernel (pixels; 0 or 1: none)
  int min_arm_area_px = 40;        // a smaller moving region is no arm (lost)
  double shoulder_height = 0.6;    // shoulder at 3/5 of the body box height, from its bottom
  double shoulder_side = 1.0 / 6;  // ... and 1/6 of its width in from the moving arm's side
  bool thesis_mode = false;        // true: the thesis path only, none of the improvements

  // --- Improvements (section 5.3 failures), used only when thesis_mode is false ---
  bool compensate_drift = true;   // subtract the global brightness drift before thresholding
  bool color_difference = true;   // threshold the largest channel difference, not the grey one
  bool reject_shadow = true;      // drop pixels that are the background darkened, hue kept
  bool reject_head = true;        // ignore movement above the shoulders between them
  double near_shoulder = 0.5;     // keep the blob nearest the shoulder, within this * arm length
  bool two_line_split = true;     // refine the upper/fore split by distance to the two segments
  bool extent_yaw = true;         // yaw from the arm's reach along its axis, not the ellipse
  double bend_hysteresis = 0.05;  // straight/bent switches at straight_ratio -/+ this
  bool shoulder_from_arm_length = true;  // shoulder where the horizontal arm meets the body
  bool rest_pose = true;                 // an unmoved arm is at its standstill pose, not lost
  double rest_deg = -90;                 // the standstill pose: arms hanging (thesis 5.2.2)
  double upper_arm_fraction = 0.45;      // upper arm / (shoulder-to-fingertip reach)
  bool upper_from_person = true;  // upper arm near rest: fit it in the person mask, torso removed

  // --- Honest status (arm_gate.h), used only when thesis_mode is false ---
  double max_speed_deg_s = 600;  // a segment turning faster than this is a wrong pick: lost
  double min_support = 0.5;      // share of the fitted arm lying on the person mask, at least
  int confirm_frames = 3;        // agreeing frames before a new pick is trusted

  Status Check() const;  // messages name the CLI flag where there is one
};

}  // namespace armmimic
