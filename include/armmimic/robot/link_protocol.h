// LinkProtocol: the line protocol to a VAL controller as a transport-free state machine, fed the
// bytes received and the time, and asked for the bytes to write (docs/link.md).
//
//   wake:   write the terminator, wait for the top-level prompt (retry a few times);
//   stream: write one line, wait for its echo and then a prompt, acknowledge it, next line;
//   stop:   a reply that matches the error pattern stops the stream with the controller's
//           text and the line number; no prompt within the line's timeout stops it too.
//
// It is liberal in what it accepts: CR, LF or CR LF line ends, an echo split over many reads,
// a prompt glued to the echo or on its own line, blank lines and noise between them.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "armmimic/core/angles.h"
#include "armmimic/robot/limits.h"
#include "armmimic/robot/profile.h"

namespace armmimic::robot {

struct LinkSettings {
  std::string terminator = "\r";
  std::string prompt_top = ".";
  std::string prompt_running = "*";
  std::string error_prefix = "*";
  bool echo = true;
  // Wake: a terminator is written up to `wake_attempts` times, `wake_timeout_s` apart.
  int wake_attempts = 3;
  double wake_timeout_s = 1.5;
  // A running-program prompt ("*") at the end of the received bytes could be the start of an
  // error line ("*Servo error*"): it counts only after this long without more bytes.
  double prompt_settle_s = 0.1;

  static LinkSettings FromProfile(const ControllerProfile& profile);
};

struct LinkLine {
  std::string text;      // without the terminator
  int line_no = 0;       // in the source file (for messages)
  int index = 0;         // 0-based position in the whole program (for the journal)
  double timeout_s = 5;  // how long after writing it the prompt may take
  double time_s = kNaN;  // its planned time (the gate's speed check); NaN: untimed
};

// kReady: an open-ended stream (StartStream) has every line acknowledged and waits for the next.
enum class LinkState { kIdle, kWaking, kWaitingReply, kReady, kDone, kFailed };
enum class LinkError { kNone, kControllerError, kTimeout, kNotReady, kAborted, kRefused };

class LinkProtocol {
 public:
  explicit LinkProtocol(LinkSettings settings = {});

  // Starts: wakes the controller, then sends `lines` in order. `source_name` prefixes messages
  // ("PROGRAM.val:12: ...").
  void Start(std::vector<LinkLine> lines, const std::string& source_name, double now_s);
  // An open-ended stream (live mimicking): wakes the controller, then sends each line given to
  // Append() as soon as the one before it is acknowledged; with none waiting it is kReady.
  // EndStream() lets it finish (kDone) once the last line is acknowledged.
  void StartStream(const std::string& source_name, double now_s);
  // Queues a line; in kReady it is written at once. May be called from the ack callback: the
  // line then goes out right after the acknowledged one.
  void Append(LinkLine line, double now_s);
  void EndStream();
  bool ready() const { return state_ == LinkState::kReady; }
  // Lines appended and not yet written.
  std::size_t queued() const { return lines_.size() - next_ - (written_ ? 1 : 0); }
  void OnBytes(std::string_view data, double now_s);
  void OnTick(double now_s);
  // Bytes to write to the port now (and clears them).
  std::string TakeOutput();
  // Stops with kAborted (the operator cancelled, the port vanished). `key`: the setting the
  // message is about ("port.port" when the port vanished), or "".
  void Abort(const std::string& message, const std::string& key = std::string());

  LinkState state() const { return state_; }
  bool finished() const { return state_ == LinkState::kDone || state_ == LinkState::kFailed; }
  LinkError error() const { return error_; }
  // The message naming the file and line ("PROGRAM.val:12: controller error: *Servo error*").
  const std::string& error_message() const { return error_message_; }
  // The setting the error is about (Status::key()), or "".
  const std::string& error_key() const { return error_key_; }
  // The controller's own error text, when error() is kControllerError.
  const std::string& controller_text() const { return controller_text_; }
  // Lines of `lines` acknowledged so far.
  std::size_t acknowledged() const { return next_; }
  std::size_t total() const { return lines_.size(); }
  // The line written and not yet acknowledged, or nullptr.
  const LinkLine* in_flight() const;
  // Reply lines (neither echo nor prompt) received for the last acknowledged line.
  const std::vector<std::string>& last_replies() const { return last_replies_; }
  // Lines received that were neither echo, prompt, error nor reply (e.g. stale prompts).
  int noise_lines() const { return noise_; }

  // The last word before a line is written: returns "" to let it go, or why it may not (the
  // stream then stops with kRefused and the line is never written). send uses it for the
  // safety check of every line.
  void SetGate(std::function<std::string(const LinkLine&)> gate) { gate_ = std::move(gate); }
  // Called before a line is written (for the journal's "sent" record) and after it is
  // acknowledged (with its reply lines).
  void SetSentCallback(std::function<void(const LinkLine&)> callback) {
    on_sent_ = std::move(callback);
  }
  void SetAckCallback(
      std::function<void(const LinkLine&, const std::vector<std::string>& replies)> callback) {
    on_ack_ = std::move(callback);
  }

 private:
  void Scan(double now_s);
  void HandleLine(const std::string& cleaned);
  // Returns true when the tail was consumed.
  bool HandleTail(const std::string& cleaned, double now_s);
  void OnPrompt(double now_s);
  void SendNext(double now_s);
  void Fail(LinkError error, const std::string& message);
  std::string Where() const;  // "PROGRAM.val:12" for the line in flight
  bool IsTopPrompt(const std::string& s) const;
  bool IsEditPrompt(const std::string& s) const;
  bool IsError(const std::string& s) const;
  bool EchoMatches(const std::string& s, std::string* rest) const;

  LinkSettings settings_;
  LinkState state_ = LinkState::kIdle;
  LinkError error_ = LinkError::kNone;
  std::string error_message_;
  std::string error_key_;
  std::string controller_text_;

  std::string source_name_;
  std::vector<LinkLine> lines_;
  std::size_t next_ = 0;     // index into lines_ of the line in flight / to send
  bool open_ended_ = false;  // StartStream: out of lines means kReady, not kDone
  std::string rx_;
  std::string out_;
  double deadline_s_ = 0;
  double last_rx_s_ = 0;
  double now_s_ = 0;
  int wake_attempt_ = 0;
  bool written_ = false;  // lines_[next_] went out and is not acknowledged yet
  bool echo_seen_ = false;
  bool running_seen_ = false;
  bool pending_prompt_ = false;
  bool dirty_ = false;  // the line being handled held control or non-ASCII bytes  // a prompt was
                        // found while scanning
  std::vector<std::string> replies_;
  std::vector<std::string> last_replies_;
  int noise_ = 0;
  std::function<std::string(const LinkLine&)> gate_;
  std::function<void(const LinkLine&)> on_sent_;
  std::function<void(const LinkLine&, const std::vector<std::string>&)> on_ack_;
};

// Upper-cases and collapses runs of blanks, trims: how lines are compared with their echo.
std::string NormalizeLine(const std::string& line);
// The six joint angles of a WHERE reply (the last reply line holding exactly six numbers).
bool ParseWhereReply(const std::vector<std::string>& replies, JointArray* joints_deg);
// The target of a "[DO] MOVE #PPOINT(j1,...,j6)" line (any unique abbreviation of MOVE).
bool ParsePpointTarget(const std::string& line, JointArray* joints_deg);
// True for lines that move the arm: [DO] MOVE, DO DRIVE, EXECUTE.
bool IsMotionLine(const std::string& line);

}  // namespace armmimic::robot
