#include "common/analysis_inputs.h"

#include <opencv2/imgproc.hpp>

#include "armmimic/core/image_io.h"

namespace armmimic::internal {

std::string SizeText(const cv::Size& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

std::unique_ptr<VideoSource> OpenInput(const AnalysisOptions& options, Status* status) {
  if (options.open_source) return options.open_source(status);
  return VideoSource::Open(options.inputs, status);
}

Status LoadSized(const std::string& path, const std::string& key, const std::string& what,
                 const VideoInfo& video, cv::Mat* out) {
  Status st = ReadImage(path, out);
  if (!st) return st.WithKey(key);
  if (out->size() != video.size) {
    return Status::Error(key, what + " " + path + " is " + SizeText(out->size()) + " but " +
                                  video.path + " is " + SizeText(video.size) +
                                  "; they must have the same size");
  }
  return Status::Ok();
}

Status MeanOfFrames(std::unique_ptr<VideoSource> source, const Status& open_status, int start,
                    int count, const std::string& what, cv::Mat* mean,
                    const AnalysisCallbacks& callbacks) {
  if (count < 1) return Status::Error(what + " needs at least 1 frame");
  if (start < 0) return Status::Error("the first frame of " + what + " must be 0 or more");
  if (!source) return open_status;
  Status st;
  const VideoInfo& info = source->info();
  const std::string range =
      "[" + std::to_string(start) + ", " + std::to_string(start + count) + ")";
  if (info.frame_count >= 0 && start + count > info.frame_count) {
    return Status::Error(info.path + " has " + std::to_string(info.frame_count) + " frames; " +
                         what + " needs frames " + range);
  }
  if (start > 0) {
    st = source->Seek(start);
    if (!st) return st;
  }
  cv::Mat sum;
  Frame frame;
  for (int i = 0; i < count; ++i) {
    if (callbacks.cancel != nullptr && callbacks.cancel->load(std::memory_order_relaxed)) {
      return Status::Ok();
    }
    Status read_status;
    if (!source->Read(&frame, &read_status)) {
      if (!read_status) return read_status;
      return Status::Error(info.path + " ended after " + std::to_string(start + i) + " frames; " +
                           what + " needs frames " + range);
    }
    if (sum.empty()) sum = cv::Mat::zeros(frame.image.size(), CV_32FC3);
    if (frame.image.size() != sum.size()) {
      return Status::Error(info.path + ": frame " + std::to_string(frame.index) + " is " +
                           SizeText(frame.image.size()) + ", the first is " + SizeText(sum.size()));
    }
    cv::accumulate(frame.image, sum);
    if (callbacks.on_progress) callbacks.on_progress(i + 1, count);
  }
  sum.convertTo(*mean, CV_8UC3, 1.0 / count);
  return Status::Ok();
}

}  // namespace armmimic::internal
