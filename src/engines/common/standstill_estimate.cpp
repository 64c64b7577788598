// EstimateStandstillJoints: the lk engine's standstill calibration (LkEngine::Standstill and
// Calibrated) done ahead of the run, on the same images: the mean of the same frames, cut to the
// same region of interest, with the same parameters.
#include "armmimic/engines/standstill_estimate.h"

#include <memory>

#include "armmimic/core/video_source.h"
#include "common/analysis_inputs.h"
#include "common/standstill_calibration.h"

namespace armmimic {
namespace {

using internal::SizeText;

// The mean of frames [first, first + count) of the input, as the engines average them; `info`
// gets the input's description.
Status MeanOf(const AnalysisOptions& options, int first, int count, const std::string& what,
              cv::Mat* mean, VideoInfo* info) {
  Status st;
  std::unique_ptr<VideoSource> source = internal::OpenInput(options, &st);
  if (source) *info = source->info();
  return internal::MeanOfFrames(std::move(source), st, first, count, what, mean);
}

}  // namespace

Status EstimateStandstillJoints(const AnalysisOptions& options, StandstillJoints* out) {
  *out = StandstillJoints();
  const EngineKind kind = options.engine.kind;
  if (kind != EngineKind::kLk && kind != EngineKind::kHybrid) {
    return Status::Error("analysis.engine",
                         std::string("the ") + EngineName(kind) +
                             " engine does not calibrate from the standstill (lk and hybrid do)");
  }
  if (options.background_path.empty() && options.background_frames <= 0) {
    return Status::Error("analysis.background",
                         "calibrating from the standstill needs a background: an image of the "
                         "empty room or frames to average");
  }
  if (options.arm_length_path.empty()) {
    return Status::Error("analysis.arm_length",
                         "calibrating from the standstill needs the arm-length image (the same "
                         "arm held straight and horizontal)");
  }
  if (options.inputs.empty() && !options.open_source) {
    return Status::Error("calibrating from the standstill needs a video: open one first");
  }
  const LkOptions& lk = options.engine.lk;  // the hybrid engine runs lk with these
  if (options.start < 0) return Status::Error("analysis.start", "the start frame is negative");
  cv::Mat standstill;
  VideoInfo info;
  Status st =
      MeanOf(options, options.start, lk.standstill_frames, "the standstill", &standstill, &info);
  if (!st) return st.WithKey("analysis.start");
  cv::Mat background, arm_length;
  if (!options.background_path.empty()) {
    st = internal::LoadSized(options.background_path, "analysis.background", "the background image",
                             info, &background);
  } else {
    st = MeanOf(options, 0, options.background_frames, "the background", &background, &info)
             .WithKey("analysis.background_frames");
  }
  if (!st) return st;
  st = internal::LoadSized(options.arm_length_path, "analysis.arm_length", "the arm-length image",
                           info, &arm_length);
  if (!st) return st;

  cv::Rect region(cv::Point(0, 0), standstill.size());
  if (options.roi) {
    if ((*options.roi & region) != *options.roi || options.roi->area() <= 0) {
      return Status::Error("analysis.roi", "the region of interest does not fit in the " +
                                               SizeText(standstill.size()) + " frame");
    }
    region = *options.roi;
  }
  const StandstillCalibration cal = CalibrateFromStandstill(
      background(region).clone(), standstill(region).clone(), arm_length(region).clone(), lk);
  if (!cal.ok) return Status::Error("cannot calibrate from the standstill: " + cal.note);
  const cv::Point2d offset(region.tl());
  out->frame = options.start + lk.standstill_frames - 1;
  out->shoulder_px = cal.shoulder + offset;
  out->elbow_px = cal.elbow + offset;
  out->wrist_px = cal.wrist + offset;
  out->description = cal.Describe(offset);
  return Status::Ok();
}

}  // namespace armmimic
