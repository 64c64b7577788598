// The parameter table of the hybrid engine (its own options; it takes lk's and bgsub's too):
// one row per option (option_table.h), and HybridOptions::Check(), which is the table's ranges.
#include "armmimic/core/option_rows.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic {
namespace {

using namespace option_rows;  // NOLINT(google-build-using-namespace): the row builders
using H = HybridOptions;

}  // namespace

const std::vector<OptionField<HybridOptions>>& HybridOptionFields() {
  static const std::vector<OptionField<H>> fields = {
      Real<H>("max_disagreement_deg", &H::max_disagreement_deg, 12, 1, 90, 1, "Max. disagreement",
              "lk's and bgsub's directions of a segment further apart than this (plus the "
              "joints' pixel uncertainty) make the frame lost, degrees")
          .Unit("deg")
          .Main(),
      Real<H>("joint_px", &H::joint_px, 2, 0, 50, 1, "Joint uncertainty",
              "how far each measurement may place a joint off, pixels: a short segment's "
              "directions may differ by atan(2 x this / its length) more"),
      Int<H>("restart_frames", &H::restart_frames, 5, 1, 100000, "Restart after",
             "frames in a row the tracker has had no pose of its own before it restarts from the "
             "second opinion's joints"),
      Int<H>("confirm_frames", &H::confirm_frames, 5, 1, 1000, "Steady frames",
             "frames in a row the second opinion (the background difference, or the pose network "
             "without one) must be ok and steady to restart the tracker from"),
  };
  return fields;
}

Status HybridOptions::Check() const {
  return CheckOptionFields(HybridOptionFields(), "hybrid", *this);
}

}  // namespace armmimic
