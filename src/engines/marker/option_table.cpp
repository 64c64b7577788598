// The parameter table of the marker engine (the marked joint, thesis chapter 4): one row per option
// (option_table.h), and MarkerOptions::Check(), which is the table's ranges and relations plus the
// odd median window. The engines test checks the table against its struct (same defaults, every
// field listed, ranges that pass Check(), a value outside a range refused with its key).
#include <string>

#include "armmimic/core/option_rows.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic {
namespace {

using namespace option_rows;  // NOLINT(google-build-using-namespace): the row builders
using M = MarkerOptions;

}  // namespace

const std::vector<OptionField<MarkerOptions>>& MarkerOptionFields() {
  static const std::vector<OptionField<M>> fields = {
      Int<M>("median_size", &M::median_size, 5, 1, 31, "Median window",
             "median filter window, odd (4.2.1)")
          .Step(2)
          .Main(),
      Int<M>("low", &M::low, 20, 0, 255, "Low threshold", "darkest marker grey level (4.2.2)")
          .Flag("--low")
          .BelowKeyedHere("high")
          .Main(),
      Int<M>("high", &M::high, 80, 0, 255, "High threshold", "brightest marker grey level (4.2.2)")
          .Flag("--high")
          .Main(),
      Int<M>("flood_range", &M::flood_range, 10, 0, 255, "Flood range",
             "flood-fill value range (+/-) around the seed (4.2.3)")
          .Main(),
      Int<M>("min_area", &M::min_area, 10, 1, 100000, "Min. area",
             "smallest marker area, pixels at 320x240 (4.2.4)")
          .Below("max_area"),
      Int<M>("max_area", &M::max_area, 200, 1, 100000, "Max. area",
             "largest marker area, pixels at 320x240 (4.2.4)"),
      Real<M>("min_aspect", &M::min_aspect, 0.2, 0.01, 100, 2, "Min. aspect",
              "smallest bounding-box width / height")
          .Below("max_aspect"),
      Real<M>("max_aspect", &M::max_aspect, 3.0, 0.01, 100, 2, "Max. aspect",
              "largest bounding-box width / height"),
      Real<M>("min_fill", &M::min_fill, 0.7, 0, 1, 2, "Min. fill",
              "smallest area / bounding-box area"),
      Bool<M>("auto_window", &M::auto_window, true, "Shift the grey window",
              "when [low, high] misses the reference's markers, use the nearest window that "
              "shows them"),
      Bool<M>("thesis_mode", &M::thesis_mode, false, "Thesis path only",
              "three largest survivors, box centres, yaw = acos(n/N)")
          .Flag("--thesis")
          .Main(),
      Real<M>("fov_deg", &M::fov_deg, 60, 0, 140, 1, "Camera field of view",
              "the camera's horizontal field of view, degrees (0: a distant camera)")
          .Unit("deg")
          .Flag("--fov")
          .Main(),
      Real<M>("max_marker_turn_deg", &M::max_marker_turn_deg, 74, 1, 89, 1, "Max. marker turn",
              "a view is read only when a lower marker faces the camera within this, degrees"),
      Real<M>("agreement_sigmas", &M::agreement_sigmas, 4, 0.5, 100, 1, "Marker agreement",
              "lost when the two lower markers' yaws differ by more than this many expected "
              "spreads (plus 1 degree)"),
      Real<M>("max_upper_turn_deg", &M::max_upper_turn_deg, 60, 1, 89, 1, "Max. upper turn",
              "the bend is measured while the upper marker faces the camera within this, "
              "degrees"),
      Real<M>("upper_tolerance", &M::upper_tolerance, 0.06, 0.01, 1, 2, "Upper marker tolerance",
              "how far (relative to e) the upper marker may lie from where the model puts it"),
  };
  return fields;
}

Status MarkerOptions::Check() const {
  if (Status st = CheckOptionFields(MarkerOptionFields(), "marker", *this); !st) return st;
  if (median_size % 2 == 0) {  // cv::medianBlur takes odd windows only
    return Status::Error("marker.median_size",
                         "median window is " + std::to_string(median_size) + "; it must be odd");
  }
  return Status::Ok();
}

}  // namespace armmimic
