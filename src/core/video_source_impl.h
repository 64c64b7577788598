// The three VideoSource implementations, created by VideoSource::Open after it has checked
// the inputs exist and has decided their kind. Private to src/core.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "armmimic/core/video_source.h"

namespace armmimic::internal {

// `path` is an existing, readable, non-empty file with a video extension.
std::unique_ptr<VideoSource> OpenVideoFileSource(const std::string& path, Status* status);
// `files` are existing image files (in the order to read them); `shown_path` goes to info().path.
std::unique_ptr<VideoSource> OpenImageSource(const std::vector<std::string>& files,
                                             const std::string& shown_path, Status* status);
// "camera:N" or a stream URL.
std::unique_ptr<VideoSource> OpenCameraSource(const std::string& spec, Status* status);

// Hands out a decoded frame of a stream (video file or camera) as frame `index`: refuses a
// frame whose size differs from the stream's (the message names the source and the frame),
// then fills the frame's image, index and time.
inline bool DeliverStreamFrame(const cv::Mat& img, int index, const VideoInfo& info, Frame* frame,
                               Status* status) {
  if (img.size() != info.size) {
    *status = Status::Error(info.path + ": frame " + std::to_string(index) + " changes size");
    return false;
  }
  frame->image = img;
  frame->index = index;
  frame->time_s = info.fps > 0 ? index / info.fps : 0;
  frame->name.clear();
  return true;
}

}  // namespace armmimic::internal
