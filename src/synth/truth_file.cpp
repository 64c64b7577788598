// Truth files of the generated scenes: the columns, the line-by-line reader and the writer.
// Length: ParseTruthFile is one pass over the lines whose checks share the header's column
// positions.
#include "armmimic/synth/truth_file.h"
#include "armmimic/core/text.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "armmimic/core/output_file.h"

namespace armmimic::synth {

const char* const kTruthColumns[12] = {"frame",   "time_s",   "upper_deg",  "fore_deg",
                                       "yaw_deg", "bend_deg", "shoulder_x", "shoulder_y",
                                       "elbow_x", "elbow_y",  "wrist_x",    "wrist_y"};

namespace {

constexpr std::size_t kMaxLineLength = 65536;

std::string Where(const std::string& source, int line) {
  return source + ":" + std::to_string(line) + ": ";
}

}  // namespace

bool TruthRow::HasAngles() const {
  return std::isfinite(upper_deg) || std::isfinite(fore_deg) || std::isfinite(yaw_deg) ||
         std::isfinite(bend_deg);
}

std::string TruthFile::Meta(const std::string& key, const std::string& fallback) const {
  return MetaValue(meta, key, fallback);
}

int TruthFile::ExtraColumn(const std::string& name) const {
  for (std::size_t i = 0; i < extra_columns.size(); ++i) {
    if (extra_columns[i] == name) return static_cast<int>(i);
  }
  return -1;
}

const TruthRow* TruthFile::Find(int frame) const {
  // Rows are strictly increasing by frame: binary search.
  std::size_t lo = 0, hi = rows.size();
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (rows[mid].frame < frame)
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo < rows.size() && rows[lo].frame == frame) return &rows[lo];
  return nullptr;
}

Status ParseTruthFile(std::istream& in, const std::string& source_name, TruthFile* out) {
  *out = TruthFile();
  std::string line;
  int line_no = 0;
  bool have_magic = false;
  bool have_header = false;
  bool meta_done = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.size() > kMaxLineLength) {
      return Status::Error(Where(source_name, line_no) + "line longer than " +
                           std::to_string(kMaxLineLength) + " characters");
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!have_magic) {
      if (line_no == 1) StripUtf8Bom(&line);
      if (line != kTruthFileMagic) {
        return Status::Error(Where(source_name, line_no) + "not a truth file (expected the line '" +
                             std::string(kTruthFileMagic) + "')");
      }
      have_magic = true;
      continue;
    }
    if (!line.empty() && line[0] == '#') {
      if (!have_header && !meta_done && line.find('=') != std::string::npos) {
        std::istringstream words(line.substr(1));
        std::string word;
        while (words >> word) {
          const std::size_t eq = word.find('=');
          if (eq == std::string::npos || eq == 0) continue;
          out->meta.emplace_back(word.substr(0, eq), PercentDecode(word.substr(eq + 1)));
        }
        meta_done = true;
      }
      continue;
    }
    if (line.empty()) {
      if (!have_header) {
        return Status::Error(Where(source_name, line_no) +
                             "empty line where the header was expected");
      }
      // Empty lines after the header are skipped.
      continue;
    }
    const std::vector<std::string> fields = SplitTabs(line);
    if (!have_header) {
      if (fields.size() < 12) {
        return Status::Error(Where(source_name, line_no) + "header has " +
                             std::to_string(fields.size()) + " columns, expected at least 12 (" +
                             "frame, time_s, upper_deg, ... wrist_y)");
      }
      for (int i = 0; i < 12; ++i) {
        if (fields[i] != kTruthColumns[i]) {
          return Status::Error(Where(source_name, line_no) + "header column " +
                               std::to_string(i + 1) + " is '" + fields[i] + "', expected '" +
                               kTruthColumns[i] + "'");
        }
      }
      out->extra_columns.assign(fields.begin() + 12, fields.end());
      have_header = true;
      continue;
    }
    const std::size_t want = 12 + out->extra_columns.size();
    if (fields.size() != want) {
      return Status::Error(Where(source_name, line_no) + "row has " +
                           std::to_string(fields.size()) + " fields, the header has " +
                           std::to_string(want));
    }
    TruthRow row;
    if (!ParseFrameIndex(fields[0], &row.frame)) {
      return Status::Error(Where(source_name, line_no) + "frame '" + fields[0] +
                           "' is not a non-negative integer");
    }
    double* values[11] = {&row.time_s,   &row.upper_deg,  &row.fore_deg,   &row.yaw_deg,
                          &row.bend_deg, &row.shoulder_x, &row.shoulder_y, &row.elbow_x,
                          &row.elbow_y,  &row.wrist_x,    &row.wrist_y};
    for (int i = 0; i < 11; ++i) {
      if (!ParseTableNumber(fields[i + 1], true, values[i])) {
        return Status::Error(Where(source_name, line_no) + kTruthColumns[i + 1] + " '" +
                             fields[i + 1] + "' is not a number or nan");
      }
    }
    if (std::isnan(row.time_s)) {
      return Status::Error(Where(source_name, line_no) + "time_s must not be nan");
    }
    if (!out->rows.empty() && row.frame <= out->rows.back().frame) {
      return Status::Error(Where(source_name, line_no) + "frame " + std::to_string(row.frame) +
                           " does not follow frame " + std::to_string(out->rows.back().frame) +
                           " (frames must increase)");
    }
    row.extra.assign(fields.begin() + 12, fields.end());
    out->rows.push_back(std::move(row));
  }
  if (in.bad()) return Status::Error(source_name + ": read error");
  if (!have_magic) return Status::Error(source_name + ": empty file, not a truth file");
  if (!have_header) return Status::Error(source_name + ": no header line (frame, time_s, ...)");
  return Status::Ok();
}

Status ReadTruthFile(const std::string& path, TruthFile* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(path + ": cannot open the truth file");
  return ParseTruthFile(in, path, out);
}

std::string FormatTruthFile(const TruthFile& file) {
  std::string s = std::string(kTruthFileMagic) + "\n";
  if (!file.meta.empty()) {
    s += "#";
    for (const auto& [k, v] : file.meta) s += " " + k + "=" + PercentEncode(v);
    s += "\n";
  }
  s += "# units: degrees; directions CCW on screen from +x, (-180,180]; pixels, image y down\n";
  for (int i = 0; i < 12; ++i) s += std::string(i ? "\t" : "") + kTruthColumns[i];
  for (const auto& c : file.extra_columns) s += "\t" + c;
  s += "\n";
  for (const TruthRow& r : file.rows) {
    if (r.extra.size() != file.extra_columns.size()) {
      throw std::invalid_argument("FormatTruthFile: row " + std::to_string(r.frame) + " has " +
                                  std::to_string(r.extra.size()) + " extra values for " +
                                  std::to_string(file.extra_columns.size()) + " extra columns");
    }
    s += std::to_string(r.frame);
    s += "\t" + FormatNumber(r.time_s, 4);
    for (double v : {r.upper_deg, r.fore_deg, r.yaw_deg, r.bend_deg})
      s += "\t" + FormatNumber(v, 3);
    for (double v : {r.shoulder_x, r.shoulder_y, r.elbow_x, r.elbow_y, r.wrist_x, r.wrist_y}) {
      s += "\t" + FormatNumber(v, 2);
    }
    for (const auto& e : r.extra) {
      if (e.find_first_of("\t\n\r") != std::string::npos) {
        throw std::invalid_argument("FormatTruthFile: extra value contains a tab or newline");
      }
      s += "\t" + e;
    }
    s += "\n";
  }
  return s;
}

Status WriteTruthFile(const std::string& path, const TruthFile& file) {
  return WriteOutputFile(path, FormatTruthFile(file));
}

}  // namespace armmimic::synth
