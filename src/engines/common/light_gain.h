// The light on a frame against the learnt background (common/arm_appearance.h's evidence map
// relights the frame with it before comparing).
#pragma once

#include <opencv2/core.hpp>

namespace armmimic::arm {

// The light on the frame against the background, per channel, over blocks of `block` pixels:
// the median ratio of frame to background over the known pixels away from `ignore`, smoothed
// over neighbouring blocks and interpolated to every pixel (CV_32FC3 of the region's size). A
// shadow, a flicker or a drift of the light changes whole areas by one factor; the arm changes a
// part of a block. Blocks with too few pixels take the whole region's median.
cv::Mat LightGain(const cv::Mat& bgr, const cv::Mat& background, const cv::Mat& known,
                  const cv::Mat& ignore, const cv::Rect& region);

}  // namespace armmimic::arm
