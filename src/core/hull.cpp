// Convex hull by Sklansky's three-coins scan (thesis section 3.6) and convexity defects.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "armmimic/core/geometry.h"

namespace armmimic {
namespace {

// Twice the signed area of (o, a, b) in raw coordinates: > 0 when o->a->b turns towards +y
// from +x (a "left" turn with y taken as up, i.e. clockwise as seen on screen).
int64_t Cross(const cv::Point& o, const cv::Point& a, const cv::Point& b) {
  return int64_t(a.x - o.x) * (b.y - o.y) - int64_t(a.y - o.y) * (b.x - o.x);
}

}  // namespace

std::vector<int> ConvexHullIndices(const std::vector<cv::Point>& points) {
  const int n = static_cast<int>(points.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  // Sklansky's scan needs the points as a star-shaped sequence; sorting by (x, y) makes the
  // lower and the upper chain each monotone, where the three-coins scan is exact.
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const cv::Point& p = points[a];
    const cv::Point& q = points[b];
    return p.x != q.x ? p.x < q.x : p.y < q.y;
  });
  order.erase(
      std::unique(order.begin(), order.end(), [&](int a, int b) { return points[a] == points[b]; }),
      order.end());
  const int m = static_cast<int>(order.size());
  if (m <= 2) return order;

  // Three coins: the last two hull vertices and the candidate. While the rear coin, the middle
  // coin and the candidate do not make a strict turn in the hull's direction, the middle coin
  // is not a hull vertex: take it back and look again.
  std::vector<int> hull(2 * m);
  int k = 0;
  for (int i = 0; i < m; ++i) {  // first chain, left to right
    while (k >= 2 && Cross(points[hull[k - 2]], points[hull[k - 1]], points[order[i]]) <= 0) --k;
    hull[k++] = order[i];
  }
  const int first_chain = k + 1;
  for (int i = m - 2; i >= 0; --i) {  // second chain, right to left
    while (k >= first_chain &&
           Cross(points[hull[k - 2]], points[hull[k - 1]], points[order[i]]) <= 0) {
      --k;
    }
    hull[k++] = order[i];
  }
  hull.resize(k - 1);  // the last vertex is the first again
  if (hull.size() == 2 && points[hull[0]] == points[hull[1]]) hull.resize(1);
  return hull;
}

std::vector<cv::Point> ConvexHull(const std::vector<cv::Point>& points) {
  const std::vector<int> idx = ConvexHullIndices(points);
  std::vector<cv::Point> out;
  out.reserve(idx.size());
  for (int i : idx) out.push_back(points[i]);
  return out;
}

std::vector<ConvexityDefect> ConvexityDefects(const std::vector<cv::Point>& contour,
                                              const std::vector<int>& hull_indices) {
  std::vector<ConvexityDefect> defects;
  const int n = static_cast<int>(contour.size());
  if (n < 4 || hull_indices.size() < 3) return defects;
  // Walk the contour in its own order between hull vertices, whatever the hull's orientation.
  std::vector<int> hull;
  hull.reserve(hull_indices.size());
  for (int h : hull_indices) {
    if (h >= 0 && h < n) hull.push_back(h);
  }
  std::sort(hull.begin(), hull.end());
  hull.erase(std::unique(hull.begin(), hull.end()), hull.end());
  const int hn = static_cast<int>(hull.size());
  if (hn < 3) return defects;
  for (int i = 0; i < hn; ++i) {
    const int start = hull[i];
    const int end = hull[(i + 1) % hn];
    const cv::Point& a = contour[start];
    const cv::Point& b = contour[end];
    const double ex = b.x - a.x;
    const double ey = b.y - a.y;
    const double len = std::sqrt(ex * ex + ey * ey);
    const double scale = len > 0 ? 1.0 / len : 0.0;
    double best = 0;
    int best_index = -1;
    for (int j = (start + 1) % n; j != end; j = (j + 1) % n) {
      const double dist = std::abs(ex * (contour[j].y - a.y) - ey * (contour[j].x - a.x)) * scale;
      if (dist > best) {
        best = dist;
        best_index = j;
      }
    }
    if (best_index >= 0) defects.push_back({start, end, best_index, best});
  }
  std::stable_sort(
      defects.begin(), defects.end(),
      [](const ConvexityDefect& p, const ConvexityDefect& q) { return p.depth_px > q.depth_px; });
  return defects;
}

}  // namespace armmimic
