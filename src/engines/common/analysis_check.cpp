// CheckAnalysisInputs: a dry pass of the analysis that stops at its first row, so a live run can
// refuse a bad input before it touches the robot (docs/live.md).
#include <atomic>

#include "armmimic/engines/analysis.h"

namespace armmimic {

Status CheckAnalysisInputs(const AnalysisOptions& given) {
  AnalysisOptions options = given;
  options.realtime = false;  // no pacing: the check reads as fast as the engine goes
  std::atomic<bool> stop{false};
  bool live = false;
  int frames_read = 0;
  AnalysisCallbacks cb;
  cb.cancel = &stop;
  cb.on_open = [&live](const VideoInfo& info) { live = info.kind == SourceKind::kCamera; };
  cb.on_frame = [&](const Frame&, std::chrono::steady_clock::time_point) {
    ++frames_read;
    if (live) stop.store(true);  // a camera or stream: one decoded frame is enough
  };
  cb.on_measurement = [&stop](const Frame&, const ArmMeasurement& m) {
    if (m.row()) stop.store(true);  // a file: its first analysed row
  };
  AnalysisSummary summary;
  const Status st = RunAnalysis(options, cb, &summary);
  if (!st) return st;
  const std::string name = summary.video.path.empty() ? options.inputs.front() : summary.video.path;
  if (frames_read == 0) {
    return Status::Error(name + ": no frame could be decoded");
  }
  if (!live && summary.frames == 0) {
    return Status::Error(name + ": ended after " + std::to_string(frames_read) +
                         " frames without an analysed frame");
  }
  return Status::Ok();
}

}  // namespace armmimic
