// Angle CSV: the rows of an angle file as comma-separated values for spreadsheets, next to the
// angle file v1 (TSV), which stays the exchange format. One header row with the unit of every
// column, one row per frame, an empty cell for every value not measured (`nan` in the TSV). The
// semicolon style writes decimal commas, as spreadsheets in comma-decimal locales expect.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"

namespace armmimic {

enum class CsvStyle {
  kComma,      // "1.5,2.25": separator ',', decimal point '.'
  kSemicolon,  // "1,5;2,25": separator ';', decimal comma ','
};

// The header row: "frame,time (s),status,upper (deg),...,fore_cy (px)" and ",file" with
// `file_column` (marker engine), separated as `style` says. No line ending.
std::string FormatCsvHeader(bool file_column, CsvStyle style);
// One data row (no line ending). Angles and centres of a lost row are empty cells.
std::string FormatCsvRow(const AngleRow& row, bool file_column, CsvStyle style);
// The header and every row, each line ended by CR LF (RFC 4180).
std::string FormatAnglesCsv(const std::vector<AngleRow>& rows, bool file_column, CsvStyle style);
// FormatAnglesCsv written atomically to `path`; the message names the file.
Status WriteAnglesCsv(const std::string& path, const std::vector<AngleRow>& rows, bool file_column,
                      CsvStyle style);

}  // namespace armmimic
