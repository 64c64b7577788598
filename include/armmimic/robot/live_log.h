// The two records live mimicking keeps beside its angle file (docs/live.md):
//
// LiveJournal (ANGLES.tsv.journal): every line written to the controller and its
// acknowledgement, flushed before the line goes out, and at the end the last acknowledged move.
//   # armmimic mimic journal v1
//   stream source=scene.avi engine=lk port=/dev/pts/3 profile=puma760-val2 speed=75
//   sent 1 0.412 - SPEED 75                      <- seq, stream time (s), frame, the line
//   ack 1 0.415
//   sent 2 0.530 63 DO MOVE #PPOINT(...)
//   ack 2 0.733
//   stop interrupted (Ctrl-C)                    <- or "end" when the input ended
//   last-ack 2 63 DO MOVE #PPOINT(...)           <- or "last-ack none"
//
// LatencyLog (ANGLES.tsv.latency.tsv): one row per analysed frame with its capture, analysis and
// planning times and, for a frame whose target was written, the write and acknowledgement times,
// all in milliseconds on the stream clock; and the summary of those times.
#pragma once

#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include "armmimic/core/angles.h"
#include "armmimic/core/status.h"

namespace armmimic::robot {

class LiveJournal {
 public:
  LiveJournal() = default;
  ~LiveJournal();
  LiveJournal(const LiveJournal&) = delete;
  LiveJournal& operator=(const LiveJournal&) = delete;

  static std::string PathFor(const std::string& angles_path) { return angles_path + ".journal"; }
  // `header`: the "key=value ..." text of the stream line.
  Status Open(const std::string& path, const std::string& header);
  bool is_open() const { return file_ != nullptr; }
  Status Sent(int seq, double time_s, int frame, const std::string& line);
  Status Acked(int seq, double time_s);
  // Ends the journal: "stop REASON" (or "end" for an empty reason) and the last acknowledged
  // move; synced to disk.
  Status Close(const std::string& stop_reason, int last_ack_seq, int last_ack_frame,
               const std::string& last_ack_line);
  const std::string& path() const { return path_; }

 private:
  Status Append(const std::string& record);
  std::string path_;
  std::FILE* file_ = nullptr;
};

// One frame's times, in seconds on the stream clock (NaN: did not happen).
struct FrameLatency {
  int frame = -1;
  bool ok = false;
  double capture_s = kNaN;   // the frame was captured (a paced file: when it was due)
  double analysed_s = kNaN;  // the engine returned
  double planned_s = kNaN;   // the planner took it
  double written_s = kNaN;   // a command with this frame's target was written
  double acked_s = kNaN;     // ... and acknowledged
  int seq = 0;               // that command's number in the journal (0: none)
  std::string hold;          // why no command came from this frame ("" when one did)
};

struct Percentiles {
  int count = 0;
  double median_ms = kNaN;
  double p95_ms = kNaN;
  double max_ms = kNaN;
};
// Median (nearest rank), 95th percentile and maximum of `values_ms`.
Percentiles Summarise(std::vector<double> values_ms);

struct LatencySummary {
  Percentiles frame_to_command;  // written - capture, per command
  Percentiles analysis;          // analysed - capture, per frame
  Percentiles planning;          // planned - analysed, per frame
  Percentiles acknowledgement;   // acked - written, per command
  int frames = 0;
  int commands_sent = 0;   // motion commands written
  int commands_acked = 0;  // ... and acknowledged
  double duration_s = 0;   // first capture to last event
  // "frame-to-command latency median 12.3 ms, p95 25.0 ms (n=214); ..." (one line)
  std::string Describe() const;
};

class LatencyLog {
 public:
  LatencyLog() = default;
  ~LatencyLog();
  LatencyLog(const LatencyLog&) = delete;
  LatencyLog& operator=(const LatencyLog&) = delete;

  static std::string PathFor(const std::string& angles_path) {
    return angles_path + ".latency.tsv";
  }
  // An empty path keeps the rows in memory only (for the summary).
  Status Open(const std::string& path);
  // A frame was planned. Rows are written in frame order once nothing more can happen to them.
  void Add(const FrameLatency& row);
  // Frame `frame`'s target went out as command `seq` at `written_s`.
  void Written(int seq, int frame, double written_s);
  void Acked(int seq, double acked_s);
  // Writes every row still held and closes the file; returns the summary.
  LatencySummary Close();
  LatencySummary Summary() const;
  const std::string& path() const { return path_; }

 private:
  void FlushSettled();
  void WriteRow(const FrameLatency& row);
  std::string path_;
  std::FILE* file_ = nullptr;
  std::deque<FrameLatency> pending_;  // rows that may still get a write or an ack
  std::vector<double> to_command_ms_, analysis_ms_, planning_ms_, ack_ms_;
  int frames_ = 0, sent_ = 0, acked_ = 0;
  double first_s_ = kNaN, last_s_ = kNaN;
};

}  // namespace armmimic::robot
