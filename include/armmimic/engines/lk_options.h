// Options of the Lucas-Kanade tracking engine (thesis chapter 6), with thesis defaults.
// docs/lk.md maps every field to the thesis step it configures.
#pragma once

#include <string>

#include "armmimic/core/status.h"

namespace armmimic {

// Which side of the body box the moving arm is on (decides the shoulder at 1/6 or 5/6 width).
enum class LkArmSide { kAuto, kLeft, kRight };  // left/right as seen on screen

struct LkOptions {
  // --- setup (6.1): the background and the standstill only locate the shoulder ---
  int standstill_frames = 60;       // frames averaged into the standstill image
  int body_threshold = 45;          // grey-level difference standstill vs background (body box)
  double shoulder_height = 0.6;     // shoulder at 3/5 of the body box height, from its bottom
  double shoulder_inset = 1.0 / 6;  // and at 1/6 (or 5/6) of its width
  // The anchored path's body-box rule: the joint sits higher and nearer the box edge than the
  // thesis rule puts it (measured on the armmimic synthetic person; the sleeve lines then refine
  // it).
  double anchored_shoulder_height = 0.7;
  double anchored_shoulder_inset = 0.09;
  LkArmSide side = LkArmSide::kAuto;  // kAuto: the side where the first motion happens

  // --- known starting posture ---
  double initial_upper_deg = -90;  // known starting directions (the hanging arm)
  double initial_fore_deg = -90;

  // --- Shi-Tomasi corners (6.2.1): minimal eigenvalue, 3x3 non-maximum suppression ---
  int max_corners = 300;        // strongest corners kept per detection
  double quality_level = 0.01;  // a corner's eigenvalue >= quality * the strongest one
  double min_distance_px = 5;   // minimum distance between corners
  int block_size = 3;           // eigenvalue neighbourhood (3x3)

  // --- pyramidal iterative LK (6.2.2) ---
  int window_px = 15;       // LK search window (square)
  int pyramid_levels = 3;   // pyramid levels above the full image
  int max_iterations = 20;  // per level
  double epsilon = 0.03;    // stop when the update is smaller than this (pixels)

  // --- which features are the arm (6.2.3) ---
  double motion_threshold_px = 1.0;  // a feature that moved more than this is on the arm
  int still_frames_drop = 10;        // a feature still for more than this many frames is dropped

  // --- improvements over the thesis (6.4); ignored in thesis_mode ---
  bool thesis_mode = false;          // true: 2-means and summed increments only, as the thesis
  bool use_bar = true;               // anchor each part on its sleeve colour (lk/arm_bar.h)
  double bar_search_deg = 30;        // searched around the features' estimate
  double bar_min_score = 0.4;        // weaker bars (part in front of the body) are not used
  bool refine_shoulder = true;       // refine a body-box shoulder from the sleeve's lines
  double upper_fraction = 0.53;      // upper arm / (shoulder to wrist), the elbow prior
  double forward_backward_px = 1.0;  // drop a track whose backward track misses by more (0: off)
  double confirm_motion_px = 4.0;    // a feature joins the fit once the model moved it this far
  double outlier_px = 3.0;           // residual (pixels) above which a feature is an outlier
  int outlier_frames_drop = 3;       // consecutive outlier frames before a feature is dropped
  int reseed_interval = 5;           // frames between re-seeding corners on the arm
  int min_part_features = 12;        // re-seed at once when a part has fewer features
  double arm_width_ratio = 0.14;     // half-width of the arm band / arm length (re-seed mask)
  double joint_weight = 1.0;         // weight of the shoulder/elbow pseudo-feature in the fits
  double prior_weight = 2;  // the previous pose votes like this many features at a part's end
  double inlier_deg = 8;    // a feature whose implied direction is this far off is ignored
  double bend_for_elbow_deg = 20;  // the elbow is located only when bent this much
  double max_bend_deg = 150;       // the forearm's sleeve is not searched folded further back

  // --- honest status (arm_gate.h); ignored in thesis_mode ---
  double max_speed_deg_s = 600;  // a segment turning faster than this is a wrong lock: lost
  double min_support = 0.3;      // a pose backed by less sleeve/feature evidence is lost
  int confirm_frames = 3;        // agreeing frames before a new lock is trusted again
  // Model path (clicked joints): the torso's features move the shoulder at most this share of
  // the upper arm's length from where it was clicked (a body that sways); features that say more
  // follow something else (the sleeve's cap rising with the arm). 0 keeps it at the click.
  double shoulder_sway = 0.05;

  Status Check() const;  // the table's ranges and an odd window; errors carry "lk.KEY"
};

const char* LkArmSideName(LkArmSide side);  // "auto", "left", "right"
bool ParseLkArmSide(const std::string& name, LkArmSide* out);

}  // namespace armmimic
