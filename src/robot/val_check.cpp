// The safety check of VAL lines before they are sent: every command the checker understands,
// the joint limits, the speed limits and the EDIT ... E / EXECUTE bookkeeping, kept in a
// SafetyState from one line to the next.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "armmimic/core/text.h"
#include "armmimic/robot/val_program.h"
#include "val_text.h"

namespace armmimic::robot {
namespace {

using val_text::Num;
using val_text::ParseDouble;
using val_text::ParseList;

std::string Upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// The command keywords the checker understands. A keyword may be abbreviated to any prefix of two
// letters or more that is unique among them (VAL accepts unique prefixes); "E" alone leaves the
// editor.
enum class Keyword { kNone, kDo, kDrive, kEdit, kExecute, kMove, kSpeed, kEndEdit };

Keyword MatchKeyword(const std::string& token) {
  const std::string t = Upper(token);
  if (t == "E") return Keyword::kEndEdit;
  if (t.size() < 2) return Keyword::kNone;
  static const std::pair<const char*, Keyword> kWords[] = {
      {"DO", Keyword::kDo},           {"DRIVE", Keyword::kDrive}, {"EDIT", Keyword::kEdit},
      {"EXECUTE", Keyword::kExecute}, {"MOVE", Keyword::kMove},   {"SPEED", Keyword::kSpeed}};
  Keyword found = Keyword::kNone;
  int matches = 0;
  for (const auto& [word, kw] : kWords) {
    if (std::string(word).rfind(t, 0) == 0) {
      found = kw;
      ++matches;
    }
  }
  return matches == 1 ? found : Keyword::kNone;
}

// Splits "WORD rest" at the first space.
void SplitWord(const std::string& text, std::string* word, std::string* rest) {
  const auto sp = text.find(' ');
  *word = text.substr(0, sp);
  *rest = sp == std::string::npos ? "" : Trim(text.substr(sp + 1));
}

bool ValidName(const std::string& name) {
  if (name.empty() || name.size() > 15) return false;
  for (char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.') return false;
  }
  return true;
}

Status CheckSpeedSetting(double monitor_pct, double program_pct, const SafetyState& s) {
  const double eff = (std::isnan(monitor_pct) ? 100.0 : monitor_pct) * program_pct / 100.0;
  for (int j = 0; j < kJoints; ++j) {
    const double joint_speed = eff / 100.0 * s.joint_speed_at_100_deg_s[j];
    if (joint_speed > s.limits.max_speed_deg_s[j] * (1 + 1e-9)) {
      return Status::Error("speed " + Num(eff) + "% would let J" + std::to_string(j + 1) +
                           " move at " + Num(joint_speed) + " deg/s, over its limit of " +
                           Num(s.limits.max_speed_deg_s[j]) + " deg/s");
    }
  }
  return Status::Ok();
}

Status CheckTarget(const JointArray& target, double time_s, SafetyState& s) {
  if (std::isnan(s.monitor_speed_pct)) {
    return Status::Error("motion before any SPEED line: the controller's speed is unknown");
  }
  for (int j = 0; j < kJoints; ++j) {
    if (target[j] < s.limits.min_deg[j] || target[j] > s.limits.max_deg[j]) {
      return Status::Error("J" + std::to_string(j + 1) + " target " + Num(target[j]) +
                           " is outside the limit " + DescribeLimit(s.limits, j));
    }
  }
  if (!std::isnan(time_s) && !std::isnan(s.last_time_s) && s.have_position) {
    const double dt = time_s - s.last_time_s;
    if (!(dt > 0)) {
      return Status::Error("t=" + Num(time_s) +
                           " is not after the previous move's t=" + Num(s.last_time_s));
    }
    for (int j = 0; j < kJoints; ++j) {
      const double delta = std::abs(target[j] - s.last_deg[j]);
      if (delta > s.limits.max_speed_deg_s[j] * dt + s.tolerance_deg) {
        return Status::Error("J" + std::to_string(j + 1) + " moves " + Num(delta) + " deg in " +
                             Num(dt) + " s (" + Num(delta / dt) + " deg/s), over its limit of " +
                             Num(s.limits.max_speed_deg_s[j]) + " deg/s");
      }
    }
  }
  s.last_deg = target;
  s.have_position = true;
  if (!std::isnan(time_s)) s.last_time_s = time_s;
  return Status::Ok();
}

// MOVE #PPOINT(j1,...,j6): six numbers, a target inside the limits, reached within the speed
// limits from the last checked position (CheckTarget).
Status CheckMove(const std::string& cmd, const std::string& rest, double time_s,
                 SafetyState& state) {
  const std::string u = Upper(rest);
  if (u.rfind("#PPOINT", 0) != 0) {
    return Status::Error(cmd + "only moves to #PPOINT(j1,...,j6) can be checked");
  }
  std::string args = Trim(rest.substr(7));
  if (args.size() < 2 || args.front() != '(' || args.back() != ')') {
    return Status::Error(cmd + "expected #PPOINT(j1,j2,j3,j4,j5,j6)");
  }
  std::vector<double> v;
  if (!ParseList(args.substr(1, args.size() - 2), &v) || v.size() != kJoints) {
    return Status::Error(cmd + "#PPOINT needs six numbers");
  }
  JointArray target{};
  std::copy(v.begin(), v.end(), target.begin());
  const Status s = CheckTarget(target, time_s, state);
  return s.ok() ? s : Status::Error(cmd + s.message());
}

// DRIVE joint,change,speed: from a known position, inside the joint's limit and speed limit.
Status CheckDrive(const std::string& cmd, const std::string& rest, SafetyState& state) {
  std::vector<double> v;
  if (!ParseList(rest, &v) || v.size() != 3) {
    return Status::Error(cmd + "expected DRIVE joint,change,speed");
  }
  // Range first: converting a double outside int's range is undefined.
  if (!(v[0] >= 1 && v[0] <= kJoints) || v[0] != std::floor(v[0])) {
    return Status::Error(cmd + "joint must be 1..6");
  }
  const int joint = static_cast<int>(v[0]);
  if (!(v[2] > 0 && v[2] <= 100)) return Status::Error(cmd + "speed must be in (0,100]");
  if (!state.have_position) {
    return Status::Error(cmd + "DRIVE needs a known joint position (send a checked MOVE first)");
  }
  if (std::isnan(state.monitor_speed_pct)) {
    return Status::Error(cmd + "motion before any SPEED line: the controller's speed is unknown");
  }
  const int j = joint - 1;
  const double target = state.last_deg[j] + v[1];
  if (!state.limits.Inside(j, target)) {
    return Status::Error(cmd + "J" + std::to_string(joint) + " would reach " + Num(target) +
                         ", outside the limit " + DescribeLimit(state.limits, j));
  }
  const double joint_speed =
      state.monitor_speed_pct / 100.0 * v[2] / 100.0 * state.joint_speed_at_100_deg_s[j];
  if (joint_speed > state.limits.max_speed_deg_s[j] * (1 + 1e-9)) {
    return Status::Error(cmd + "J" + std::to_string(joint) + " would move at " + Num(joint_speed) +
                         " deg/s, over its limit of " + Num(state.limits.max_speed_deg_s[j]) +
                         " deg/s");
  }
  state.last_deg[j] = target;
  state.last_time_s = kNaN;  // a DRIVE takes its own time
  return Status::Ok();
}

// SPEED pct: the monitor speed, or the program speed inside EDIT ... E or after DO; either way
// no joint may then move faster than its limit.
Status CheckSpeed(const std::string& cmd, const std::string& rest, bool via_do,
                  SafetyState& state) {
  double pct = 0;
  if (!ParseDouble(rest, &pct) || !(pct > 0)) {
    return Status::Error(cmd + "expected SPEED followed by one number > 0");
  }
  const bool program_speed = via_do || state.in_editor;
  const double monitor = program_speed ? state.monitor_speed_pct : pct;
  const double prog = program_speed ? pct : state.program_speed_pct;
  const Status s = CheckSpeedSetting(monitor, prog, state);
  if (!s.ok()) return Status::Error(cmd + s.message());
  if (program_speed) {
    state.program_speed_pct = pct;
  } else {
    state.monitor_speed_pct = pct;
  }
  return Status::Ok();
}

}  // namespace

SafetyState SafetyState::For(const JointLimits& limits, const ControllerProfile& profile) {
  SafetyState s;
  s.limits = limits;
  s.joint_speed_at_100_deg_s = profile.joint_speed_at_100_deg_s;
  s.max_line_length = profile.max_line_length;
  const double step = std::pow(10.0, -profile.decimals);
  s.tolerance_deg = std::max(0.011, 1.1 * step);
  return s;
}

Status CheckLine(const std::string& line, SafetyState& state) {
  return CheckLine(line, kNaN, state);
}

Status CheckLine(const std::string& raw_line, double time_s, SafetyState& state) {
  if (static_cast<int>(raw_line.size()) > state.max_line_length) {
    return Status::Error("line is " + std::to_string(raw_line.size()) +
                         " characters, over the limit of " + std::to_string(state.max_line_length));
  }
  for (unsigned char c : raw_line) {
    if (c < 0x20 || c >= 0x7f) return Status::Error("control or non-ASCII character in the line");
  }
  const std::string line = Trim(raw_line);
  if (line.empty()) return Status::Ok();
  if (line[0] == ';') return Status::Error("comment lines are never sent");

  std::string word, rest;
  SplitWord(line, &word, &rest);
  Keyword kw = MatchKeyword(word);
  bool via_do = false;
  if (kw == Keyword::kDo) {
    via_do = true;
    SplitWord(rest, &word, &rest);
    kw = MatchKeyword(word);
    if (kw != Keyword::kMove && kw != Keyword::kDrive && kw != Keyword::kSpeed) {
      return Status::Error("'" + line + "': only DO MOVE, DO DRIVE and DO SPEED can be checked");
    }
  }
  const std::string cmd = "'" + line + "': ";
  switch (kw) {
    case Keyword::kMove:
      return CheckMove(cmd, rest, time_s, state);
    case Keyword::kDrive:
      return CheckDrive(cmd, rest, state);
    case Keyword::kSpeed:
      return CheckSpeed(cmd, rest, via_do, state);
    case Keyword::kEdit:
      if (state.in_editor) return Status::Error(cmd + "EDIT while already editing");
      if (!ValidName(rest)) return Status::Error(cmd + "expected EDIT followed by a program name");
      state.in_editor = true;
      state.edited_programs.insert(Upper(rest));
      return Status::Ok();
    case Keyword::kEndEdit:
      if (!rest.empty() || !state.in_editor) {
        return Status::Error(cmd + "E (leave the editor) outside EDIT ... E");
      }
      state.in_editor = false;
      return Status::Ok();
    case Keyword::kExecute:
      if (state.in_editor) return Status::Error(cmd + "EXECUTE inside EDIT ... E");
      if (!state.edited_programs.count(Upper(rest))) {
        return Status::Error(cmd +
                             "only a program uploaded and checked in this run may be executed");
      }
      if (std::isnan(state.monitor_speed_pct)) {
        return Status::Error(cmd +
                             "EXECUTE before any SPEED line: the controller's speed is unknown");
      }
      return Status::Ok();
    default:
      return Status::Error(cmd + "not a command the safety check can verify; it is not sent");
  }
}

Status CheckProgram(const ValProgram& program, SafetyState& state) {
  for (const ValLine& l : program.lines) {
    const Status s = CheckLine(l.text, l.time_s, state);
    if (!s.ok()) {
      return Status::Error(program.source_name + ":" + std::to_string(l.line_no) + ": " +
                           s.message());
    }
  }
  return Status::Ok();
}

}  // namespace armmimic::robot
