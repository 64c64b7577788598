// Angle file v1: formatting, the line-by-line reader with its checks, and the atomic writer.
// Length: ParseAngleFile is one pass over the lines whose checks share the header's column
// positions, and the optional columns' checks read those same positions.
#include "armmimic/core/angle_file.h"
#include "armmimic/core/text.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <sstream>
#include <stdexcept>

#include "armmimic/core/output_file.h"

namespace armmimic {

const char* const kAngleColumns[11] = {"frame",    "time_s",  "status",   "upper_deg",
                                       "fore_deg", "yaw_deg", "bend_deg", "upper_cx",
                                       "upper_cy", "fore_cx", "fore_cy"};
const char* const kAngle3dColumns[5] = {"upper_az_deg", "upper_el_deg", "fore_az_deg",
                                        "fore_el_deg", "elbow_deg"};

namespace {}  // namespace

std::string MetaValue(const AngleMeta& meta, const std::string& key, const std::string& fallback) {
  for (const auto& [k, v] : meta) {
    if (k == key) return v;
  }
  return fallback;
}

std::string AngleFile::Meta(const std::string& key, const std::string& fallback) const {
  return MetaValue(meta, key, fallback);
}

std::string FormatNumber(double value, int decimals) {
  if (std::isnan(value)) return "nan";
  if (!std::isfinite(value)) {
    throw std::invalid_argument("FormatNumber: infinite value cannot be written to an angle file");
  }
  if (value == 0) value = 0;  // no "-0.000"
  // Fixed notation of a large double has up to 309 digits before the point.
  char buf[512];
  const auto r = std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::fixed, decimals);
  if (r.ec != std::errc()) throw std::invalid_argument("FormatNumber: too many decimals");
  std::string s(buf, r.ptr);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string FormatMetaLine(const AngleMeta& meta) {
  std::string line = "#";
  for (const auto& [k, v] : meta) line += " " + k + "=" + PercentEncode(v);
  return line;
}

std::string FormatAngleRow(const AngleRow& row, bool file_column, bool confidence_column,
                           bool signed_yaw_column, bool columns_3d) {
  const bool ok = row.ok();
  auto ang = [&](double v) { return FormatNumber(ok ? v : kNaN, 3); };
  auto px = [&](double v) { return FormatNumber(ok ? v : kNaN, 2); };
  std::string s;
  s.reserve(128);
  s += std::to_string(row.frame);
  s += '\t';
  s += FormatNumber(row.time_s, 4);
  s += ok ? "\tok" : "\tlost";
  for (double v : {row.upper_deg, row.fore_deg, row.yaw_deg, row.bend_deg}) {
    s += '\t';
    s += ang(v);
  }
  for (double v : {row.upper_cx, row.upper_cy, row.fore_cx, row.fore_cy}) {
    s += '\t';
    s += px(v);
  }
  if (confidence_column) {
    s += '\t';
    s += FormatNumber(std::isnan(row.confidence) ? kNaN : row.confidence, 3);
  }
  if (file_column) {
    s += '\t';
    s += row.file;
  }
  if (signed_yaw_column) {
    s += '\t';
    s += ang(row.yaw_signed_deg);
  }
  if (columns_3d) {
    for (double v :
         {row.upper_az_deg, row.upper_el_deg, row.fore_az_deg, row.fore_el_deg, row.elbow_deg}) {
      s += '\t';
      s += ang(v);
    }
  }
  return s;
}

namespace {

// The 3-D columns present (index > 0) of a row: numbers in their ranges, nan in lost rows.
Status Parse3dColumns(const std::vector<std::string>& f, const std::size_t (&index)[5],
                      AngleRow* row) {
  double* values[5] = {&row->upper_az_deg, &row->upper_el_deg, &row->fore_az_deg, &row->fore_el_deg,
                       &row->elbow_deg};
  // Azimuths in (-180, 180], elevations in [-90, 90], the elbow in [0, 180].
  const double lo[5] = {-180, -90, -180, -90, 0};
  const double hi[5] = {180, 90, 180, 90, 180};
  const bool lo_open[5] = {true, false, true, false, false};
  for (int c = 0; c < 5; ++c) {
    if (index[c] == 0) continue;
    const std::string& v = f[index[c]];
    const std::string name = kAngle3dColumns[c];
    if (!ParseTableNumber(v, true, values[c])) {
      return Status::Error(name + " \"" + Excerpt(v) +
                           "\" is not a number (use '.' decimals, or nan)");
    }
    const double x = *values[c];
    if (std::isnan(x)) continue;
    if (!row->ok()) {
      return Status::Error("status is lost but " + name +
                           " is a number (lost rows carry nan angles)");
    }
    if ((lo_open[c] ? x <= lo[c] - 1e-9 : x < lo[c] - 1e-9) || x > hi[c] + 1e-9) {
      return Status::Error(name + " " + Excerpt(v) + " is outside " + (lo_open[c] ? "(" : "[") +
                           FormatNumber(lo[c], 0) + ", " + FormatNumber(hi[c], 0) + "]");
    }
  }
  return Status::Ok();
}

}  // namespace

Status ParseAngleFile(std::istream& in, const std::string& source_name, AngleFile* out) {
  *out = AngleFile();
  auto err = [&](int line_no, const std::string& what) {
    return Status::Error(source_name + ":" + std::to_string(line_no) + ": " + what);
  };
  std::string line;
  int line_no = 0;
  bool have_header = false;
  std::size_t header_columns = 0;
  std::size_t file_index = 0;  // trailing columns, 0: absent
  std::size_t confidence_index = 0;
  int last_frame = -1;
  bool seen_meta = false;
  std::size_t signed_yaw_index = 0;
  std::size_t index_3d[5] = {0, 0, 0, 0, 0};
  while (true) {
    // Bounded: never holds more than kMaxAngleLineLength + 1 characters of one line.
    bool too_long = false;
    if (!ReadTextLine(in, &line, kMaxAngleLineLength, &too_long)) break;
    ++line_no;
    if (too_long || line.size() > kMaxAngleLineLength) {
      return err(line_no,
                 "line is longer than " + std::to_string(kMaxAngleLineLength) + " characters");
    }
    if (line_no == 1) StripUtf8Bom(&line);
    if (line.find('\0') != std::string::npos) return err(line_no, "line contains a NUL byte");

    if (!line.empty() && line[0] == '#') {
      if (have_header && line == kIncompleteMark) out->complete = false;
      if (line.rfind("# armmimic angles v", 0) == 0 && line != kAngleFileMagic) {
        return err(line_no, "unsupported angle file version \"" + Excerpt(line.substr(2)) +
                                "\" (this reader knows v1)");
      }
      if (!have_header && !seen_meta && line.find('=') != std::string::npos &&
          line.rfind("# units:", 0) != 0) {
        seen_meta = true;
        out->meta_line = line_no;
        std::istringstream words(line.substr(1));
        std::string word;
        while (words >> word) {
          const auto eq = word.find('=');
          if (eq == std::string::npos || eq == 0) continue;
          out->meta.emplace_back(word.substr(0, eq), PercentDecode(word.substr(eq + 1)));
          if (word.substr(0, eq) == "complete" && word.substr(eq + 1) == "no") {
            out->complete = false;
          }
        }
      }
      continue;
    }
    if (!have_header) {
      if (line.empty()) return err(line_no, "expected the column header, found an empty line");
      const std::vector<std::string> cols = SplitTabs(line);
      for (std::size_t i = 0; i < 11; ++i) {
        if (i >= cols.size() || cols[i] != kAngleColumns[i]) {
          std::string expected;
          for (std::size_t j = 0; j < 11; ++j)
            expected += (j ? "\\t" : "") + std::string(kAngleColumns[j]);
          return err(line_no, "bad column header: column " + std::to_string(i + 1) + " is \"" +
                                  (i < cols.size() ? Excerpt(cols[i]) : std::string()) +
                                  "\", expected the header " + expected);
        }
      }
      header_columns = cols.size();
      for (std::size_t i = 11; i < cols.size(); ++i) {
        if (cols[i] == "file") file_index = i;
        if (cols[i] == "confidence") confidence_index = i;
        if (cols[i] == kSignedYawColumn) signed_yaw_index = i;
        for (int c = 0; c < 5; ++c) {
          if (cols[i] == kAngle3dColumns[c]) index_3d[c] = i;
        }
      }
      for (std::size_t i : index_3d) out->has_3d_columns = out->has_3d_columns || i > 0;
      out->has_file_column = file_index > 0;
      out->has_confidence_column = confidence_index > 0;
      out->has_signed_yaw_column = signed_yaw_index > 0;
      have_header = true;
      continue;
    }
    if (line.empty()) continue;  // a blank line (e.g. at the end) carries no row
    const std::vector<std::string> f = SplitTabs(line);
    if (f.size() != header_columns) {
      return err(line_no, "row has " + std::to_string(f.size()) + " fields, the header has " +
                              std::to_string(header_columns));
    }
    AngleRow row;
    if (!ParseFrameIndex(f[0], &row.frame)) {
      return err(line_no, "frame \"" + Excerpt(f[0]) + "\" is not a non-negative integer");
    }
    if (row.frame <= last_frame) {
      return err(line_no, "frame " + Excerpt(f[0]) +
                              (row.frame == last_frame ? " is repeated" : " is out of order") +
                              " (previous row is frame " + std::to_string(last_frame) + ")");
    }
    last_frame = row.frame;
    if (!ParseTableNumber(f[1], false, &row.time_s)) {
      return err(line_no, "time_s \"" + Excerpt(f[1]) + "\" is not a finite number");
    }
    if (f[2] == "ok") {
      row.status = RowStatus::kOk;
    } else if (f[2] == "lost") {
      row.status = RowStatus::kLost;
    } else {
      return err(line_no, "status \"" + Excerpt(f[2]) + "\" is neither ok nor lost");
    }
    double* values[8] = {&row.upper_deg, &row.fore_deg, &row.yaw_deg, &row.bend_deg,
                         &row.upper_cx,  &row.upper_cy, &row.fore_cx, &row.fore_cy};
    for (int i = 0; i < 8; ++i) {
      if (!ParseTableNumber(f[3 + i], true, values[i])) {
        return err(line_no, std::string(kAngleColumns[3 + i]) + " \"" + Excerpt(f[3 + i]) +
                                "\" is not a number (use '.' decimals, or nan)");
      }
      if (row.status == RowStatus::kLost && i < 4 && !std::isnan(*values[i])) {
        return err(line_no, std::string("status is lost but ") + kAngleColumns[3 + i] +
                                " is a number (lost rows carry nan angles)");
      }
    }
    for (int i = 0; i < 4; ++i) {
      if (!std::isnan(*values[i]) && (*values[i] <= -180.0 - 1e-9 || *values[i] > 180.0 + 1e-9)) {
        return err(line_no, std::string(kAngleColumns[3 + i]) + " " + Excerpt(f[3 + i]) +
                                " is outside (-180, 180]");
      }
    }
    if (!std::isnan(row.yaw_deg) && row.yaw_deg < 0) {
      return err(line_no, "yaw_deg " + Excerpt(f[5]) + " is negative (yaw is always >= 0)");
    }
    if (out->has_file_column) row.file = f[file_index];
    if (confidence_index > 0) {
      if (!ParseTableNumber(f[confidence_index], true, &row.confidence) ||
          (!std::isnan(row.confidence) && (row.confidence < 0 || row.confidence > 1))) {
        return err(line_no, "confidence \"" + Excerpt(f[confidence_index]) +
                                "\" is not a number in [0, 1] (or nan)");
      }
    }
    if (signed_yaw_index > 0) {
      const std::string& v = f[signed_yaw_index];
      if (!ParseTableNumber(v, true, &row.yaw_signed_deg)) {
        return err(line_no, std::string(kSignedYawColumn) + " \"" + v +
                                "\" is not a number (use '.' decimals, or nan)");
      }
      if (row.status == RowStatus::kLost && !std::isnan(row.yaw_signed_deg)) {
        return err(line_no, std::string("status is lost but ") + kSignedYawColumn +
                                " is a number (lost rows carry nan angles)");
      }
      if (!std::isnan(row.yaw_signed_deg) &&
          (row.yaw_signed_deg <= -180.0 - 1e-9 || row.yaw_signed_deg > 180.0 + 1e-9)) {
        return err(line_no,
                   std::string(kSignedYawColumn) + " " + Excerpt(v) + " is outside (-180, 180]");
      }
    }
    if (Status st = Parse3dColumns(f, index_3d, &row); !st) return err(line_no, st.message());
    out->rows.push_back(std::move(row));
  }
  if (!have_header) {
    return Status::Error(source_name +
                         ": no column header found (is this an armmimic angle file?)");
  }
  return Status::Ok();
}

Status ReadAngleFile(const std::string& path, AngleFile* out) {
  if (Status st = CheckInputFile(path); !st) return st;
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(path + ": cannot open (" + FileErrorText(errno) + ")");
  return ParseAngleFile(in, path, out);
}

struct AngleFileWriter::Impl {
  OutputFile file;
  std::string path;
  AngleMeta meta;
  bool file_column = false;
  bool confidence_column = false;
  bool signed_yaw_column = false;
  bool columns_3d = false;
  bool open = false;
  int rows = 0;
};

AngleFileWriter::AngleFileWriter() : impl_(std::make_unique<Impl>()) {}
AngleFileWriter::~AngleFileWriter() = default;

int AngleFileWriter::rows_written() const { return impl_->rows; }

namespace {
std::string HeaderText(const AngleMeta& meta, bool file_column, bool confidence_column,
                       bool signed_yaw_column, bool columns_3d) {
  std::string s =
      std::string(kAngleFileMagic) + "\n" + FormatMetaLine(meta) + "\n" + kAngleFileUnits + "\n";
  for (int i = 0; i < 11; ++i) s += (i ? "\t" : "") + std::string(kAngleColumns[i]);
  if (confidence_column) s += "\tconfidence";
  if (file_column) s += "\tfile";
  if (signed_yaw_column) s += std::string("\t") + kSignedYawColumn;
  if (columns_3d) {
    for (const char* c : kAngle3dColumns) s += std::string("\t") + c;
  }
  return s + "\n";
}
}  // namespace

Status AngleFileWriter::Open(const std::string& path, const AngleMeta& meta, bool file_column,
                             bool confidence_column, bool signed_yaw_column, bool columns_3d) {
  impl_ = std::make_unique<Impl>();
  Status st = impl_->file.Open(path);
  if (!st) return st;
  impl_->path = path;
  impl_->meta = meta;
  impl_->file_column = file_column;
  impl_->confidence_column = confidence_column;
  impl_->signed_yaw_column = signed_yaw_column;
  impl_->columns_3d = columns_3d;
  const std::string header =
      HeaderText(meta, file_column, confidence_column, signed_yaw_column, columns_3d);
  if (std::fputs(header.c_str(), impl_->file.file()) < 0) {
    return Status::Error(path + ": write failed (" + ErrnoText(errno) + ")");
  }
  impl_->open = true;
  return Status::Ok();
}

Status AngleFileWriter::Write(const AngleRow& row) {
  if (!impl_->open) return Status::Error("angle file is not open");
  if (impl_->file_column && row.file.find_first_of("\t\n\r") != std::string::npos) {
    return Status::Error(impl_->path + ": file name \"" + row.file +
                         "\" contains a tab or newline");
  }
  const std::string s = FormatAngleRow(row, impl_->file_column, impl_->confidence_column,
                                       impl_->signed_yaw_column, impl_->columns_3d) +
                        "\n";
  if (std::fputs(s.c_str(), impl_->file.file()) < 0) {
    return Status::Error(impl_->path + ": write failed (" + ErrnoText(errno) + ")");
  }
  ++impl_->rows;
  return Status::Ok();
}

Status AngleFileWriter::Commit(bool complete, const std::string& reason) {
  if (!impl_->open) return Status::Error("angle file is not open");
  impl_->open = false;
  if (complete) return impl_->file.Commit();
  if (!impl_->file.replacing()) {
    // A device or FIFO cannot be rewound: the rows went out as they came, and a last comment
    // line marks them, which ReadAngleFile() reads as complete=no too.
    std::fputs(kIncompleteMark, impl_->file.file());
    std::fputs("\n", impl_->file.file());
    return impl_->file.Commit();
  }
  // Rewrite with complete=no in the meta line, keeping every row written so far.
  std::fflush(impl_->file.file());
  OutputFile marked;
  Status st = marked.Open(impl_->path);
  if (!st) return st;
  AngleMeta meta = impl_->meta;
  meta.emplace_back("complete", "no");
  if (!reason.empty()) meta.emplace_back("incomplete", reason);
  const std::string header = HeaderText(meta, impl_->file_column, impl_->confidence_column,
                                        impl_->signed_yaw_column, impl_->columns_3d);
  std::fputs(header.c_str(), marked.file());
  std::ifstream rows(impl_->file.temp_path(), std::ios::binary);
  std::string line;
  int skip = 4;  // the header lines of the unmarked temporary
  while (std::getline(rows, line)) {
    if (skip > 0) {
      --skip;
      continue;
    }
    std::fputs((line + "\n").c_str(), marked.file());
  }
  impl_->file.Discard();
  return marked.Commit();
}

}  // namespace armmimic
