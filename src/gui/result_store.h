// ResultStore: the measurements of the last analysis, kept per frame so scrubbing shows the
// overlay at once and the plot can be redrawn from them.
#pragma once

#include <map>
#include <optional>

#include <QStringList>

#include "armmimic/core/status.h"
#include "armmimic/engines/measurement.h"

namespace armmimic::gui {

class ResultStore {
 public:
  void clear() { by_frame_.clear(); }
  void add(const ArmMeasurement& m) { by_frame_[m.frame] = m; }
  const ArmMeasurement* find(int frame) const {
    auto it = by_frame_.find(frame);
    return it == by_frame_.end() ? nullptr : &it->second;
  }
  std::optional<ArmMeasurement> at(int frame) const {
    const ArmMeasurement* m = find(frame);
    return m ? std::optional<ArmMeasurement>(*m) : std::nullopt;
  }
  const std::map<int, ArmMeasurement>& all() const { return by_frame_; }
  int size() const { return static_cast<int>(by_frame_.size()); }
  int rows() const;  // measurements that are angle-file rows (ok or lost)
  int lost() const;
  // The arms measured: 2 for the pose engine's side both (ArmMeasurement::right_arm), else 1.
  int arms() const;

 private:
  std::map<int, ArmMeasurement> by_frame_;
};

// Reads the rows of angle files into `out` (cleared first): one file, or the left and the right
// arm's files of one analysis (side both), joined frame by frame (ArmMeasurement::right_arm).
// The error names the file.
Status ReadResults(const QStringList& paths, ResultStore* out);

}  // namespace armmimic::gui
