// The parameter table of the bgsub engine (background subtraction, thesis chapter 5): one row per
// option (option_table.h). The engines test checks it against its struct (same defaults, every
// field listed, ranges that pass Check()).
#include "armmimic/core/option_rows.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic {
namespace {

using namespace option_rows;  // NOLINT(google-build-using-namespace): the row builders
using B = BgsubOptions;

}  // namespace

const std::vector<OptionField<BgsubOptions>>& BgsubOptionFields() {
  static const std::vector<OptionField<B>> fields = {
      Int<B>("threshold", &B::threshold, 45, 1, 254, "Threshold",
             "grey-level difference from the background (5.2.2, 5.2.4)")
          .Flag("--threshold")
          .Main(),
      Int<B>("standstill_frames", &B::standstill_frames, 60, 1, 100000, "Standstill frames",
             "frames averaged into the standstill image (5.2.2)")
          .Flag("--standstill-frames")
          .Main(),
      Real<B>("straight_ratio", &B::straight_ratio, 0.30, 0.10, 0.95, 2, "Straight-arm ratio",
              "defect depth below this share of the semi-major axis: a straight arm")
          .Main(),
      Int<B>("closing_size", &B::closing_size, 5, 0, 51, "Closing size",
             "morphological closing kernel, pixels (0 or 1: none)")
          .Main(),
      Int<B>("min_arm_area_px", &B::min_arm_area_px, 40, 1, 100000, "Minimum arm area",
             "a smaller moving region is no arm (lost), pixels"),
      Real<B>("shoulder_height", &B::shoulder_height, 0.6, 0, 1, 3, "Shoulder height",
              "shoulder at this share of the body box height, from its bottom (5.2.2)"),
      Real<B>("shoulder_side", &B::shoulder_side, 1.0 / 6, 0, 0.5, 3, "Shoulder inset",
              "shoulder at this share of the body box width in from the moving arm's side"),
      Bool<B>("thesis_mode", &B::thesis_mode, false, "Thesis path only",
              "none of the improvements below")
          .Flag("--thesis")
          .Main(),
      Real<B>("rest_deg", &B::rest_deg, -90, -180, 180, 1, "Rest direction",
              "the standstill pose's direction, degrees (arms hanging: -90)"),
      Real<B>("upper_arm_fraction", &B::upper_arm_fraction, 0.45, 0.11, 0.89, 2,
              "Upper-arm fraction", "upper arm / shoulder-to-fingertip reach"),
      Int<B>("max_bend_deg", &B::max_bend_deg, 150, 90, 180, "Largest bend",
             "the forearm is not searched folded further back onto the upper arm, degrees "
             "(an elbow flexes to about 150)"),
      Real<B>("max_speed_deg_s", &B::max_speed_deg_s, 600, 10, 100000, 0, "Fastest arm turn",
              "a segment turning faster than this, degrees a second, is a wrong pick: lost"),
      Real<B>("min_support", &B::min_support, 0.5, 0, 1, 2, "Minimum support",
              "a fitted arm with less of its length on the person mask (0..1) is lost"),
      Int<B>("confirm_frames", &B::confirm_frames, 3, 1, 1000, "Frames to re-acquire",
             "agreeing frames before a new pick is trusted (also at the start)"),
  };
  return fields;
}

}  // namespace armmimic
