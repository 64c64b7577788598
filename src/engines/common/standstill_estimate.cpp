// EstimateStandstillJoints: the lk engine's standstill calibration (LkEngine::Standstill and
// Calibrated) done ahead of the run, on the same images: the mean of the same frames, cut to the
// same region of interest, with the same parameters.
#include "armmimic/engines/standstill_estimate.h"

#include <memory>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/image_io.h"
#include "armmimic/core/video_source.h"
#include "common/standstill_calibration.h"

namespace armmimic {
namespace {

std::string SizeText(const cv::Size& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

std::unique_ptr<VideoSource> OpenInput(const AnalysisOptions& options, Status* status) {
  if (options.open_source) return options.open_source(status);
  return VideoSource::Open(options.inputs, status);
}

// The mean of frames [first, first + count) of the input, as the engines average them (a float
// sum, then one rounding to 8 bits). `what` names the stretch in errors.
Status MeanOf(const AnalysisOptions& options, int first, int count, const std::string& what,
              cv::Mat* mean) {
  Status st;
  std::unique_ptr<VideoSource> source = OpenInput(options, &st);
  if (!source) return st;
  const VideoInfo info = source->info();
  const std::string range =
      "[" + std::to_string(first) + ", " + std::to_string(first + count) + ")";
  if (info.frame_count >= 0 && first + count > info.frame_count) {
    return Status::Error(info.path + " has " + std::to_string(info.frame_count) + " frames; " +
                         what + " needs frames " + range);
  }
  if (first > 0) {
    st = source->Seek(first);
    if (!st) return st;
  }
  cv::Mat sum;
  Frame frame;
  for (int i = 0; i < count; ++i) {
    Status read;
    if (!source->Read(&frame, &read)) {
      if (!read) return read;
      return Status::Error(info.path + " ended after " + std::to_string(first + i) + " frames; " +
                           what + " needs frames " + range);
    }
    if (sum.empty()) sum = cv::Mat::zeros(frame.image.size(), CV_32FC3);
    if (frame.image.size() != sum.size() || frame.image.type() != CV_8UC3) {
      return Status::Error(info.path + ": frame " + std::to_string(frame.index) +
                           " is not a colour image of " + SizeText(sum.size()));
    }
    cv::accumulate(frame.image, sum);
  }
  sum.convertTo(*mean, CV_8UC3, 1.0 / count);
  return Status::Ok();
}

Status LoadSized(const std::string& path, const std::string& key, const std::string& what,
                 const cv::Size& size, cv::Mat* out) {
  Status st = ReadImage(path, out);
  if (!st) return st.WithKey(key);
  if (out->size() != size) {
    return Status::Error(key, what + " " + path + " is " + SizeText(out->size()) +
                                  " but the video is " + SizeText(size));
  }
  return Status::Ok();
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
  Status st = MeanOf(options, options.start, lk.standstill_frames, "the standstill", &standstill);
  if (!st) return st.WithKey("analysis.start");
  cv::Mat background, arm_length;
  if (!options.background_path.empty()) {
    st = LoadSized(options.background_path, "analysis.background", "the background image",
                   standstill.size(), &background);
  } else {
    st = MeanOf(options, 0, options.background_frames, "the background", &background)
             .WithKey("analysis.background_frames");
  }
  if (!st) return st;
  st = LoadSized(options.arm_length_path, "analysis.arm_length", "the arm-length image",
                 standstill.size(), &arm_length);
  if (!st) return st;

  cv::Rect region(cv::Point(0, 0), standstill.size());
  if (options.roi) {
    if ((*options.roi & region) != *options.roi || options.roi->area() <= 0) {
      return Status::Error("analysis.roi", "the region of interest does not fit in the " +
                                               SizeText(standstill.size()) + " frame");
    }
    region = *options.roi;
  }
  const int side = lk.side == LkArmSide::kLeft ? -1 : lk.side == LkArmSide::kRight ? 1 : 0;
  const StandstillCalibration cal = CalibrateFromStandstill(
      background(region).clone(), standstill(region).clone(), arm_length(region).clone(),
      lk.body_threshold, side, lk.upper_fraction);
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
