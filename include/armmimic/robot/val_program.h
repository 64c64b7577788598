// VAL program text: writing a trajectory as a .val file, reading a .val back, and the safety
// checker send runs on every line right before it reaches the port.
//
// .val layout (docs/robot.md):
//   ; armmimic VAL program v1                      <- magic comment
//   ; key=value ...                                 <- header: source, mapping, filter, limits
//   SPEED 75                                        <- monitor speed, before any motion
//   ; t=0.000                                       <- timing of the next motion line (seconds)
//   DO MOVE #PPOINT(0.00,-90.00,0.00,0.00,0.00,0.00)
// Lines starting with ';' are comments, never sent. Every other non-blank line is sent as is.
#pragma once

#include <iosfwd>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "armmimic/core/angles.h"
#include "armmimic/core/status.h"
#include "armmimic/robot/limits.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/trajectory.h"

namespace armmimic::robot {

inline constexpr const char* kValMagic = "; armmimic VAL program v1";

struct ValLine {
  int line_no = 0;       // 1-based line in the file (for messages)
  std::string text;      // exactly what is sent, without the terminator
  double time_s = kNaN;  // from a "; t=..." comment right before it; NaN when absent
};

struct ValProgram {
  std::string source_name;
  std::vector<ValLine> lines;                         // the lines to send, in order
  std::vector<std::pair<int, std::string>> comments;  // (line_no, text after ';', trimmed)
  // "; key=value" pairs of the header (comments before the first sent line).
  std::map<std::string, std::string> header;
  // The limits recorded in the header (limits_min_deg, limits_max_deg, speed_limit_deg_s), when
  // all three are present and valid.
  bool has_header_limits = false;
  JointLimits header_limits;
};

// Strict reader: a line longer than `max_line_length`, a control character, or a malformed
// "; t=" or header limits comment is an error naming "file:line". An empty program is an error.
Status ParseValProgram(std::istream& in, const std::string& source_name, int max_line_length,
                       ValProgram* out);
Status ReadValProgram(const std::string& path, ValProgram* out, int max_line_length = 80);

// Joint angle as written in VAL text: '.' decimals whatever the locale, fixed decimals, no "-0".
std::string FormatJointDeg(double deg, int decimals);

// The SPEED setting (1..100) that keeps every joint at or under its speed limit, given the
// profile's joint speeds at SPEED 100.
int SpeedSettingFor(const JointLimits& limits, const ControllerProfile& profile);

// One line of the profile's templates: the monitor SPEED line, and a stream-mode move (the
// profile's move_template with the targets written at its decimals).
std::string FormatSpeedLine(int speed, const ControllerProfile& profile);
std::string FormatMoveLine(const JointArray& target_deg, const ControllerProfile& profile);

// Writes a trajectory as .val text in the profile's mode. `header` lines are written as "; "
// comments after the magic line (each "key=value ..."); the limits are added to the header.
// Fails (naming the keyframe) when a line would exceed the profile's max_line_length or a
// target is outside `limits`.
Status FormatValProgram(const Trajectory& trajectory, const ControllerProfile& profile,
                        const JointLimits& limits, const std::vector<std::string>& header,
                        std::string* text);

// What the safety checker knows while lines go out.
struct SafetyState {
  JointLimits limits;
  JointArray joint_speed_at_100_deg_s = ControllerProfile().joint_speed_at_100_deg_s;
  int max_line_length = 80;
  double tolerance_deg = 0.011;  // slack for the written rounding of angles and times

  // Tracked as lines pass.
  bool have_position = false;  // last_deg is known (after the first checked move)
  JointArray last_deg{};
  double last_time_s = kNaN;              // time of the last timed move
  double monitor_speed_pct = kNaN;        // top-level "SPEED n"; NaN until one was sent
  double program_speed_pct = 100;         // "SPEED n" inside a program or "DO SPEED n"
  bool in_editor = false;                 // between "EDIT name" and "E"
  std::set<std::string> edited_programs;  // upper-case names uploaded (and so checked) in this run

  static SafetyState For(const JointLimits& limits, const ControllerProfile& profile);
};

// Checks one line before it is written to the port. Recognises (with VAL's unique-prefix
// abbreviations of two letters or more): "[DO] MOVE #PPOINT(j1,...,j6)", "DO DRIVE j,change,speed",
// "[DO] SPEED n", "EDIT name", "E", "EXECUTE name", and blank lines. Refuses any joint target
// outside the limits, a SPEED that would let a joint exceed its speed limit, a motion before any
// monitor SPEED, a timed move faster than the speed limit, a too-long line, and anything else
// (a command it cannot verify never reaches the port). The state is updated only on success.
// The message does not carry a line number; the caller prefixes "file:line: ".
Status CheckLine(const std::string& line, SafetyState& state);
Status CheckLine(const std::string& line, double time_s, SafetyState& state);
// Checks every line of a program from `state`, prefixing messages with "file:line: ".
Status CheckProgram(const ValProgram& program, SafetyState& state);

}  // namespace armmimic::robot
