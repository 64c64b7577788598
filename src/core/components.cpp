// Connected components by flood fill (thesis section 3.5), 4-connected.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#include "armmimic/core/geometry.h"

namespace armmimic {

std::vector<Component> FloodFillComponents(const cv::Mat& gray, int min_value, int max_value,
                                           int range, cv::Mat* labels) {
  if (!gray.empty() && gray.type() != CV_8UC1) {
    throw std::invalid_argument("FloodFillComponents: image must be CV_8UC1");
  }
  const int w = gray.cols;
  const int h = gray.rows;
  cv::Mat local;
  cv::Mat& lab = labels ? *labels : local;
  lab.create(h, w, CV_32S);
  lab.setTo(0);
  std::vector<Component> comps;
  if (gray.empty()) return comps;

  // Pixel stack as flat indices; sized once, so the fill itself never allocates.
  std::vector<int> stack;
  stack.reserve(static_cast<size_t>(w) * h + 4);
  for (int y0 = 0; y0 < h; ++y0) {
    const uint8_t* grow = gray.ptr<uint8_t>(y0);
    const int32_t* lrow = lab.ptr<int32_t>(y0);
    for (int x0 = 0; x0 < w; ++x0) {
      const int seed_value = grow[x0];
      if (lrow[x0] != 0 || seed_value < min_value || seed_value > max_value) continue;
      // A neighbour joins when it is inside the value window and within `range` of the seed.
      const int lo = std::max(min_value, seed_value - range);
      const int hi = std::min(max_value, seed_value + range);
      const int label = static_cast<int>(comps.size()) + 1;
      Component c;
      c.label = label;
      c.seed = cv::Point(x0, y0);
      int min_x = x0, max_x = x0, min_y = y0, max_y = y0, area = 0;
      auto visit = [&](int x, int y) {
        int32_t& l = lab.ptr<int32_t>(y)[x];
        if (l != 0) return;
        const int v = gray.ptr<uint8_t>(y)[x];
        if (v < lo || v > hi) return;
        l = label;
        stack.push_back(y * w + x);
      };
      visit(x0, y0);
      while (!stack.empty()) {
        const int p = stack.back();
        stack.pop_back();
        const int x = p % w;
        const int y = p / w;
        ++area;
        min_x = std::min(min_x, x);
        max_x = std::max(max_x, x);
        min_y = std::min(min_y, y);
        max_y = std::max(max_y, y);
        if (x > 0) visit(x - 1, y);
        if (x + 1 < w) visit(x + 1, y);
        if (y > 0) visit(x, y - 1);
        if (y + 1 < h) visit(x, y + 1);
      }
      c.area_px = area;
      c.box = cv::Rect(min_x, min_y, max_x - min_x + 1, max_y - min_y + 1);
      comps.push_back(c);
    }
  }
  return comps;
}

std::vector<Component> MaskComponents(const cv::Mat& mask, cv::Mat* labels) {
  // Every non-zero value lies in [1, 255] and within 255 of any other: one window, no range.
  return FloodFillComponents(mask, 1, 255, 255, labels);
}

}  // namespace armmimic
