// Where two colour images of one size differ: the largest of the channels' absolute differences
// above a threshold. The standing person of the thesis protocol's standstill for lk's body box
// and for the standstill calibration (common/standstill_calibration.h).
#pragma once

#include <opencv2/core.hpp>

namespace armmimic {

// CV_8UC1, 255 where max over channels |a - b| > threshold, else 0.
cv::Mat ColourDifferenceMask(const cv::Mat& a, const cv::Mat& b, int threshold);

}  // namespace armmimic
