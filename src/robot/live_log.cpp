#include "armmimic/robot/live_log.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include <unistd.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/output_file.h"
#include "armmimic/core/text.h"

namespace armmimic::robot {
namespace {

std::string Ms(double s) { return std::isnan(s) ? "nan" : FormatNumber(s * 1000.0, 2); }

std::string Fixed(double v, int decimals) { return FormatNumber(v, decimals); }

std::string Describe(const char* what, const Percentiles& p) {
  if (p.count == 0) return std::string(what) + " -";
  return std::string(what) + " median " + Fixed(p.median_ms, 1) + " ms, p95 " + Fixed(p.p95_ms, 1) +
         " ms";
}

}  // namespace

LiveJournal::~LiveJournal() {
  if (file_) std::fclose(file_);
}

Status LiveJournal::Open(const std::string& path, const std::string& header) {
  path_ = path;
  if (Status st = OpenLogFile(path, false, &file_); !st) {
    return Status::Error("cannot write the journal: " + st.message());
  }
  Status s = Append("# armmimic mimic journal v1");
  if (s.ok()) s = Append("stream " + header);
  return s;
}

Status LiveJournal::Append(const std::string& record) {
  if (!file_) return Status::Error(path_ + ": the journal is not open");
  if (std::fprintf(file_, "%s\n", record.c_str()) < 0 || std::fflush(file_) != 0) {
    return Status::Error(path_ + ": cannot write the journal: " + ErrnoText(errno));
  }
  return Status::Ok();
}

Status LiveJournal::Sent(int seq, double time_s, int frame, const std::string& line) {
  return Append("sent " + std::to_string(seq) + " " + Fixed(time_s, 3) + " " +
                (frame >= 0 ? std::to_string(frame) : std::string("-")) + " " + line);
}

Status LiveJournal::Acked(int seq, double time_s) {
  return Append("ack " + std::to_string(seq) + " " + Fixed(time_s, 3));
}

Status LiveJournal::Close(const std::string& stop_reason, int last_ack_seq, int last_ack_frame,
                          const std::string& last_ack_line) {
  if (!file_) return Status::Ok();
  std::string reason = stop_reason;
  for (char& c : reason) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  Status s = Append(reason.empty() ? std::string("end") : "stop " + reason);
  if (s.ok()) {
    s = Append(last_ack_seq > 0 ? "last-ack " + std::to_string(last_ack_seq) + " " +
                                      (last_ack_frame >= 0 ? std::to_string(last_ack_frame) : "-") +
                                      " " + last_ack_line
                                : std::string("last-ack none"));
  }
  if (s.ok() && !SyncOutput(file_)) {
    s = Status::Error(path_ + ": cannot sync the journal: " + FileErrorText(errno));
  }
  std::fclose(file_);
  file_ = nullptr;
  return s;
}

Percentiles Summarise(std::vector<double> values_ms) {
  Percentiles p;
  p.count = static_cast<int>(values_ms.size());
  if (values_ms.empty()) return p;
  std::sort(values_ms.begin(), values_ms.end());
  auto rank = [&](double q) {
    const std::size_t i = static_cast<std::size_t>(std::ceil(q * values_ms.size())) - 1;
    return values_ms[std::min(i, values_ms.size() - 1)];
  };
  p.median_ms = rank(0.5);
  p.p95_ms = rank(0.95);
  p.max_ms = values_ms.back();
  return p;
}

std::string LatencySummary::Describe() const {
  std::string s = "frame-to-command latency ";
  if (frame_to_command.count == 0) {
    s += "- (no command written)";
  } else {
    s += "median " + Fixed(frame_to_command.median_ms, 1) + " ms, p95 " +
         Fixed(frame_to_command.p95_ms, 1) + " ms, max " + Fixed(frame_to_command.max_ms, 1) +
         " ms";
  }
  s += " over " + std::to_string(commands_sent) + " commands; " +
       armmimic::robot::Describe("analysis", analysis) + "; " +
       armmimic::robot::Describe("planning", planning) + "; " +
       armmimic::robot::Describe("acknowledgement", acknowledgement) + "; " +
       std::to_string(commands_acked) + " of " + std::to_string(commands_sent) +
       " moves acknowledged; " + Fixed(duration_s > 0 ? commands_sent / duration_s : 0.0, 2) +
       " commands/s over " + Fixed(duration_s, 1) + " s";
  return s;
}

LatencyLog::~LatencyLog() {
  if (file_) std::fclose(file_);
}

Status LatencyLog::Open(const std::string& path) {
  path_ = path;
  if (path.empty()) return Status::Ok();
  if (Status st = OpenLogFile(path, false, &file_); !st) {
    return Status::Error("cannot write the latency log: " + st.message());
  }
  std::fprintf(file_,
               "# armmimic mimic latency v1\n"
               "# times in ms on the stream clock; nan: did not happen\n"
               "frame\tstatus\tcapture_ms\tanalysed_ms\tplanned_ms\twritten_ms\tacked_ms\t"
               "seq\thold\n");
  return Status::Ok();
}

void LatencyLog::Add(const FrameLatency& row) {
  ++frames_;
  if (std::isnan(first_s_)) first_s_ = row.capture_s;
  last_s_ = row.planned_s;
  analysis_ms_.push_back((row.analysed_s - row.capture_s) * 1000.0);
  planning_ms_.push_back((row.planned_s - row.analysed_s) * 1000.0);
  pending_.push_back(row);
  FlushSettled();
}

void LatencyLog::Written(int seq, int frame, double written_s) {
  auto it = pending_.rbegin();
  while (it != pending_.rend() && it->frame != frame) ++it;
  if (it == pending_.rend()) return;
  FrameLatency& row = *it;
  row.written_s = written_s;
  row.seq = seq;
  row.hold.clear();
  ++sent_;
  last_s_ = written_s;
  to_command_ms_.push_back((written_s - row.capture_s) * 1000.0);
}

void LatencyLog::Acked(int seq, double acked_s) {
  for (auto it = pending_.rbegin(); it != pending_.rend(); ++it) {
    if (it->seq != seq) continue;
    it->acked_s = acked_s;
    ++acked_;
    last_s_ = acked_s;
    ack_ms_.push_back((acked_s - it->written_s) * 1000.0);
    break;
  }
  FlushSettled();
}

void LatencyLog::FlushSettled() {
  // The newest row may still get a command (when the link frees up); a written row its ack.
  while (pending_.size() > 1) {
    const FrameLatency& r = pending_.front();
    if (r.seq > 0 && std::isnan(r.acked_s)) break;
    WriteRow(r);
    pending_.pop_front();
  }
}

void LatencyLog::WriteRow(const FrameLatency& r) {
  if (!file_) return;
  std::fprintf(file_, "%d\t%s\t%s\t%s\t%s\t%s\t%s\t%d\t%s\n", r.frame, r.ok ? "ok" : "lost",
               Ms(r.capture_s).c_str(), Ms(r.analysed_s).c_str(), Ms(r.planned_s).c_str(),
               Ms(r.written_s).c_str(), Ms(r.acked_s).c_str(), r.seq,
               r.seq > 0 ? "sent" : (r.hold.empty() ? "-" : r.hold.c_str()));
}

LatencySummary LatencyLog::Summary() const {
  LatencySummary s;
  s.frame_to_command = Summarise(to_command_ms_);
  s.analysis = Summarise(analysis_ms_);
  s.planning = Summarise(planning_ms_);
  s.acknowledgement = Summarise(ack_ms_);
  s.frames = frames_;
  s.commands_sent = sent_;
  s.commands_acked = acked_;
  s.duration_s = std::isnan(first_s_) || std::isnan(last_s_) ? 0 : last_s_ - first_s_;
  return s;
}

LatencySummary LatencyLog::Close() {
  for (const FrameLatency& r : pending_) WriteRow(r);
  pending_.clear();
  if (file_) std::fclose(file_);
  file_ = nullptr;
  return Summary();
}

}  // namespace armmimic::robot
