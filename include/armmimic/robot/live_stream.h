// LiveStream: live mimicking without a transport. Analysed frames go in; the StreamPlanner turns
// them into joint targets; a DO MOVE line goes out whenever the link has acknowledged the last
// one and the planner has a target worth sending. Every line passes the same safety gate as
// `send` (robot::CheckLine, with the times the planner used) right before it is written, and is
// journaled; every frame's times go to the latency log. The command-line `mimic` and the
// desktop application's Mimic live mode both run it (through live::MimicRun).
//
// It drives a LinkProtocol in its open-ended mode (StartStream/Append): Attach() sets the gate
// and callbacks and names the function that appends a line (the transport's, so the bytes go out
// at once); SendOpening() writes the SPEED line first. Without a protocol (dry run) each
// line is checked by the same gate and goes to the writer callback, as if acknowledged at once.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/robot/live_log.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/stream_planner.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::robot {

struct LiveStreamOptions {
  PlannerOptions planner;
  ControllerProfile profile;
  SourceKind kind = SourceKind::kArm;
  double sample_rate_hz = 30;
  // No measured frame for this long holds the robot (a stalled camera, a slow engine).
  double stale_after_s = 0.2;
  std::string journal_path;  // "" : no journal
  std::string latency_path;  // "" : latency kept in memory only
  std::string source_name;   // the input, for the journal and messages
  std::string port_name;     // for the journal
  // Lines are named "mimic:SEQ" in the protocol's messages.
  Status Check() const;
};

class LiveStream {
 public:
  LiveStream() = default;
  LiveStream(const LiveStream&) = delete;
  LiveStream& operator=(const LiveStream&) = delete;

  Status Begin(const LiveStreamOptions& options);
  // The source's real frame rate, once it is open (before its first frame): the filter's rate.
  Status SetSampleRate(double sample_rate_hz);
  // The protocol the lines go to; sets its gate and callbacks. `append` queues a line on it and
  // flushes the transport (SerialLink::Append). Before StartStream.
  void Attach(LinkProtocol* protocol, std::function<void(const LinkLine&)> append);
  // Dry run: lines go here instead (no protocol), each acknowledged at once.
  void SetWriter(std::function<void(const LinkLine&)> write) { writer_ = std::move(write); }
  // The clock of the stream (seconds); the ack callback reads it. Default: 0.
  void SetClock(std::function<double()> now) { clock_ = std::move(now); }
  // Called for every command written (for a robot preview): the target and its frame.
  void SetCommandCallback(std::function<void(const JointArray&, int frame)> callback) {
    on_command_ = std::move(callback);
  }
  // Writes the monitor SPEED line (right after StartStream): every move needs it first.
  void SendOpening();

  // One analysed frame, with its capture and analysis times, planned at `now_s`.
  void OnFrame(const AngleRow& row, double capture_s, double analysed_s, double now_s);
  // Holds the robot (no new commands) while on: the operator's dead-man is released.
  void SetHeld(bool held, double now_s);
  // Stops sending for good; the line in flight (if any) still gets its acknowledgement.
  void Stop(const std::string& reason);
  bool stopped() const { return stopped_; }
  // Closes the journal (the stop reason, the last acknowledged move) and the latency log.
  Status Close();

  const StreamPlanner& planner() const { return planner_; }
  HoldReason holding(double now_s) const;
  LatencySummary Summary() const { return latency_.Summary(); }
  int lines_written() const { return seq_; }
  int last_acked_seq() const { return last_ack_seq_; }
  const std::string& stop_reason() const { return stop_reason_; }
  std::string JournalPath() const { return options_.journal_path; }
  std::string LatencyPath() const { return options_.latency_path; }

 private:
  bool LinkFree(bool from_ack) const;
  void TrySend(double now_s, bool from_ack);
  std::string HoldText(double now_s) const;
  LinkLine MakeLine(const std::string& text, double time_s);
  void Write(const LinkLine& line);
  std::string MoveText(const JointArray& target) const;
  void OnSent(const LinkLine& line);
  void OnAcked(const LinkLine& line);

  LiveStreamOptions options_;
  StreamPlanner planner_;
  SafetyState gate_;
  LinkProtocol* protocol_ = nullptr;
  std::function<void(const LinkLine&)> append_;
  std::function<void(const LinkLine&)> writer_;
  std::function<double()> clock_;
  std::function<void(const JointArray&, int)> on_command_;
  LiveJournal journal_;
  LatencyLog latency_;
  std::string journal_error_;
  int seq_ = 0;
  bool held_ = false;
  bool stopped_ = false;
  std::string stop_reason_;
  // The commands written, by sequence number (frame, text), for the journal's last-ack record.
  std::vector<std::pair<int, std::string>> written_;
  int last_ack_seq_ = 0;
  bool closed_ = false;
};

}  // namespace armmimic::robot
