// Frame: one decoded image of a video, an image file or a camera, with its position in the source.
#pragma once

#include <string>

#include <opencv2/core.hpp>

namespace armmimic {

struct Frame {
  cv::Mat image;      // CV_8UC3, BGR
  int index = 0;      // 0-based index in the source, counted from its first frame
  double time_s = 0;  // index / fps for videos; 0 for still images without a rate
  std::string name;   // file name for image inputs; empty for videos
};

}  // namespace armmimic
