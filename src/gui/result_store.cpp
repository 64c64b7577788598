#include "result_store.h"

#include <memory>

#include "armmimic/core/angle_file.h"

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

Status ReadResults(const QStringList& paths, ResultStore* out) {
  out->clear();
  if (paths.size() > 2) return Status::Error("the results name more than two angle files");
  std::vector<AngleFile> files(static_cast<std::size_t>(paths.size()));
  for (int i = 0; i < paths.size(); ++i) {
    const Status st = ReadAngleFile(paths[i].toStdString(), &files[static_cast<std::size_t>(i)]);
    if (!st) return st;
  }
  if (files.empty()) return Status::Ok();
  std::map<int, ArmMeasurement> right;
  if (files.size() == 2) {
    for (const AngleRow& row : files[1].rows) right[row.frame] = ArmMeasurement::FromRow(row);
  }
  for (const AngleRow& row : files[0].rows) {
    ArmMeasurement m = ArmMeasurement::FromRow(row);
    if (files.size() == 2) {
      const auto it = right.find(row.frame);
      if (it == right.end()) {
        return Status::Error(paths[1].toStdString() + ": no row for frame " +
                             std::to_string(row.frame) + ", which " + paths[0].toStdString() +
                             " has");
      }
      m.right_arm = std::make_shared<const ArmMeasurement>(it->second);
    }
    out->add(m);
  }
  return Status::Ok();
}

}  // namespace armmimic::gui
