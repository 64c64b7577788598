// VAL program text: reading a program file (commands, timing comments, header limits) and
// writing one from a trajectory. The safety check of each line is in val_check.cpp.
#include "armmimic/robot/val_program.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/text.h"
#include "val_text.h"

namespace armmimic::robot {
namespace val_text {

// Plain decimal numbers only ([+-]digits[.digits]): no exponent, hex, inf or nan, so the value
// checked is the value any controller reads.
bool ParseDouble(const std::string& text, double* out) {
  const std::string t = Trim(text);
  if (t.empty()) return false;
  std::size_t i = (t[0] == '+' || t[0] == '-') ? 1 : 0;
  int digits = 0, dots = 0;
  for (; i < t.size(); ++i) {
    if (std::isdigit(static_cast<unsigned char>(t[i]))) {
      ++digits;
    } else if (t[i] == '.' && dots == 0) {
      ++dots;
    } else {
      return false;
    }
  }
  if (digits == 0) return false;
  const char* first = t.data();
  const char* last = t.data() + t.size();
  if (*first == '+') ++first;
  double v = 0;
  const auto r = std::from_chars(first, last, v);
  if (r.ec != std::errc() || r.ptr != last || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

bool ParseList(const std::string& text, std::vector<double>* out) {
  out->clear();
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) {
    double v = 0;
    if (!ParseDouble(part, &v)) return false;
    out->push_back(v);
  }
  return !text.empty() && text.back() != ',';
}

std::string Num(double v) {
  // Short form for messages: up to three decimals, trailing zeros dropped.
  std::string s = FormatNumber(v, 3);
  while (s.find('.') != std::string::npos && (s.back() == '0' || s.back() == '.')) {
    const bool dot = s.back() == '.';
    s.pop_back();
    if (dot) break;
  }
  return s;
}

}  // namespace val_text
namespace {

using val_text::Num;
using val_text::ParseDouble;
using val_text::ParseList;

std::string Replace(std::string text, const std::string& key, const std::string& value) {
  const std::string token = "{" + key + "}";
  for (auto pos = text.find(token); pos != std::string::npos; pos = text.find(token, pos)) {
    text.replace(pos, token.size(), value);
    pos += value.size();
  }
  return text;
}

std::string JoinJoints(const JointArray& values, int decimals) {
  std::string s;
  for (int j = 0; j < kJoints; ++j) {
    if (j) s += ',';
    s += FormatJointDeg(values[j], decimals);
  }
  return s;
}

std::string FormatSeconds(double s) { return FormatNumber(s, 3); }

// Rounds up to whole milliseconds (times are written with three decimals).
double CeilMs(double s) { return std::ceil(s * 1000.0 - 1e-6) / 1000.0; }

double RoundTo(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

// The limits a program's header records (limits_min_deg, limits_max_deg, speed_limit_deg_s):
// all three or none, six numbers each, and limits that pass their own check.
Status ReadHeaderLimits(const std::string& source_name, ValProgram* p) {
  const auto min_it = p->header.find("limits_min_deg");
  const auto max_it = p->header.find("limits_max_deg");
  const auto speed_it = p->header.find("speed_limit_deg_s");
  const int present =
      (min_it != p->header.end()) + (max_it != p->header.end()) + (speed_it != p->header.end());
  if (present > 0) {
    std::vector<double> mins, maxs, speeds;
    if (present != 3 || !ParseList(min_it->second, &mins) || !ParseList(max_it->second, &maxs) ||
        !ParseList(speed_it->second, &speeds) || mins.size() != kJoints || maxs.size() != kJoints ||
        speeds.size() != kJoints) {
      return Status::Error(source_name +
                           ": header limits need limits_min_deg, limits_max_deg and "
                           "speed_limit_deg_s, six comma-separated numbers each");
    }
    JointLimits lim;
    std::copy(mins.begin(), mins.end(), lim.min_deg.begin());
    std::copy(maxs.begin(), maxs.end(), lim.max_deg.begin());
    std::copy(speeds.begin(), speeds.end(), lim.max_speed_deg_s.begin());
    const Status check = lim.Check();
    if (!check.ok()) return Status::Error(source_name + ": header limits: " + check.message());
    p->header_limits = lim;
    p->has_header_limits = true;
  }
  return Status::Ok();
}

}  // namespace

std::string FormatJointDeg(double deg, int decimals) { return FormatNumber(deg, decimals); }

int SpeedSettingFor(const JointLimits& limits, const ControllerProfile& profile) {
  double pct = 100;
  for (int j = 0; j < kJoints; ++j) {
    pct = std::min(pct, 100.0 * limits.max_speed_deg_s[j] / profile.joint_speed_at_100_deg_s[j]);
  }
  return std::max(1, static_cast<int>(std::floor(pct + 1e-9)));
}

Status ParseValProgram(std::istream& in, const std::string& source_name, int max_line_length,
                       ValProgram* out) {
  ValProgram p;
  p.source_name = source_name;
  std::string raw;
  int line_no = 0;
  double pending_time = kNaN;
  int pending_line = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    if (line_no == 1) StripUtf8Bom(&raw);
    const std::string where = source_name + ":" + std::to_string(line_no) + ": ";
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    for (unsigned char c : raw) {
      if ((c < 0x20 && c != '\t') || c >= 0x7f) {
        return Status::Error(where + "non-ASCII or control character (VAL lines are plain ASCII)");
      }
    }
    const std::string line = Trim(raw);
    if (line.empty()) continue;
    if (line[0] == ';') {
      const std::string text = Trim(line.substr(1));
      p.comments.emplace_back(line_no, text);
      if (text.rfind("t=", 0) == 0 && text.find(' ') == std::string::npos) {
        double t = 0;
        if (!ParseDouble(text.substr(2), &t) || t < 0) {
          return Status::Error(where + "'; " + text + "' is not a timing comment (; t=SECONDS)");
        }
        if (!std::isnan(pending_time)) {
          return Status::Error(source_name + ":" + std::to_string(pending_line) +
                               ": timing comment not followed by a command line");
        }
        pending_time = t;
        pending_line = line_no;
      } else if (p.lines.empty() && line_no > 1) {
        std::stringstream ss(text);
        std::string token;
        while (ss >> token) {
          const auto eq = token.find('=');
          if (eq != std::string::npos && eq > 0)
            p.header[token.substr(0, eq)] = token.substr(eq + 1);
        }
      }
      continue;
    }
    if (static_cast<int>(line.size()) > max_line_length) {
      return Status::Error(where + "line is " + std::to_string(line.size()) +
                           " characters, over the controller's limit of " +
                           std::to_string(max_line_length));
    }
    ValLine l;
    l.line_no = line_no;
    l.text = line;
    l.time_s = pending_time;
    pending_time = kNaN;
    p.lines.push_back(l);
  }
  if (in.bad()) return Status::Error(source_name + ": read error");
  if (!std::isnan(pending_time)) {
    return Status::Error(source_name + ":" + std::to_string(pending_line) +
                         ": timing comment not followed by a command line");
  }
  if (p.lines.empty()) return Status::Error(source_name + ": no command lines to send");
  const Status limits = ReadHeaderLimits(source_name, &p);
  if (!limits.ok()) return limits;
  *out = std::move(p);
  return Status::Ok();
}

Status ReadValProgram(const std::string& path, ValProgram* out, int max_line_length) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(path + ": cannot open the VAL program");
  return ParseValProgram(in, path, max_line_length, out);
}

Status FormatValProgram(const Trajectory& trajectory, const ControllerProfile& profile,
                        const JointLimits& limits, const std::vector<std::string>& header,
                        std::string* text) {
  if (trajectory.keyframes.empty()) return Status::Error("the trajectory has no keyframes");
  const int speed = SpeedSettingFor(limits, profile);
  const int dec = profile.decimals;
  std::string out;
  auto comment = [&](const std::string& c) { out += "; " + c + "\n"; };
  Status status;
  auto command = [&](const std::string& line, const std::string& what) {
    if (static_cast<int>(line.size()) > profile.max_line_length) {
      if (status.ok()) {
        status = Status::Error(what + ": '" + line + "' is " + std::to_string(line.size()) +
                               " characters, over the profile's max_line_length of " +
                               std::to_string(profile.max_line_length));
      }
    }
    out += line + "\n";
  };
  auto list = [&](const JointArray& v) { return JoinJoints(v, 2); };

  out += std::string(kValMagic) + "\n";
  for (const std::string& h : header) comment(h);
  comment("limits_min_deg=" + list(limits.min_deg));
  comment("limits_max_deg=" + list(limits.max_deg));
  comment("speed_limit_deg_s=" + list(limits.max_speed_deg_s));
  comment("profile=" + profile.name + " mode=" + SendModeName(profile.mode) + " speed=" +
          std::to_string(speed) + " keyframes=" + std::to_string(trajectory.keyframes.size()));
  command(Replace(profile.speed_template, "speed", std::to_string(speed)), "speed line");
  const bool program = profile.mode == SendMode::kProgram;
  if (program) command(Replace(profile.edit_template, "name", profile.program_name), "edit line");

  JointArray prev{};
  double prev_t = 0;
  for (std::size_t k = 0; k < trajectory.keyframes.size(); ++k) {
    const Keyframe& kf = trajectory.keyframes[k];
    JointArray rounded{};
    for (int j = 0; j < kJoints; ++j) {
      rounded[j] = RoundTo(kf.joint_deg[j], dec);
      if (!std::isfinite(kf.joint_deg[j]) || rounded[j] < limits.min_deg[j] ||
          rounded[j] > limits.max_deg[j]) {
        return Status::Error("keyframe " + std::to_string(k) + " (frame " +
                             std::to_string(kf.frame) + "): J" + std::to_string(j + 1) +
                             " target " + Num(kf.joint_deg[j]) + " is outside " +
                             DescribeLimit(limits, j));
      }
    }
    // Written times are whole milliseconds, and never closer than the speed limits allow for
    // the written (rounded) angles, so that send's check of this very file passes.
    double t = CeilMs(kf.time_s);
    if (k > 0) {
      double need = 0;
      for (int j = 0; j < kJoints; ++j) {
        need = std::max(need, std::abs(rounded[j] - prev[j]) / limits.max_speed_deg_s[j]);
      }
      t = std::max({t, CeilMs(prev_t + need), prev_t + 0.001});
    }
    comment("t=" + FormatSeconds(t));
    std::string line = program ? profile.program_move_template : profile.move_template;
    for (int j = 0; j < kJoints; ++j) {
      line = Replace(line, "j" + std::to_string(j + 1), FormatJointDeg(rounded[j], dec));
    }
    command(line, "keyframe " + std::to_string(k));
    prev = rounded;
    prev_t = t;
  }
  if (program) {
    command(profile.end_edit_line, "end edit line");
    command(Replace(profile.execute_template, "name", profile.program_name), "execute line");
  }
  if (!status.ok()) return status;
  *text = std::move(out);
  return Status::Ok();
}

std::string FormatSpeedLine(int speed, const ControllerProfile& profile) {
  return Replace(profile.speed_template, "speed", std::to_string(speed));
}

std::string FormatMoveLine(const JointArray& target_deg, const ControllerProfile& profile) {
  std::string line = profile.move_template;
  for (int j = 0; j < kJoints; ++j) {
    line = Replace(line, "j" + std::to_string(j + 1),
                   FormatJointDeg(RoundTo(target_deg[j], profile.decimals), profile.decimals));
  }
  return line;
}

}  // namespace armmimic::robot
