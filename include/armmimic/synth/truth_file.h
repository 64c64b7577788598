// Truth file v1: the ground truth of a generated scene, one row per frame (docs/synth.md).
//   # armmimic truth v1
//   # scene=arm seed=1 ...                      (optional "# k=v" meta lines, then comments)
//   frame time_s upper_deg fore_deg yaw_deg bend_deg shoulder_x shoulder_y elbow_x elbow_y
//   wrist_x wrist_y [extra columns...]          (TAB-separated)
// Values are '.'-decimal numbers or "nan" where not applicable. Extra trailing columns (e.g. the
// marker scenes' "file") are kept as text. The reader is strict and names the line of every error.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "armmimic/core/status.h"

namespace armmimic::synth {

inline constexpr const char* kTruthFileMagic = "# armmimic truth v1";
extern const char* const kTruthColumns[12];

struct TruthRow {
  int frame = 0;
  double time_s = 0;
  double upper_deg = kNaN;
  double fore_deg = kNaN;
  double yaw_deg = kNaN;
  double bend_deg = kNaN;
  double shoulder_x = kNaN;
  double shoulder_y = kNaN;
  double elbow_x = kNaN;
  double elbow_y = kNaN;
  double wrist_x = kNaN;
  double wrist_y = kNaN;
  std::vector<std::string> extra;  // one value per TruthFile::extra_columns
  // True when at least one of the four angles is known (the frame is scored).
  bool HasAngles() const;
};

struct TruthFile {
  AngleMeta meta;                          // from the "# k=v" line after the magic line
  std::vector<std::string> extra_columns;  // names after the 12 listed ones
  std::vector<TruthRow> rows;              // in file order; frames strictly increasing

  std::string Meta(const std::string& key, const std::string& fallback = "") const;
  // Index of the extra column `name`, or -1.
  int ExtraColumn(const std::string& name) const;
  // The row of `frame`, or nullptr.
  const TruthRow* Find(int frame) const;
};

// `source_name` is used in messages ("truth.tsv:12: ...").
Status ParseTruthFile(std::istream& in, const std::string& source_name, TruthFile* out);
Status ReadTruthFile(const std::string& path, TruthFile* out);

// The whole file as text; rows must have extra.size() == extra_columns.size() (throws otherwise).
std::string FormatTruthFile(const TruthFile& file);
// Writes atomically (a reader never sees half a file).
Status WriteTruthFile(const std::string& path, const TruthFile& file);

}  // namespace armmimic::synth
