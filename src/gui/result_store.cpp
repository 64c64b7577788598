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

}  // namespace armmimic::gui
