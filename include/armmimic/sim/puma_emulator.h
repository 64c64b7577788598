// PumaEmulator: a PUMA 760 / VAL II controller emulator, fed bytes and time. It speaks the
// default controller profile (echo, "." prompt, "*" while a program runs, CR lines of at most 80
// characters, "*"-prefixed errors) and interprets the VAL subset documented in
// docs/val-dialect.md. It keeps the joint state inside the configured limits, times each motion
// from the speed settings, and logs every executed move so tests can prove "exactly once".
//
// It is not thread-safe: PtyServer (pty_server.h) owns one and guards it; the GUI can run one
// in-process as a "simulated controller".
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "armmimic/robot/limits.h"

namespace armmimic::sim {

struct EmulatorOptions {
  robot::JointLimits limits;
  // Each joint's speed at monitor SPEED 100 and instruction speed 100, in deg/s (the default
  // profile's joint_speed_at_100_deg_s).
  robot::JointArray joint_speed_at_100_deg_s = {60, 60, 60, 120, 120, 120};
  robot::JointArray start_deg = {0, -90, 0, 0, 0, 0};
  // Every motion and delay lasts this many times its real duration (0.01: 100x faster).
  double time_scale = 1.0;
  // Settling time added to every motion (before scaling), in seconds.
  double settle_s = 0.05;
  int max_line_length = 80;
  // What ends every line the emulator prints.
  std::string newline = "\r\n";
  // Fault injection, counted in non-blank command lines received since start (-1: off).
  // fail_after N: line N+1 is refused with "*Servo error*" (once) and not executed.
  int fail_after = -1;
  // silent_after N: line N+1 is executed but the emulator then answers nothing (no echo, no
  // prompt) until the client disconnects (OnDisconnect), like a cut reply wire.
  int silent_after = -1;
  // garble_after N: from line N+1 on, a line of noise bytes comes before every prompt.
  int garble_after = -1;
  // PtyServer only: > 0 paces the bytes as an RS-232 line at this baud rate would (10 bits a
  // byte, 8N1), both ways: a line reaches the controller, and its echo and prompt come back, one
  // character time per byte, as on a real VAL terminal port. 0: the pseudo-terminal's speed.
  int line_baud = 0;
};

// One executed motion.
struct LoggedMove {
  int seq = 0;         // 1, 2, ... in execution order
  std::string source;  // the command or program instruction that caused it
  robot::JointArray target_deg{};
  double start_s = 0;  // emulator time the motion started and ends
  double end_s = 0;
};

class PumaEmulator {
 public:
  explicit PumaEmulator(EmulatorOptions options = {});

  // Received bytes at time `now_s` (seconds, monotonic). Returns the bytes to send back.
  std::string Feed(std::string_view bytes, double now_s);
  // Advances time: finishes motions, steps a running program. Returns bytes to send back.
  std::string Tick(double now_s);
  // The client closed the line: partial input is dropped and a silence fault ends.
  void OnDisconnect();

  // Current joint angles (interpolated during a motion, as of the last Feed/Tick).
  robot::JointArray joints() const { return current_; }
  // The target of the current or last motion.
  robot::JointArray target() const { return target_; }
  bool busy() const;
  // Earliest time something will happen on its own (motion end), or a negative value.
  double NextEventTime() const;
  const std::vector<LoggedMove>& log() const { return log_; }
  int lines_received() const { return lines_received_; }
  // Called for every executed move as it starts.
  void SetMoveCallback(std::function<void(const LoggedMove&)> callback) {
    on_move_ = std::move(callback);
  }
  // Formats six joint values the way WHERE prints them.
  static std::string FormatJoints(const robot::JointArray& deg);

 private:
  enum class Mode { kTop, kEdit, kRunning };
  struct Motion {
    bool active = false;
    robot::JointArray from{};
    robot::JointArray to{};
    double start_s = 0;
    double end_s = 0;
  };

  void ProcessLines(double now_s);
  void ExecuteLine(const std::string& raw, double now_s);
  void TopLevel(const std::string& line, double now_s);
  // Runs one instruction (MOVE, DRIVE, SPEED, DELAY). Returns "" or an error text.
  std::string Instruction(const std::string& text, double now_s);
  std::string StartMotion(const robot::JointArray& to, double speed_pct, const std::string& source,
                          double now_s);
  void StepProgram(double now_s);
  void Emit(const std::string& text);  // one line
  void Prompt();
  void Advance(double now_s);

  EmulatorOptions options_;
  robot::JointArray current_;
  robot::JointArray target_;
  Motion motion_;
  double delay_until_s_ = -1;
  std::string input_;               // partial line
  std::vector<std::string> queue_;  // complete lines waiting for the controller
  bool last_was_cr_ = false;
  bool awaiting_prompt_ = false;  // a motion is running; prompt when it ends
  std::string out_;
  Mode mode_ = Mode::kTop;
  double monitor_speed_ = 100;
  double program_speed_ = 100;
  std::string edit_name_;
  std::map<std::string, std::vector<std::string>> programs_;
  std::map<std::string, robot::JointArray> points_;
  std::string run_name_;
  std::size_t run_pc_ = 0;
  std::vector<LoggedMove> log_;
  std::function<void(const LoggedMove&)> on_move_;
  int lines_received_ = 0;
  bool fail_done_ = false;
  bool silenced_ = false;
  bool silence_done_ = false;
  double now_s_ = 0;
  std::string source_;  // the line or program step being executed, for the log
};

}  // namespace armmimic::sim
