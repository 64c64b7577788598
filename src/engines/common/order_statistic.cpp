#include "common/order_statistic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace armmimic::arm {
namespace {

float MedianOfThree(float a, float b, float c) {
  return std::max(std::min(a, b), std::min(std::max(a, b), c));
}

// Moves the elements of [first, first + n) that satisfy `keep` to the front, in one pass that
// swaps every element and advances on the condition (the elements between the front and the
// element looked at all fail it, so a swap with one of them changes nothing that matters); the
// number kept.
template <typename Keep>
std::size_t Partition(float* first, std::size_t n, Keep keep) {
  std::size_t front = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const float v = first[j];
    first[j] = first[front];
    first[front] = v;
    front += keep(v) ? 1 : 0;
  }
  return front;
}

}  // namespace

float KthSmallest(float* first, std::size_t n, std::size_t k) {
  constexpr std::size_t kSmall = 24;  // below this, nth_element's own insertion sort is as quick
  while (n > kSmall) {
    const float pivot = MedianOfThree(first[0], first[n / 2], first[n - 1]);
    const std::size_t below = Partition(first, n, [pivot](float v) { return v < pivot; });
    if (k < below) {
      n = below;
      continue;
    }
    // The rest are at least the pivot. While some were below it, the rest are fewer: the next
    // round takes them as they are.
    if (below > 0) {
      first += below;
      n -= below;
      k -= below;
      continue;
    }
    // None below: those equal to the pivot come first, then the larger ones. The pivot is one of
    // the values, so the round leaves fewer.
    const std::size_t equal = Partition(first, n, [pivot](float v) { return v <= pivot; });
    if (equal == 0) return pivot;  // a NaN pivot: nothing equals it, and no round would end
    if (k < equal) return pivot;
    first += equal;
    n -= equal;
    k -= equal;
  }
  std::nth_element(first, first + k, first + n);
  return first[k];
}

double NearestRankQuantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  auto at = values.begin() + static_cast<std::ptrdiff_t>(std::lround(q * (values.size() - 1)));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

double TheilSenSlope(const std::vector<cv::Point2d>& points, double min_dy) {
  std::vector<double> slopes;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const double dy = points[j].y - points[i].y;
      if (dy != 0 && std::abs(dy) >= min_dy) slopes.push_back((points[j].x - points[i].x) / dy);
    }
  }
  return NearestRankQuantile(std::move(slopes), 0.5);
}

double MedianIntercept(const std::vector<cv::Point2d>& points, double y0, double slope) {
  std::vector<double> intercepts;
  intercepts.reserve(points.size());
  for (const cv::Point2d& p : points) intercepts.push_back(p.x - slope * (p.y - y0));
  return NearestRankQuantile(std::move(intercepts), 0.5);
}

}  // namespace armmimic::arm
