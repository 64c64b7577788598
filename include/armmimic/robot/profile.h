// ControllerProfile: everything about the controller's dialect that is not known for certain
// (terminator, prompts, error lines, echo, line length, command templates), kept in a small
// documented "key = value" file (docs/profiles/default.profile) with built-in defaults.
#pragma once

#include <iosfwd>
#include <string>

#include "armmimic/core/status.h"
#include "armmimic/robot/limits.h"

namespace armmimic::robot {

// stream: every move is one "DO MOVE ..." line, sent as the previous one completes.
// program: the moves are uploaded as a program ("EDIT name" ... "E") and run with "EXECUTE name".
enum class SendMode { kStream, kProgram };

const char* SendModeName(SendMode mode);                     // "stream" / "program"
bool ParseSendMode(const std::string& text, SendMode* out);  // false when neither

struct ControllerProfile {
  std::string name = "puma760-val2";
  // Written after every line ("\r": CR).
  std::string terminator = "\r";
  // A received line that is exactly this is the monitor prompt (ready at top level).
  std::string prompt_top = ".";
  // A received line that is exactly this is the prompt while a program runs.
  std::string prompt_running = "*";
  // A received line that starts with this and has more text after it is an error message.
  std::string error_prefix = "*";
  // Whether the controller echoes every character it receives.
  bool echo = true;
  // Longest line (without the terminator) the controller accepts.
  int max_line_length = 80;
  // Decimals written for joint angles.
  int decimals = 2;
  // Templates. Placeholders: {speed}; {j1}..{j6}; {joint},{change}; {name}.
  std::string speed_template = "SPEED {speed}";
  std::string move_template = "DO MOVE #PPOINT({j1},{j2},{j3},{j4},{j5},{j6})";
  std::string program_move_template = "MOVE #PPOINT({j1},{j2},{j3},{j4},{j5},{j6})";
  std::string drive_template = "DO DRIVE {joint},{change},{speed}";
  std::string edit_template = "EDIT {name}";
  std::string end_edit_line = "E";
  std::string execute_template = "EXECUTE {name}";
  SendMode mode = SendMode::kStream;
  std::string program_name = "MIMIC";
  // Seconds to wait for a prompt after an ordinary line, and after a motion line.
  double prompt_timeout_s = 5;
  double motion_timeout_s = 60;
  // Each joint's speed at SPEED 100 (monitor and program speed both 100), in deg/s. Used to turn
  // a speed limit into a SPEED setting and to check any SPEED line before it is sent.
  JointArray joint_speed_at_100_deg_s = {60, 60, 60, 120, 120, 120};

  static ControllerProfile Default() { return ControllerProfile(); }
  // Every field sensible; the message names the key.
  Status Check() const;
};

// Strict reader: "key = value" lines, '#' comments, blank lines. Unknown keys, duplicate keys
// and bad values are errors naming "file:line". Keys not given keep their defaults. Values may
// use \r, \n, \t and \\ escapes (for the terminator).
Status ParseProfile(std::istream& in, const std::string& source_name, ControllerProfile* out);
Status ReadProfile(const std::string& path, ControllerProfile* out);
// The profile as a file ParseProfile reads back (every key, with comments).
std::string FormatProfile(const ControllerProfile& profile);

}  // namespace armmimic::robot
