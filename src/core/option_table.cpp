// The non-template helpers of the option tables (option_table.h).
#include "armmimic/core/option_table.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/text.h"

namespace armmimic {

std::string OptionNumberText(double v) {
  std::string text = FormatNumber(v, 6);  // shortest form: 0.300000 -> 0.3
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

std::string OptionExactNumberText(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

bool ParseOptionBool(const std::string& text, bool* out) {
  std::string t;
  for (char c : text) t += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (t == "true" || t == "on" || t == "1") {
    *out = true;
    return true;
  }
  if (t == "false" || t == "off" || t == "0") {
    *out = false;
    return true;
  }
  return false;
}

bool ParseOptionNumber(const std::string& text, double* out) {
  return ParseFiniteDouble(text, out);
}

std::string OptionRefusedNumberText(double v) {
  if (std::isnan(v)) return "nan";
  const std::string shortest = OptionNumberText(v);
  double back = 0;
  if (ParseFiniteDouble(shortest, &back) && back == v) return shortest;
  return OptionExactNumberText(v);
}

std::string OptionNoun(const std::string& label) {
  std::string noun = label;
  if (!noun.empty()) noun[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(noun[0])));
  return noun;
}

}  // namespace armmimic
