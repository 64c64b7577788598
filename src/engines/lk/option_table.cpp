// The parameter table of the lk engine (Lucas-Kanade features, thesis chapter 6): one row per
// option (option_table.h). The engines test checks it against its struct (same defaults, every
// field listed, ranges that pass Check()).
// Length: LkOptionFields is the table itself, one row per option.
#include "armmimic/core/option_rows.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic {
namespace {

using namespace option_rows;  // NOLINT(google-build-using-namespace): the row builders
using L = LkOptions;

}  // namespace

const std::vector<OptionField<LkOptions>>& LkOptionFields() {
  static const std::vector<OptionField<L>> fields = {
      Int<L>("standstill_frames", &L::standstill_frames, 60, 1, 100000, "Standstill frames",
             "frames averaged into the standstill image (6.1)")
          .Flag("--standstill-frames")
          .Main(),
      Int<L>("body_threshold", &L::body_threshold, 45, 0, 255, "Body threshold",
             "grey-level difference standstill vs background that makes the body box"),
      Real<L>("shoulder_height", &L::shoulder_height, 0.6, 0, 1, 3, "Shoulder height",
              "shoulder at this share of the body box height, from its bottom"),
      Real<L>("shoulder_inset", &L::shoulder_inset, 1.0 / 6, 0, 0.5, 3, "Shoulder inset",
              "shoulder at this share of the body box width in from the arm's side"),
      Real<L>("anchored_shoulder_height", &L::anchored_shoulder_height, 0.7, 0, 1, 3,
              "Anchored shoulder height", "the anchored path's body-box shoulder height"),
      Real<L>("anchored_shoulder_inset", &L::anchored_shoulder_inset, 0.09, 0, 0.5, 3,
              "Anchored shoulder inset", "the anchored path's body-box shoulder inset"),
      Enum<L>("side", &L::side, LkArmSide::kAuto, {"auto", "left", "right"}, "Arm side",
              "side of the body box the moving arm is on, as seen on screen"),
      Real<L>("initial_upper_deg", &L::initial_upper_deg, -90, -360, 360, 1, "Initial upper arm",
              "upper-arm direction at the start, degrees")
          .Unit("deg")
          .Flag("--initial-upper")
          .Main(),
      Real<L>("initial_fore_deg", &L::initial_fore_deg, -90, -360, 360, 1, "Initial forearm",
              "forearm direction at the start, degrees")
          .Unit("deg")
          .Flag("--initial-fore")
          .Main(),
      Int<L>("max_corners", &L::max_corners, 300, 4, 10000, "Max. corners",
             "strongest Shi-Tomasi corners kept per detection (6.2.1)"),
      Real<L>("quality_level", &L::quality_level, 0.01, 0.0001, 1, 4, "Corner quality",
              "a corner's eigenvalue is at least this share of the strongest one"),
      Real<L>("min_distance_px", &L::min_distance_px, 5, 0, 1000, 1, "Corner distance",
              "minimum distance between corners, pixels"),
      Int<L>("block_size", &L::block_size, 3, 3, 31, "Eigenvalue block",
             "eigenvalue neighbourhood, pixels"),
      Int<L>("window_px", &L::window_px, 15, 5, 101, "LK window",
             "Lucas-Kanade search window, pixels, odd (6.2.2)")
          .Step(2),
      Int<L>("pyramid_levels", &L::pyramid_levels, 3, 0, 8, "Pyramid levels",
             "pyramid levels above the full image"),
      Int<L>("max_iterations", &L::max_iterations, 20, 1, 1000, "LK iterations",
             "iterations per pyramid level"),
      Real<L>("epsilon", &L::epsilon, 0.03, 0.001, 10, 3, "LK epsilon",
              "stop when the update is smaller than this, pixels"),
      Real<L>("motion_threshold_px", &L::motion_threshold_px, 1.0, 0, 100, 2, "Motion threshold",
              "a feature that moved more than this is on the arm, pixels (6.2.3)"),
      Int<L>("still_frames_drop", &L::still_frames_drop, 10, 0, 100000, "Drop still features after",
             "a feature still for more than this many frames is dropped")
          .Main(),
      Bool<L>("thesis_mode", &L::thesis_mode, false, "Thesis path only",
              "2-means and summed increments only, none of the improvements")
          .Flag("--thesis")
          .Main(),
      Bool<L>("use_bar", &L::use_bar, true, "Sleeve bars", "anchor each part on its sleeve colour"),
      Real<L>("bar_search_deg", &L::bar_search_deg, 30, 1, 90, 1, "Bar search",
              "bars searched this far around the features' estimate, degrees"),
      Real<L>("bar_min_score", &L::bar_min_score, 0.4, -1, 1, 2, "Bar minimum score",
              "weaker bars (part in front of the body) are not used"),
      Bool<L>("refine_shoulder", &L::refine_shoulder, true, "Refine shoulder",
              "refine a body-box shoulder from the sleeve's lines"),
      Real<L>("upper_fraction", &L::upper_fraction, 0.53, 0.2, 0.8, 2, "Upper-arm fraction",
              "upper arm / shoulder-to-wrist, the elbow prior"),
      Real<L>("forward_backward_px", &L::forward_backward_px, 1.0, 0, 100, 2,
              "Forward-backward check",
              "drop a track whose backward track misses by more, pixels "
              "(0: off)"),
      Real<L>("confirm_motion_px", &L::confirm_motion_px, 4.0, 0, 1000, 1, "Confirm motion",
              "a feature joins the fit once the model moved it this far, pixels"),
      Real<L>("outlier_px", &L::outlier_px, 3.0, 0.1, 1000, 1, "Outlier residual",
              "residual above which a feature is an outlier, pixels"),
      Int<L>("outlier_frames_drop", &L::outlier_frames_drop, 3, 0, 100000, "Drop outliers after",
             "consecutive outlier frames before a feature is dropped"),
      Int<L>("reseed_interval", &L::reseed_interval, 5, 1, 100000, "Re-seed interval",
             "frames between re-seeding corners on the arm"),
      Int<L>("min_part_features", &L::min_part_features, 12, 0, 10000, "Min. part features",
             "re-seed at once when a part has fewer features"),
      Real<L>("arm_width_ratio", &L::arm_width_ratio, 0.14, 0.01, 1, 3, "Arm band width",
              "half-width of the arm band / arm length (re-seed mask)"),
      Real<L>("joint_weight", &L::joint_weight, 1.0, 0, 1000, 2, "Joint weight",
              "weight of the shoulder/elbow pseudo-feature in the fits"),
      Real<L>("prior_weight", &L::prior_weight, 2, 0, 1000, 2, "Prior weight",
              "the previous pose votes like this many features at a part's end"),
      Real<L>("inlier_deg", &L::inlier_deg, 8, 0.5, 90, 1, "Inlier angle",
              "a feature whose implied direction is this far off is ignored, degrees"),
      Real<L>("bend_for_elbow_deg", &L::bend_for_elbow_deg, 20, 0, 180, 1, "Bend to learn elbow",
              "the elbow is located only when bent this much, degrees"),
      Real<L>("max_bend_deg", &L::max_bend_deg, 150, 90, 180, 1, "Largest bend",
              "the forearm's sleeve is not searched folded further back onto the upper arm, "
              "degrees"),
      Real<L>("max_speed_deg_s", &L::max_speed_deg_s, 600, 10, 100000, 0, "Fastest arm turn",
              "a segment turning faster than this, degrees a second, is a wrong lock: lost"),
      Real<L>("min_support", &L::min_support, 0.3, 0, 1, 2, "Minimum support",
              "a pose backed by less sleeve and feature evidence (0..1) is lost"),
      Int<L>("confirm_frames", &L::confirm_frames, 3, 1, 1000, "Frames to re-acquire",
             "agreeing frames before the arm is trusted again after a rejected jump"),
      Real<L>("shoulder_sway", &L::shoulder_sway, 0.05, 0, 1, 2, "Shoulder sway",
              "with clicked joints: how far the body's features may move the shoulder from the "
              "click, a share of the upper arm (0: kept at the click)"),
  };
  return fields;
}

}  // namespace armmimic
