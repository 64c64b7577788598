#include "common/light_gain.h"

#include <algorithm>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "common/order_statistic.h"

namespace armmimic::arm {

cv::Mat LightGain(const cv::Mat& bgr, const cv::Mat& background, const cv::Mat& known,
                  const cv::Mat& ignore, const cv::Rect& region) {
  constexpr int kBlock = 24, kMinSamples = 24;
  constexpr float kMinGain = 0.4f, kMaxGain = 2.5f;
  const int bx = std::max(1, (region.width + kBlock - 1) / kBlock);
  const int by = std::max(1, (region.height + kBlock - 1) / kBlock);
  // Each block's and channel's ratios in a slot of kMost (every other row of the block, every
  // other pixel of those), their counts beside: kept from call to call, a frame fills a few
  // hundred of them.
  constexpr int kMost = (kBlock / 2) * (kBlock / 2);
  const std::size_t lists = static_cast<std::size_t>(bx * by * 3);
  thread_local std::vector<float> ratios;
  thread_local std::vector<int> counts;
  ratios.resize(lists * kMost);
  counts.assign(lists, 0);
  for (int y = 0; y < region.height; y += 2) {
    const cv::Vec3b* in = bgr.ptr<cv::Vec3b>(y + region.y) + region.x;
    const cv::Vec3f* b = background.ptr<cv::Vec3f>(y + region.y) + region.x;
    const uchar* k = known.ptr<uchar>(y + region.y) + region.x;
    const uchar* ign = ignore.empty() ? nullptr : ignore.ptr<uchar>(y + region.y) + region.x;
    for (int x = y & 2 ? 1 : 0; x < region.width; x += 2) {
      if (!k[x] || (ign && ign[x])) continue;
      const std::size_t list = static_cast<std::size_t>(((y / kBlock) * bx + x / kBlock) * 3);
      for (int c = 0; c < 3; ++c) {
        int& n = counts[list + c];
        ratios[(list + c) * kMost + n++] = (in[x][c] + 4.f) / (b[x][c] + 4.f);
      }
    }
  }
  auto median = [](float* v, int n) { return KthSmallest(v, n, n / 2); };
  // The whole region's median of a channel, taken only when a block needs it (seldom).
  float whole[3] = {0.f, 0.f, 0.f};
  auto whole_median = [&](int c) {
    if (whole[c] > 0) return whole[c];
    std::vector<float> all;
    for (std::size_t list = static_cast<std::size_t>(c); list < lists; list += 3) {
      const float* v = ratios.data() + list * kMost;
      all.insert(all.end(), v, v + counts[list]);
    }
    return whole[c] = all.empty() ? 1.f : median(all.data(), static_cast<int>(all.size()));
  };
  cv::Mat grid(by, bx, CV_32FC3);
  for (int j = 0; j < by; ++j) {
    for (int i = 0; i < bx; ++i) {
      cv::Vec3f& g = grid.at<cv::Vec3f>(j, i);
      for (int c = 0; c < 3; ++c) {
        const std::size_t list = static_cast<std::size_t>((j * bx + i) * 3 + c);
        const int n = counts[list];
        g[c] =
            std::clamp(n >= kMinSamples ? median(ratios.data() + list * kMost, n) : whole_median(c),
                       kMinGain, kMaxGain);
      }
    }
  }
  cv::blur(grid, grid, cv::Size(3, 3), cv::Point(-1, -1), cv::BORDER_REPLICATE);
  cv::Mat gain;
  // Block centres to pixels: the grid's cell i covers [i*kBlock, (i+1)*kBlock).
  cv::resize(grid, gain, cv::Size(bx * kBlock, by * kBlock), 0, 0, cv::INTER_LINEAR);
  return gain(cv::Rect(0, 0, region.width, region.height));
}

}  // namespace armmimic::arm
