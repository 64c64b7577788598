// Median filter (thesis Fig. 3-8) by Huang's running histogram: each output pixel costs one
// column out and one column in, whatever the window.
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <opencv2/core.hpp>

#include "armmimic/core/geometry.h"

namespace armmimic {

void MedianFilter(const cv::Mat& gray, int ksize, cv::Mat* out) {
  if (ksize <= 0 || ksize % 2 == 0) {
    throw std::invalid_argument("MedianFilter: window size must be odd and positive, got " +
                                std::to_string(ksize));
  }
  if (gray.type() != CV_8UC1) throw std::invalid_argument("MedianFilter: image must be CV_8UC1");
  if (out == &gray) throw std::invalid_argument("MedianFilter: output must not be the input");
  const int r = ksize / 2;
  cv::Mat padded;
  cv::copyMakeBorder(gray, padded, r, r, r, r, cv::BORDER_REPLICATE);
  out->create(gray.size(), CV_8UC1);
  if (ksize == 1) {
    gray.copyTo(*out);
    return;
  }
  const int w = gray.cols;
  const int h = gray.rows;
  const int half = (ksize * ksize) / 2;  // rank of the median among ksize^2 values, 0-based
  int hist[256];
  for (int y = 0; y < h; ++y) {
    std::memset(hist, 0, sizeof(hist));
    // Window rows y..y+2r of the padded image, columns 0..2r for x = 0.
    for (int dy = 0; dy < ksize; ++dy) {
      const uint8_t* row = padded.ptr<uint8_t>(y + dy);
      for (int dx = 0; dx < ksize; ++dx) ++hist[row[dx]];
    }
    int median = 0;
    int below = 0;  // number of window values < median
    while (below + hist[median] <= half) below += hist[median++];
    uint8_t* dst = out->ptr<uint8_t>(y);
    dst[0] = static_cast<uint8_t>(median);
    for (int x = 1; x < w; ++x) {
      const int left = x - 1;       // padded column leaving the window
      const int right = x + 2 * r;  // padded column entering it
      for (int dy = 0; dy < ksize; ++dy) {
        const uint8_t* row = padded.ptr<uint8_t>(y + dy);
        const int vo = row[left];
        const int vi = row[right];
        --hist[vo];
        below -= vo < median;
        ++hist[vi];
        below += vi < median;
      }
      if (below > half) {
        do {
          --median;
          below -= hist[median];
        } while (below > half);
      } else {
        while (below + hist[median] <= half) below += hist[median++];
      }
      dst[x] = static_cast<uint8_t>(median);
    }
  }
}

cv::Mat MedianFilter(const cv::Mat& gray, int ksize) {
  cv::Mat out;
  MedianFilter(gray, ksize, &out);
  return out;
}

}  // namespace armmimic
