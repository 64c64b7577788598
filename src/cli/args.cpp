#include "args.h"

#include "armmimic/core/text.h"

#include <charconv>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace armmimic::cli {
namespace {

std::vector<std::string> SplitNames(const std::string& names) {
  std::vector<std::string> out;
  std::stringstream ss(names);
  std::string n;
  while (std::getline(ss, n, ',')) out.push_back(n);
  return out;
}

std::string LongName(const std::vector<std::string>& names) { return names.back(); }

}  // namespace

bool ParseDoubleArg(const std::string& value, double* out) { return ParseFiniteDouble(value, out); }

bool ParseIntArg(const std::string& value, int* out) {
  if (value.empty()) return false;
  const char* first = value.data();
  if (*first == '+') ++first;
  int v = 0;
  const auto r = std::from_chars(first, value.data() + value.size(), v, 10);
  if (r.ec != std::errc() || r.ptr != value.data() + value.size()) return false;
  *out = v;
  return true;
}

std::string ParsePointArg(const std::string& value, cv::Point2d* out) {
  const auto comma = value.find(',');
  double x = 0, y = 0;
  if (comma == std::string::npos || !ParseDoubleArg(value.substr(0, comma), &x) ||
      !ParseDoubleArg(value.substr(comma + 1), &y)) {
    return "'" + value + "' is not X,Y (two numbers, e.g. 160,80)";
  }
  *out = {x, y};
  return "";
}

std::string ParseRectArg(const std::string& value, cv::Rect* out) {
  std::vector<int> v;
  std::stringstream ss(value);
  std::string part;
  while (std::getline(ss, part, ',')) {
    int n = 0;
    if (!ParseIntArg(part, &n)) return "'" + value + "' is not X,Y,W,H (four whole numbers)";
    v.push_back(n);
  }
  if (v.size() != 4) return "'" + value + "' is not X,Y,W,H (four whole numbers)";
  if (v[0] < 0 || v[1] < 0 || v[2] <= 0 || v[3] <= 0) {
    return "'" + value + "' needs X,Y >= 0 and W,H > 0";
  }
  *out = cv::Rect(v[0], v[1], v[2], v[3]);
  return "";
}

std::string ParseSizeArg(const std::string& value, cv::Size* out) {
  const auto x = value.find_first_of("xX");
  int w = 0, h = 0;
  if (x == std::string::npos || !ParseIntArg(value.substr(0, x), &w) ||
      !ParseIntArg(value.substr(x + 1), &h) || w <= 0 || h <= 0) {
    return "'" + value + "' is not WxH (e.g. 320x240)";
  }
  *out = {w, h};
  return "";
}

std::string ParseSeedArg(const std::string& value, std::uint64_t* out) {
  std::uint64_t s = 0;
  const auto r = std::from_chars(value.data(), value.data() + value.size(), s, 10);
  if (value.empty() || r.ec != std::errc() || r.ptr != value.data() + value.size()) {
    return "'" + value + "' is not a non-negative whole number";
  }
  *out = s;
  return "";
}

ArgParser::ArgParser(std::string command, std::string synopsis, std::string description)
    : command_(std::move(command)),
      synopsis_(std::move(synopsis)),
      description_(std::move(description)) {}

void ArgParser::Flag(const std::string& names, bool* out, const std::string& help) {
  Switch(names, help, [out] { *out = true; });
}

void ArgParser::Switch(const std::string& names, const std::string& help,
                       std::function<void()> on) {
  Option o;
  o.names = SplitNames(names);
  o.help = help;
  o.on_switch = std::move(on);
  options_.push_back(std::move(o));
}

void ArgParser::Custom(const std::string& names, const std::string& metavar,
                       const std::string& help,
                       std::function<std::string(const std::string&)> parse) {
  Option o;
  o.names = SplitNames(names);
  o.metavar = metavar.empty() ? "VALUE" : metavar;
  o.help = help;
  o.parse = std::move(parse);
  options_.push_back(std::move(o));
}

void ArgParser::String(const std::string& names, std::string* out, const std::string& metavar,
                       const std::string& help) {
  Custom(names, metavar, help, [out](const std::string& v) {
    *out = v;
    return std::string();
  });
}

void ArgParser::Int(const std::string& names, int* out, const std::string& metavar,
                    const std::string& help, int min_value, int max_value) {
  Custom(names, metavar, help, [out, min_value, max_value](const std::string& v) {
    int n = 0;
    if (!ParseIntArg(v, &n)) return "'" + v + "' is not a whole number";
    if (n < min_value || n > max_value) {
      return "'" + v + "' is out of range [" + std::to_string(min_value) + ", " +
             std::to_string(max_value) + "]";
    }
    *out = n;
    return std::string();
  });
}

void ArgParser::Double(const std::string& names, double* out, const std::string& metavar,
                       const std::string& help) {
  Custom(names, metavar, help, [out](const std::string& v) {
    double d = 0;
    if (!ParseDoubleArg(v, &d)) return "'" + v + "' is not a number (use '.' decimals)";
    *out = d;
    return std::string();
  });
}

void ArgParser::Positionals(std::vector<std::string>* out, const std::string& metavar,
                            int min_count, int max_count) {
  positionals_ = out;
  positional_metavar_ = metavar;
  positional_min_ = min_count;
  positional_max_ = max_count;
}

const ArgParser::Option* ArgParser::FindOption(const std::string& name) const {
  for (const auto& o : options_) {
    for (const auto& n : o.names) {
      if (n == name) return &o;
    }
  }
  return nullptr;
}

bool ArgParser::Given(const std::string& long_name) const { return given_.count(long_name) > 0; }

int ArgParser::UsageError(const std::string& message) const {
  std::cerr << "armmimic-cli " << command_ << ": " << message << "\n"
            << "Try 'armmimic-cli " << command_ << " --help'.\n";
  return 2;
}

std::string ArgParser::Help() const {
  std::ostringstream out;
  out << "Usage:\n" << synopsis_ << "\n\n" << description_ << "\n";
  if (!options_.empty()) out << "\nOptions:\n";
  for (const auto& o : options_) {
    std::string left = "  ";
    for (std::size_t i = 0; i < o.names.size(); ++i) left += (i ? ", " : "") + o.names[i];
    if (!o.metavar.empty()) left += " " + o.metavar;
    out << left;
    if (left.size() < 30) {
      out << std::string(30 - left.size(), ' ');
    } else {
      out << "\n" << std::string(30, ' ');
    }
    out << o.help << "\n";
  }
  out << "  -h, --help" << std::string(18, ' ') << "show this help\n";
  out << "\nGlobal: -q (quiet), --progress / --no-progress, --version.\n";
  return out.str();
}

std::optional<int> ArgParser::Parse(const std::vector<std::string>& args) {
  std::vector<std::string> positional;
  bool only_positional = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (only_positional || a.size() < 2 || a[0] != '-' ||
        (a[1] != '-' && (std::isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.'))) {
      positional.push_back(a);
      continue;
    }
    if (a == "--") {
      only_positional = true;
      continue;
    }
    if (a == "-h" || a == "--help") {
      std::cout << Help();
      return 0;
    }
    std::string name = a;
    std::optional<std::string> inline_value;
    const auto eq = a.find('=');
    if (a.rfind("--", 0) == 0 && eq != std::string::npos) {
      name = a.substr(0, eq);
      inline_value = a.substr(eq + 1);
    }
    const Option* o = FindOption(name);
    if (!o) return UsageError("unknown option " + name);
    given_.insert(LongName(o->names));
    if (o->on_switch) {
      if (inline_value) return UsageError(name + " takes no value");
      o->on_switch();
      continue;
    }
    std::string value;
    if (inline_value) {
      value = *inline_value;
    } else {
      if (i + 1 >= args.size()) return UsageError(name + " needs a value " + o->metavar);
      value = args[++i];
    }
    const std::string error = o->parse(value);
    if (!error.empty()) return UsageError(name + ": " + error);
  }
  const int n = static_cast<int>(positional.size());
  if (!positionals_ && n > 0) return UsageError("unexpected argument '" + positional[0] + "'");
  if (positionals_) {
    if (n < positional_min_) {
      return UsageError("missing " + positional_metavar_ + " (see the usage)");
    }
    if (positional_max_ >= 0 && n > positional_max_) {
      return UsageError("unexpected argument '" + positional[positional_max_] + "'");
    }
    *positionals_ = positional;
  }
  return std::nullopt;
}

}  // namespace armmimic::cli
