// MimicRun: live mimicking in one Qt Core object, shared by `armmimic-cli mimic` and the desktop
// application's Mimic live mode (docs/live.md). The analysis (RunAnalysis through
// AnalyzeToFile, so the angle file is the one `analyze` writes) runs on its own thread; each
// analysed frame is posted to the object's thread, where robot::LiveStream plans it and writes
// a command over the serial link whenever the controller has acknowledged the last one.
//
// It ends when the input ends (ok), when Stop() is called (the operator, Ctrl-C), or when the
// link fails (lost port, silent or refusing controller): the analysis is cancelled (its rows
// are kept in a file marked complete=no), no new command is written, the line in flight gets its
// acknowledgement (or its timeout), the journal records the last acknowledged move, and
// finished() comes once.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include <QObject>
#include <QPointer>
#include <QString>

#include "armmimic/core/status.h"
#include "armmimic/engines/analysis.h"
#include "armmimic/robot/live_stream.h"

#include "armmimic/serial/serial_link.h"

namespace armmimic::live {

struct MimicOptions {
  AnalysisOptions analysis;         // inputs, engine and calibration; realtime for a file
  std::string angles_path;          // the angle file written as frames are analysed
  robot::LiveStreamOptions stream;  // planner, profile, journal and latency paths
  // Used when the source reports no frame rate (some cameras and streams).
  double fallback_fps = 30;
};

class MimicRun : public QObject {
  Q_OBJECT
 public:
  // `link`: an open port (not owned; it may be deleted first, which ends the run), or nullptr for
  // a dry run (lines go to the dry writer).
  explicit MimicRun(serial::SerialLink* link, QObject* parent = nullptr);
  ~MimicRun() override;  // cancels and joins the analysis thread

  void SetDryWriter(std::function<void(const robot::LinkLine&)> writer);
  // Called on the analysis thread for every frame the engine processed (a live overlay).
  void SetFrameHook(std::function<void(const Frame&, const ArmMeasurement&)> hook);

  // Starts the stream (the controller is woken up, the SPEED line goes first) and the analysis.
  Status Start(const MimicOptions& options);
  // Ends the run: no new command, the analysis stops. A second call also abandons the line in
  // flight (it was written whole; its acknowledgement is no longer awaited).
  void Stop(const std::string& reason);
  // The dead-man: while held, no new command is written.
  void SetHeld(bool held);
  bool running() const { return started_ && !finished_; }

  double Now() const;  // the stream clock, seconds since Start()
  const robot::LiveStream& stream() const { return stream_; }
  const AnalysisSummary& analysis_summary() const { return summary_; }
  // Exit status for the shells: 0 input ended, 1 link or analysis failure or stopped.
  bool ended_normally() const { return ended_normally_; }
  // The setting finished()'s message is about (Status::key()), or "".
  const std::string& failure_key() const { return failure_key_; }

 signals:
  // Every analysed frame, after planning: the planner's target (valid when `has_target`).
  void framePlanned(int frame, bool ok, bool has_target, const robot::JointArray& target,
                    const QString& hold);
  void commandWritten(const robot::JointArray& target, int frame);
  void finished(bool ok, const QString& message);

 private:
  void OnOpen(const VideoInfo& info);
  void OnRow(const AngleRow& row, double capture_s, double analysed_s);
  void OnAnalysisDone(const Status& status, const AnalysisSummary& summary);
  void OnLinkFinished(bool ok);
  void OnLinkGone();
  void MaybeFinish();
  double Seconds(std::chrono::steady_clock::time_point t) const;

  QPointer<serial::SerialLink> link_;  // null once the port's owner has deleted it
  MimicOptions options_;
  robot::LiveStream stream_;
  std::function<void(const robot::LinkLine&)> dry_writer_;
  std::function<void(const Frame&, const ArmMeasurement&)> frame_hook_;
  std::thread thread_;
  std::atomic<bool> cancel_{false};
  std::chrono::steady_clock::time_point epoch_;
  bool dry_run_ = false;
  bool started_ = false;
  bool stream_begun_ = false;
  bool analysis_done_ = false;
  bool link_done_ = false;
  bool finished_ = false;
  bool ended_normally_ = false;
  int stops_ = 0;
  std::string failure_;  // the first thing that went wrong
  std::string failure_key_;

  AnalysisSummary summary_;
};

}  // namespace armmimic::live
