// The shoulder from the background and the standstill (thesis 6.1, the same rule as 5.2.2): the
// standing body is where the standstill mean differs from the background; the shoulder lies at
// 3/5 of the body box height (from its bottom) and 1/6 or 5/6 of its width.
#pragma once

#include <opencv2/core.hpp>

#include "armmimic/engines/lk_options.h"

namespace armmimic::lk {

struct BodyBox {
  bool found = false;
  cv::Rect box;
  cv::Point2d left_shoulder, right_shoulder;  // as seen on screen
};

// `background` and `standstill` are CV_8UC3 of one size. The body is the largest connected
// region whose largest channel difference exceeds options.body_threshold.
BodyBox FindBodyBox(const cv::Mat& background, const cv::Mat& standstill, const LkOptions& options);

}  // namespace armmimic::lk
