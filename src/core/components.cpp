// Connected components by flood fill (thesis section 3.5), 4-connected. A scanline fill: each
// pixel is tested a few times and labelled once, runs are filled with tight row loops.
// Length: FloodFillComponents is one scanline fill whose inner loops share the seed stack.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "armmimic/core/geometry.h"

namespace armmimic {
namespace {

struct Seed {
  int x;
  int y;
};

}  // namespace

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
  min_value = std::max(min_value, 0);
  max_value = std::min(max_value, 255);
  range = std::max(range, 0);

  std::vector<Seed> stack;
  stack.reserve(256);
  for (int y0 = 0; y0 < h; ++y0) {
    const uint8_t* grow = gray.ptr<uint8_t>(y0);
    const int32_t* lrow = lab.ptr<int32_t>(y0);
    for (int x0 = 0; x0 < w; ++x0) {
      // Background runs of zeros (the usual case for masks) are skipped eight bytes at a time.
      if (min_value > 0 && x0 + 8 <= w) {
        uint64_t word;
        std::memcpy(&word, grow + x0, sizeof(word));
        if (word == 0) {
          x0 += 7;
          continue;
        }
      }
      const int seed_value = grow[x0];
      if (seed_value < min_value || seed_value > max_value || lrow[x0] != 0) continue;
      // Joining pixels lie inside the value window and within `range` of the seed's value.
      const int lo = std::max(min_value, seed_value - range);
      const int hi = std::min(max_value, seed_value + range);
      const int label = static_cast<int>(comps.size()) + 1;
      auto joins = [&](const uint8_t* g, const int32_t* l, int x) {
        return l[x] == 0 && g[x] >= lo && g[x] <= hi;
      };
      int min_x = x0, max_x = x0, min_y = y0, max_y = y0, area = 0;
      stack.clear();
      stack.push_back({x0, y0});
      while (!stack.empty()) {
        const Seed s = stack.back();
        stack.pop_back();
        const uint8_t* g = gray.ptr<uint8_t>(s.y);
        int32_t* l = lab.ptr<int32_t>(s.y);
        if (!joins(g, l, s.x)) continue;
        int xl = s.x;
        int xr = s.x;
        while (xl > 0 && joins(g, l, xl - 1)) --xl;
        while (xr + 1 < w && joins(g, l, xr + 1)) ++xr;
        std::fill(l + xl, l + xr + 1, label);
        area += xr - xl + 1;
        min_x = std::min(min_x, xl);
        max_x = std::max(max_x, xr);
        min_y = std::min(min_y, s.y);
        max_y = std::max(max_y, s.y);
        // One seed per run of joining pixels in the rows above and below the span.
        for (int ny : {s.y - 1, s.y + 1}) {
          if (ny < 0 || ny >= h) continue;
          const uint8_t* ng = gray.ptr<uint8_t>(ny);
          const int32_t* nl = lab.ptr<int32_t>(ny);
          bool in_run = false;
          for (int x = xl; x <= xr; ++x) {
            const bool j = joins(ng, nl, x);
            if (j && !in_run) stack.push_back({x, ny});
            in_run = j;
          }
        }
      }
      Component c;
      c.label = label;
      c.seed = cv::Point(x0, y0);
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
