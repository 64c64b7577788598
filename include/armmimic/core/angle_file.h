// Angle file v1 (see docs/angle-file.md): a TSV of per-frame arm angles, written by the engines
// and read by score, plan and send. The reader is strict and names the line of every error.
#pragma once

#include <iosfwd>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "armmimic/core/angles.h"
#include "armmimic/core/status.h"

namespace armmimic {

enum class RowStatus { kOk, kLost };

struct AngleRow {
  int frame = 0;
  double time_s = 0;
  RowStatus status = RowStatus::kLost;
  double upper_deg = kNaN;
  double fore_deg = kNaN;
  double yaw_deg = kNaN;
  double bend_deg = kNaN;
  double upper_cx = kNaN;
  double upper_cy = kNaN;
  double fore_cx = kNaN;
  double fore_cy = kNaN;
  std::string file;          // marker engine only: the image's file name
  double confidence = kNaN;  // optional trailing column, 0..1 (pose engine)
  // Marker engine only: the signed yaw, positive when the joint turns its right side towards the
  // camera (the trailing yaw_signed_deg column); yaw_deg is its magnitude.
  double yaw_signed_deg = kNaN;
  // The optional 3-D columns (pose engine with BlazePose), read by name: each segment's
  // direction in the camera's frame (x to the image's right, y down, z away from the camera) as
  // azimuth atan2(-d_z, d_x) in (-180, 180] and elevation atan2(-d_y, hypot(d_x, d_z)) in
  // [-90, 90], and the elbow's 3-D angle in [0, 180] (180: straight); docs/angle-file.md.
  double upper_az_deg = kNaN;
  double upper_el_deg = kNaN;
  double fore_az_deg = kNaN;
  double fore_el_deg = kNaN;
  double elbow_deg = kNaN;
  bool ok() const { return status == RowStatus::kOk; }
  // The yaw to turn a robot joint by: the signed one where the row has it, else yaw_deg.
  double turn_yaw_deg() const { return std::isnan(yaw_signed_deg) ? yaw_deg : yaw_signed_deg; }
  // The same for a row of a file: in a file with the yaw_signed_deg column (`signed_column`) a
  // nan there means the sign could not be told, and the yaw to turn by is unknown (nan: hold
  // the joint), never the unsigned yaw_deg.
  double turn_yaw_deg(bool signed_column) const {
    return signed_column ? yaw_signed_deg : turn_yaw_deg();
  }
};

// Ordered key=value pairs of the "# engine=... source=..." header line.
using AngleMeta = std::vector<std::pair<std::string, std::string>>;

// The value of the first `key` in `meta`, or `fallback`.
std::string MetaValue(const AngleMeta& meta, const std::string& key,
                      const std::string& fallback = "");

struct AngleFile {
  AngleMeta meta;
  bool has_file_column = false;
  bool has_confidence_column = false;
  bool has_signed_yaw_column = false;  // a yaw_signed_deg column after the listed ones
  bool has_3d_columns = false;         // any of kAngle3dColumns
  bool complete = true;  // false when the header says complete=no (an interrupted run)
  int meta_line = 0;     // the line of the "# key=value ..." header line; 0: none
  std::vector<AngleRow> rows;

  // Value of a meta key, or `fallback` when absent.
  std::string Meta(const std::string& key, const std::string& fallback = "") const;
};

inline constexpr const char* kAngleFileMagic = "# armmimic angles v1";
inline constexpr const char* kAngleFileUnits =
    "# units: degrees; directions CCW on screen from +x, (-180,180]; image y down";
// The contract's columns, in order. The marker engine adds "file" and then "yaw_signed_deg"
// after them.
extern const char* const kAngleColumns[11];
inline constexpr const char* kSignedYawColumn = "yaw_signed_deg";
// The optional 3-D columns, written last (after confidence) and read by name.
extern const char* const kAngle3dColumns[5];
// The last line of a file written to a device or FIFO by a run that stopped early, where the
// header could not be rewritten with complete=no; read as complete=no all the same.
inline constexpr const char* kIncompleteMark = "# complete=no";
inline constexpr std::size_t kMaxAngleLineLength = 65536;

// Parses an angle file; `source_name` is used in messages ("angles.tsv:12: ...").
Status ParseAngleFile(std::istream& in, const std::string& source_name, AngleFile* out);
Status ReadAngleFile(const std::string& path, AngleFile* out);

// Formats a number the way the file stores it: '.' decimals whatever the locale, "nan" for NaN.
std::string FormatNumber(double value, int decimals);
// Formats one data row (no trailing newline).
std::string FormatAngleRow(const AngleRow& row, bool file_column, bool confidence_column = false,
                           bool signed_yaw_column = false, bool columns_3d = false);
// The "# k=v k=v" meta line; spaces and '%' in values are percent-encoded.
std::string FormatMetaLine(const AngleMeta& meta);

// Streams rows to a temporary file beside `path`, renamed over `path` by Commit(): a reader
// never sees half a file. If the writer is destroyed without Commit(), the target is untouched.
class AngleFileWriter {
 public:
  AngleFileWriter();
  ~AngleFileWriter();
  AngleFileWriter(const AngleFileWriter&) = delete;
  AngleFileWriter& operator=(const AngleFileWriter&) = delete;

  // confidence_column: the optional trailing confidence column after the contract's columns;
  // signed_yaw_column: the marker engine's yaw_signed_deg; columns_3d: kAngle3dColumns, last.
  Status Open(const std::string& path, const AngleMeta& meta, bool file_column,
              bool confidence_column = false, bool signed_yaw_column = false,
              bool columns_3d = false);
  Status Write(const AngleRow& row);
  // complete=false rewrites the header with complete=no (rows so far are kept); in a device or
  // FIFO, which cannot be rewound, a last line kIncompleteMark says so instead. A `reason`
  // (a truncated video) goes into the header as incomplete=REASON after complete=no.
  Status Commit(bool complete = true, const std::string& reason = "");
  int rows_written() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace armmimic
