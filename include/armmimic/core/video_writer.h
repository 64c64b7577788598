// VideoFileWriter: frames into a video file (AVI with MJPG, XVID, FFV1 ...), for the scenes the
// synthetic generators render. It lives in the video-I/O module, loaded on first use.
#pragma once

#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"

namespace armmimic {

class VideoFileWriter {
 public:
  virtual ~VideoFileWriter() = default;

  // Opens `path` for `fourcc` (four characters) at `fps` and `size`. For MJPG, a `jpeg_quality`
  // in 1..100 selects OpenCV's own MJPEG encoder, which honours it; 0 leaves FFmpeg's default.
  // Returns nullptr with *status set when the codec has no encoder or the file cannot be made;
  // an error about the codec has the key "codec".
  static std::unique_ptr<VideoFileWriter> Open(const std::string& path, const std::string& fourcc,
                                               double fps, cv::Size size, int jpeg_quality,
                                               Status* status);

  // Appends one CV_8UC3 BGR frame of the opened size.
  virtual void Write(const cv::Mat& frame) = 0;
  // Finishes the file; the destructor does it too.
  virtual void Close() = 0;
};

}  // namespace armmimic
