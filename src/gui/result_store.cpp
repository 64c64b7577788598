#include "result_store.h"

namespace armmimic::gui {

int ResultStore::rows() const {
  int n = 0;
  for (const auto& [frame, m] : by_frame_) n += m.row() ? 1 : 0;
  return n;
}

int ResultStore::lost() const {
  int n = 0;
  for (const auto& [frame, m] : by_frame_) n += m.phase == MeasurementPhase::kLost ? 1 : 0;
  return n;
}

int ResultStore::arms() const {
  // Every measurement of a run follows the same arms.
  return !by_frame_.empty() && by_frame_.begin()->second.right_arm ? 2 : 1;
}

}  // namespace armmimic::gui
