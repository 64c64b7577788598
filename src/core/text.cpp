#include "armmimic/core/text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <istream>
#include <limits>
#include <system_error>

namespace armmimic {

std::vector<std::string> SplitTabs(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = line.find('\t', start);
    if (tab == std::string::npos) {
      out.push_back(line.substr(start));
      return out;
    }
    out.push_back(line.substr(start, tab - start));
    start = tab + 1;
  }
}

bool ParseTableNumber(const std::string& field, bool allow_nan, double* out) {
  if (field == "nan") {
    if (!allow_nan) return false;
    *out = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  if (field.empty() || field[0] == '+') return false;
  // from_chars accepts "inf"/"infinity"/"nan(...)": allow only the characters of a decimal.
  for (char c : field) {
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == 'e' || c == 'E' || c == '+')) {
      return false;
    }
  }
  double v = 0;
  const char* last = field.data() + field.size();
  const auto r = std::from_chars(field.data(), last, v, std::chars_format::general);
  if (r.ec != std::errc() || r.ptr != last || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

bool ParseFrameIndex(const std::string& field, int* out) {
  if (field.empty() || field.size() > 10) return false;
  int v = 0;
  const char* last = field.data() + field.size();
  const auto r = std::from_chars(field.data(), last, v, 10);
  if (r.ec != std::errc() || r.ptr != last || v < 0) return false;
  *out = v;
  return true;
}

bool ParseFiniteDouble(const std::string& text, double* out) {
  if (text.empty()) return false;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (*first == '+') ++first;
  double v = 0;
  const auto r = std::from_chars(first, last, v);
  if (r.ec != std::errc() || r.ptr != last || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

void StripUtf8Bom(std::string* line) {
  if (line->size() >= 3 && line->compare(0, 3, "\xEF\xBB\xBF") == 0) line->erase(0, 3);
}

std::string Trim(const std::string& text) {
  const auto a = text.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = text.find_last_not_of(" \t\r");
  return text.substr(a, b - a + 1);
}

std::string PercentEncode(const std::string& value) {
  std::string out;
  for (char c : value) {
    switch (c) {
      case ' ':
        out += "%20";
        break;
      case '%':
        out += "%25";
        break;
      case '\t':
        out += "%09";
        break;
      case '\n':
        out += "%0A";
        break;
      case '\r':
        out += "%0D";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string PercentDecode(const std::string& value) {
  std::string out;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (value[i] == '%' && i + 2 < value.size()) {
      int code = 0;
      const auto r = std::from_chars(value.data() + i + 1, value.data() + i + 3, code, 16);
      if (r.ec == std::errc() && r.ptr == value.data() + i + 3) {
        out += static_cast<char>(code);
        i += 2;
        continue;
      }
    }
    out += value[i];
  }
  return out;
}

std::string Excerpt(const std::string& text, std::size_t max_chars) {
  std::string out;
  std::size_t shown = 0;
  for (; shown < text.size(); ++shown) {
    const auto c = static_cast<unsigned char>(text[shown]);
    // Never cut inside a UTF-8 sequence: its continuation bytes (10xxxxxx) follow their lead.
    if (out.size() >= max_chars && (c & 0xC0) != 0x80) break;
    if (c == '\t') {
      out += "\\t";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02X", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (shown < text.size()) out += "... (" + std::to_string(text.size()) + " characters)";
  return out;
}

std::string EscapeTsvField(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '\\':
        out += "\\\\";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string UnescapeTsvField(const std::string& field) {
  std::string out;
  out.reserve(field.size());
  for (std::size_t i = 0; i < field.size(); ++i) {
    const char next = i + 1 < field.size() ? field[i + 1] : '\0';
    if (field[i] != '\\' || (next != '\\' && next != 't' && next != 'n' && next != 'r')) {
      out += field[i];
      continue;
    }
    out += next == 't' ? '\t' : next == 'n' ? '\n' : next == 'r' ? '\r' : '\\';
    ++i;
  }
  return out;
}

std::string ErrnoText(int err) { return std::generic_category().message(err); }

bool ReadTextLine(std::istream& in, std::string* line, std::size_t max_length, bool* too_long) {
  line->clear();
  bool got_any = false;
  for (int c = in.get(); c != std::char_traits<char>::eof(); c = in.get()) {
    got_any = true;
    if (c == '\n') break;
    if (c == '\r') {
      if (in.peek() == '\n') in.get();
      break;
    }
    if (line->size() > max_length) {
      if (too_long) *too_long = true;
      continue;
    }
    *line += static_cast<char>(c);
  }
  return got_any;
}

}  // namespace armmimic
