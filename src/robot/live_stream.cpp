#include "armmimic/robot/live_stream.h"

#include <cmath>

#include "armmimic/core/text.h"
#include "armmimic/robot/option_tables.h"

namespace armmimic::robot {

Status LiveStreamOptions::Check() const {
  Status s = planner.Check();
  if (!s.ok()) return s;
  s = profile.Check();
  if (!s.ok()) return s;
  if (profile.mode != SendMode::kStream) {
    return Status::Error(
        "live mimicking streams one DO MOVE at a time: the profile's mode must "
        "be stream, not program");
  }
  return CheckOptionFields(LiveStreamOptionFields(), "live", *this);  // the stale-frame timeout
}

Status LiveStream::Begin(const LiveStreamOptions& options) {
  Status s = options.Check();
  if (!s.ok()) return s;
  options_ = options;
  s = planner_.Begin(options.planner, options.kind, options.sample_rate_hz,
                     options.profile.decimals, options.stale_after_s);
  if (!s.ok()) return s;
  gate_ = SafetyState::For(options.planner.limits, options.profile);
  if (!options.journal_path.empty()) {
    const int speed = SpeedSettingFor(options.planner.limits, options.profile);
    s = journal_.Open(options.journal_path, "source=" + PercentEncode(options.source_name) +
                                                " port=" + PercentEncode(options.port_name) +
                                                " profile=" + PercentEncode(options.profile.name) +
                                                " speed=" + std::to_string(speed) + " mapping=" +
                                                PercentEncode(planner_.mapping().Describe()));
    if (!s.ok()) return s;
  }
  return latency_.Open(options.latency_path);
}

Status LiveStream::SetSampleRate(double sample_rate_hz) {
  options_.sample_rate_hz = sample_rate_hz;
  return planner_.Begin(options_.planner, options_.kind, sample_rate_hz, options_.profile.decimals,
                        options_.stale_after_s);
}

void LiveStream::Attach(LinkProtocol* protocol, std::function<void(const LinkLine&)> append) {
  protocol_ = protocol;
  append_ = std::move(append);
  protocol_->SetGate([this](const LinkLine& l) -> std::string {
    const Status s = CheckLine(l.text, l.time_s, gate_);
    return s.ok() ? "" : s.message();
  });
  protocol_->SetSentCallback([this](const LinkLine& l) { OnSent(l); });
  protocol_->SetAckCallback(
      [this](const LinkLine& l, const std::vector<std::string>&) { OnAcked(l); });
}

LinkLine LiveStream::MakeLine(const std::string& text, double time_s) {
  LinkLine line;
  line.text = text;
  line.line_no = ++seq_;
  line.index = seq_ - 1;
  line.time_s = time_s;
  line.timeout_s =
      IsMotionLine(text) ? options_.profile.motion_timeout_s : options_.profile.prompt_timeout_s;
  return line;
}

void LiveStream::SendOpening() {
  const int speed = SpeedSettingFor(options_.planner.limits, options_.profile);
  written_.push_back({-1, FormatSpeedLine(speed, options_.profile)});
  Write(MakeLine(written_.back().second, kNaN));
}

void LiveStream::Write(const LinkLine& line) {
  if (protocol_) {
    append_(line);
    return;
  }
  // Dry run: the same gate, then the writer; acknowledged at once.
  const Status s = CheckLine(line.text, line.time_s, gate_);
  if (!s.ok()) {
    Stop("mimic:" + std::to_string(line.line_no) + ": not sent: " + s.message());
    return;
  }
  OnSent(line);
  if (writer_) writer_(line);
  OnAcked(line);
}

bool LiveStream::LinkFree(bool from_ack) const {
  if (!protocol_) return true;
  if (protocol_->finished() || protocol_->queued() > 0) return false;
  return from_ack || protocol_->ready();
}

HoldReason LiveStream::holding(double now_s) const {
  if (held_ || stopped_) return HoldReason::kOperator;
  return planner_.holding(now_s);
}

std::string LiveStream::HoldText(double now_s) const {
  if (stopped_ && !stop_reason_.empty()) {
    // Why the stream stopped ("interrupted (SIGTERM)", a lost link), on the log's one line.
    std::string reason = stop_reason_;
    for (char& c : reason) {
      if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    }
    return reason;
  }
  const HoldReason h = holding(now_s);
  if (h != HoldReason::kNone) return HoldReasonName(h);
  if (!LinkFree(false)) return "link busy";
  StreamCommand c;
  return planner_.Next(now_s, &c) ? "" : HoldReasonName(HoldReason::kDeadband);
}

void LiveStream::OnFrame(const AngleRow& row, double capture_s, double analysed_s, double now_s) {
  planner_.Push(row, now_s);
  FrameLatency f;
  f.frame = row.frame;
  f.ok = row.ok();
  f.capture_s = capture_s;
  f.analysed_s = analysed_s;
  f.planned_s = clock_ ? clock_() : now_s;
  f.hold = HoldText(now_s);
  latency_.Add(f);
  TrySend(now_s, false);
}

void LiveStream::SetHeld(bool held, double now_s) {
  held_ = held;
  if (!held) TrySend(now_s, false);
}

void LiveStream::Stop(const std::string& reason) {
  if (stopped_) return;
  stopped_ = true;
  stop_reason_ = reason;
}

void LiveStream::TrySend(double now_s, bool from_ack) {
  if (stopped_ || held_ || !LinkFree(from_ack)) return;
  StreamCommand c;
  if (!planner_.Next(now_s, &c)) return;
  planner_.Sent(c);
  const LinkLine line = MakeLine(FormatMoveLine(c.joint_deg, options_.profile), c.time_s);
  written_.push_back({c.frame, line.text});
  if (on_command_) on_command_(c.joint_deg, c.frame);
  Write(line);
}

void LiveStream::OnSent(const LinkLine& line) {
  const double now = clock_ ? clock_() : line.time_s;
  const int frame = written_[static_cast<std::size_t>(line.index)].first;
  if (IsMotionLine(line.text)) planner_.Written(now);
  if (frame >= 0) latency_.Written(line.line_no, frame, now);
  if (!journal_.is_open()) return;
  const Status s = journal_.Sent(line.line_no, now, frame, line.text);
  if (!s.ok() && journal_error_.empty()) {
    journal_error_ = s.message();
    Stop(s.message());
    if (protocol_) protocol_->Abort(s.message());
  }
}

void LiveStream::OnAcked(const LinkLine& line) {
  const double now = clock_ ? clock_() : line.time_s;
  const int frame = written_[static_cast<std::size_t>(line.index)].first;
  if (frame >= 0) latency_.Acked(line.line_no, now);
  if (IsMotionLine(line.text)) last_ack_seq_ = line.line_no;
  if (journal_.is_open()) {
    const Status s = journal_.Acked(line.line_no, now);
    if (!s.ok() && journal_error_.empty()) {
      journal_error_ = s.message();
      Stop(s.message());
      if (protocol_) protocol_->Abort(s.message());
      return;
    }
  }
  TrySend(now, true);
}

Status LiveStream::Close() {
  if (closed_) return Status::Ok();
  closed_ = true;
  latency_.Close();
  int frame = -1;
  std::string text;
  if (last_ack_seq_ > 0) {
    frame = written_[static_cast<std::size_t>(last_ack_seq_ - 1)].first;
    text = written_[static_cast<std::size_t>(last_ack_seq_ - 1)].second;
  }
  const Status s = journal_.Close(stop_reason_, last_ack_seq_, frame, text);
  if (!journal_error_.empty()) return Status::Error(journal_error_);
  return s;
}

}  // namespace armmimic::robot
