// SendSession: everything a send does around the link protocol, without a transport, so the
// CLI's `send` and the desktop application's robot panel share one implementation (docs/link.md):
//
//   Prepare   the whole program is checked before anything moves; the link lines get their
//             timeouts (EXECUTE waits for the program's duration too); the journal decides where
//             to start (fresh, --resume, --resume-at, --restart) and refuses to replay silently;
//   Uncertain a line written before the link died but never acknowledged: WHERE asks the arm,
//             and the answer says whether the line ran, must run again, or the operator decides;
//   Attach    the safety state is replayed up to the start, and the protocol gets the gate (every
//             line checked again right before it is written) and the journal records;
//   Finish    a finished stream is journaled as done; a failed one explains how to resume.
//
// A caller owns the transport: it opens the port, runs the protocol (serial::RunToEnd in the
// CLI, the Qt event loop in the GUI) and prints or shows the messages.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "armmimic/core/status.h"
#include "armmimic/robot/journal.h"
#include "armmimic/robot/limits.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::robot {

// Reads a .val program, or plans one from an angle file (first line "# armmimic angles v1") with
// the default planner options and `limits`, exactly as `plan` would, in the profile's mode.
Status LoadProgramToSend(const std::string& path, const ControllerProfile& profile,
                         const JointLimits& limits, ValProgram* program);

// Where the arm is after each line of `program`, as far as the program tells: a MOVE's target, a
// DRIVE's change added to the last known pose. `known` is false until the first target.
struct ArmPosition {
  bool known = false;
  JointArray joint_deg{};
};
std::vector<ArmPosition> ArmPositionsAfterEachLine(const ValProgram& program);

struct SendStart {
  enum class Mode {
    kFresh,    // from the first line; refused while the journal shows an unfinished send
    kResume,   // after the last acknowledged line (--resume)
    kRestart,  // from the first line although the journal shows an unfinished send (--restart)
  };
  Mode mode = Mode::kFresh;
  int resume_at_line = 0;  // > 0: continue from this file line (--resume-at), needs the journal
  bool journal = true;     // false: no journal is read or written
  bool dry_run = false;    // a dry run never refuses because of an unfinished journal
};

class SendSession {
 public:
  SendSession();
  ~SendSession();
  SendSession(const SendSession&) = delete;
  SendSession& operator=(const SendSession&) = delete;

  // `input` names the program for messages and the journal (INPUT.journal). `limits` are the
  // caller's, tightened here by the limits in the program's header. Errors name file and line.
  Status Prepare(ValProgram program, const ControllerProfile& profile, const JointLimits& limits,
                 const std::string& input, const SendStart& start);

  // The journal shows the program sent completely: nothing to resume.
  bool nothing_to_do() const { return nothing_to_do_; }
  // The lines to write, in order: from the start point (after a resume, the last monitor SPEED
  // before it first). Each carries its planned time (NaN when the program has none).
  const std::vector<LinkLine>& lines() const { return to_send_; }
  const ValProgram& program() const { return program_; }
  const JointLimits& limits() const { return limits_; }
  std::size_t total() const { return program_.lines.size(); }
  std::size_t start_index() const { return start_; }
  double duration_s() const { return last_time_s_; }
  const std::string& journal_path() const { return journal_path_; }
  // "PROGRAM.val:12" of the first line sent after a resume, or "" when starting from the top.
  std::string ResumedAt() const;

  // A line was written before the link died and never acknowledged. Returns true and sets
  // *query (a WHERE line) when the arm must be asked; false when nothing needs asking. Fails when
  // the line's target is unknown (the operator must check the arm and use --resume-at).
  Status UncertainQuery(bool* ask, LinkLine* query) const;
  // The replies to that WHERE. Ok: the stream may go on (the line is dropped when the arm shows
  // it ran, and journaled so); *note says what was found. An error names the line, the arm's
  // angles and the target, and what the operator can do.
  Status ResolveUncertain(const std::vector<std::string>& where_replies, std::string* note);

  // Replays the safety state up to the start, opens the journal, and sets the protocol's gate,
  // sent and acknowledged callbacks. A journal that cannot be written stops the stream.
  Status Attach(LinkProtocol* protocol);
  // After the protocol has finished. Ok when every line was acknowledged (the journal says done);
  // otherwise the protocol's message, with a journal error if there was one.
  Status Finish(const LinkProtocol& protocol);
  // After a failed stream: true when a motion line was in flight, so a --resume will ask WHERE.
  bool MotionWasInFlight(const LinkProtocol& protocol) const;

 private:
  Status DecideStart(const SendStart& start, const std::string& hash, bool program_mode);

  ValProgram program_;
  ControllerProfile profile_;
  JointLimits limits_;
  std::string input_;
  std::string journal_path_;
  std::string hash_;
  bool use_journal_ = true;
  bool append_journal_ = false;
  bool nothing_to_do_ = false;
  bool check_uncertain_ = false;
  std::size_t start_ = 0;
  double last_time_s_ = 0;
  std::vector<LinkLine> all_;
  std::vector<LinkLine> to_send_;
  SafetyState gate_state_;
  SendJournal journal_;
  std::string journal_error_;
};

}  // namespace armmimic::robot
