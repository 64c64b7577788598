#include "common/colour_difference.h"

#include <vector>

namespace armmimic {

cv::Mat ColourDifferenceMask(const cv::Mat& a, const cv::Mat& b, int threshold) {
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  std::vector<cv::Mat> channels;
  cv::split(diff, channels);
  cv::Mat largest = channels[0];
  for (std::size_t c = 1; c < channels.size(); ++c) cv::max(largest, channels[c], largest);
  return largest > threshold;
}

}  // namespace armmimic
