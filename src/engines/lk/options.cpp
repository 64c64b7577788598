#include <cmath>
#include <string>

#include "armmimic/engines/lk_options.h"

namespace armmimic {
namespace {

Status Range(const char* name, double value, double lo, double hi) {
  if (std::isfinite(value) && value >= lo && value <= hi) return Status::Ok();
  return Status::Error(std::string("lk.") + name,
                       std::string("lk option ") + name + " must be in [" + std::to_string(lo) +
                           ", " + std::to_string(hi) + "], got " + std::to_string(value));
}

}  // namespace

const char* LkArmSideName(LkArmSide side) {
  switch (side) {
    case LkArmSide::kAuto:
      return "auto";
    case LkArmSide::kLeft:
      return "left";
    case LkArmSide::kRight:
      return "right";
  }
  return "?";
}

bool ParseLkArmSide(const std::string& name, LkArmSide* out) {
  for (LkArmSide s : {LkArmSide::kAuto, LkArmSide::kLeft, LkArmSide::kRight}) {
    if (name == LkArmSideName(s)) {
      *out = s;
      return true;
    }
  }
  return false;
}

Status LkOptions::Check() const {
  const Status checks[] = {
      Range("standstill_frames", standstill_frames, 1, 100000),
      Range("body_threshold", body_threshold, 0, 255),
      Range("shoulder_height", shoulder_height, 0, 1),
      Range("shoulder_inset", shoulder_inset, 0, 0.5),
      Range("anchored_shoulder_height", anchored_shoulder_height, 0, 1),
      Range("anchored_shoulder_inset", anchored_shoulder_inset, 0, 0.5),
      Range("initial_upper_deg", initial_upper_deg, -360, 360),
      Range("initial_fore_deg", initial_fore_deg, -360, 360),

      Range("max_corners", max_corners, 4, 10000),
      Range("quality_level", quality_level, 1e-6, 1),
      Range("min_distance_px", min_distance_px, 0, 1000),
      Range("block_size", block_size, 3, 31),
      Range("window_px", window_px, 5, 101),
      Range("pyramid_levels", pyramid_levels, 0, 8),
      Range("max_iterations", max_iterations, 1, 1000),
      Range("epsilon", epsilon, 1e-6, 10),
      Range("motion_threshold_px", motion_threshold_px, 0, 100),
      Range("still_frames_drop", still_frames_drop, 0, 100000),
      Range("confirm_motion_px", confirm_motion_px, 0, 1000),
      Range("outlier_px", outlier_px, 0.1, 1000),
      Range("outlier_frames_drop", outlier_frames_drop, 0, 100000),
      Range("reseed_interval", reseed_interval, 1, 100000),
      Range("min_part_features", min_part_features, 0, 10000),
      Range("arm_width_ratio", arm_width_ratio, 0.01, 1),
      Range("joint_weight", joint_weight, 0, 1000),
      Range("inlier_deg", inlier_deg, 0.5, 90),
      Range("bar_search_deg", bar_search_deg, 1, 90),
      Range("bar_min_score", bar_min_score, -1, 1),
      Range("upper_fraction", upper_fraction, 0.2, 0.8),
      Range("forward_backward_px", forward_backward_px, 0, 100),
      Range("prior_weight", prior_weight, 0, 1000),
      Range("bend_for_elbow_deg", bend_for_elbow_deg, 0, 180),
      Range("max_bend_deg", max_bend_deg, 90, 180),
      Range("max_speed_deg_s", max_speed_deg_s, 10, 100000),
      Range("min_support", min_support, 0, 1),
      Range("confirm_frames", confirm_frames, 1, 1000),
      Range("shoulder_sway", shoulder_sway, 0, 1),
  };
  for (const Status& st : checks) {
    if (!st) return st;
  }
  if (window_px % 2 == 0) {
    return Status::Error("lk.window_px",
                         "lk option window_px must be odd, got " + std::to_string(window_px));
  }
  return Status::Ok();
}

}  // namespace armmimic
