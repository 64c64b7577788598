// Background-subtraction engine, default path: the arm's calibration from the standstill and the
// arm-length image (thesis 5.2.2-5.2.3). The standing body is the standstill's difference from the
// empty room; the straight horizontal arm of the arm-length image (its difference from both) gives
// the side of the moving arm, the shoulder (the arm's axis height, one arm radius inside its inner
// end), the arm's half-width and its reach from the shoulder to the fingertip. Private to
// src/engines.
#pragma once

#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "bgsub/pixels.h"

namespace armmimic::bgsub {

struct ArmCalibration {
  bool ok = false;
  std::string note;  // what is missing when not ok
  cv::Mat body;      // CV_8UC1 0/255: the standing body of the standstill
  std::optional<cv::Rect> body_box;
  int side = 0;                 // the moving arm on screen right +1, left -1
  cv::Point2d shoulder_px;      // region coordinates
  double reach_px = kNaN;       // shoulder to fingertip, the straight arm
  double half_width_px = kNaN;  // half the arm's thickness near the shoulder
};

// `arm_length` is the arm-length image's analysed region (CV_8UC3); `fixed_shoulder`
// (--shoulder) replaces the measured shoulder.
ArmCalibration Calibrate(const PixelModel& pixels, const cv::Mat& arm_length,
                         const std::optional<cv::Point2d>& fixed_shoulder);

}  // namespace armmimic::bgsub
