#include "armmimic/core/angle_csv.h"

#include <cmath>

#include "armmimic/core/output_file.h"

namespace armmimic {
namespace {

char Separator(CsvStyle style) { return style == CsvStyle::kSemicolon ? ';' : ','; }

// A number as the angle file writes it, with the style's decimal mark; "" when not measured.
std::string Cell(double value, int decimals, CsvStyle style) {
  if (!std::isfinite(value)) return std::string();
  std::string s = FormatNumber(value, decimals);
  if (style == CsvStyle::kSemicolon) {
    for (char& c : s) {
      if (c == '.') c = ',';
    }
  }
  return s;
}

// RFC 4180: a field holding the separator, a quote or a line break is quoted, quotes doubled.
std::string Quoted(const std::string& text, char separator) {
  if (text.find_first_of(std::string("\"\r\n") + separator) == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + '"';
}

}  // namespace

std::string FormatCsvHeader(bool file_column, CsvStyle style) {
  static const char* const kColumns[] = {
      "frame",      "time (s)",      "status",        "upper (deg)",  "fore (deg)",  "yaw (deg)",
      "bend (deg)", "upper_cx (px)", "upper_cy (px)", "fore_cx (px)", "fore_cy (px)"};
  const char sep = Separator(style);
  std::string s;
  for (const char* c : kColumns) {
    if (!s.empty()) s += sep;
    s += c;
  }
  // Marker files: the view's image and the signed yaw, as in the angle file.
  if (file_column) s += std::string(1, sep) + "file" + sep + "yaw signed (deg)";
  return s;
}

std::string FormatCsvRow(const AngleRow& row, bool file_column, CsvStyle style) {
  const char sep = Separator(style);
  const bool ok = row.ok();
  std::string s = std::to_string(row.frame);
  s += sep;
  s += Cell(row.time_s, 4, style);
  s += sep;
  s += ok ? "ok" : "lost";
  for (double v : {row.upper_deg, row.fore_deg, row.yaw_deg, row.bend_deg}) {
    s += sep;
    if (ok) s += Cell(v, 3, style);
  }
  for (double v : {row.upper_cx, row.upper_cy, row.fore_cx, row.fore_cy}) {
    s += sep;
    if (ok) s += Cell(v, 2, style);
  }
  if (file_column) {
    s += sep;
    s += Quoted(row.file, sep);
    s += sep;
    if (ok) s += Cell(row.yaw_signed_deg, 3, style);
  }
  return s;
}

std::string FormatAnglesCsv(const std::vector<AngleRow>& rows, bool file_column, CsvStyle style) {
  std::string text = FormatCsvHeader(file_column, style) + "\r\n";
  text.reserve(text.size() + rows.size() * 72);
  for (const AngleRow& row : rows) text += FormatCsvRow(row, file_column, style) + "\r\n";
  return text;
}

Status WriteAnglesCsv(const std::string& path, const std::vector<AngleRow>& rows, bool file_column,
                      CsvStyle style) {
  return WriteOutputFile(path, FormatAnglesCsv(rows, file_column, style));
}

}  // namespace armmimic
