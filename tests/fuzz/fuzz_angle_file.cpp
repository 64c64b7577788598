// Fuzzes the angle file v1 reader: any bytes either parse into rows that satisfy the format's
// invariants, or fail with a message that names the line.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "armmimic/core/angle_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  armmimic::AngleFile file;
  const armmimic::Status st = armmimic::ParseAngleFile(in, "fuzz.tsv", &file);
  if (!st.ok()) {
    if (st.message().rfind("fuzz.tsv", 0) != 0) std::abort();  // every message names the file
    return 0;
  }
  int last = -1;
  for (const auto& row : file.rows) {
    if (row.frame <= last) std::abort();
    last = row.frame;
    if (!std::isfinite(row.time_s)) std::abort();
    for (double v : {row.upper_deg, row.fore_deg, row.yaw_deg, row.bend_deg, row.yaw_signed_deg}) {
      if (std::isinf(v)) std::abort();
      if (!row.ok() && !std::isnan(v)) std::abort();
    }
    // What was read must be writable again.
    (void)armmimic::FormatAngleRow(row, file.has_file_column, file.has_confidence_column,
                                   file.has_signed_yaw_column);
  }
  return 0;
}
