// Helpers shared by the thesis and the anchored tracker.
#include <cmath>

#include "lk_tracker.h"

namespace armmimic::lk {

int DecideSide(const std::vector<cv::Point2d>& shoulders, const std::vector<cv::Point2f>& start,
               const std::vector<cv::Point2f>& now, double min_motion_px, double head_limit_y,
               int min_count) {
  if (shoulders.size() == 1) return 0;
  if (shoulders.size() != 2) return -1;
  const double mid_x = 0.5 * (shoulders[0].x + shoulders[1].x);
  const bool first_is_left = shoulders[0].x <= shoulders[1].x;
  int count[2] = {0, 0};
  for (std::size_t i = 0; i < start.size() && i < now.size(); ++i) {
    const cv::Point2f d = now[i] - start[i];
    if (std::hypot(d.x, d.y) <= min_motion_px) continue;
    if (head_limit_y >= 0 && start[i].y < head_limit_y) continue;
    const bool left = start[i].x < mid_x;
    ++count[left == first_is_left ? 0 : 1];
  }
  if (count[0] >= min_count && count[0] >= 2 * count[1]) return 0;
  if (count[1] >= min_count && count[1] >= 2 * count[0]) return 1;
  return -1;
}

cv::Point2d MeanPoint(const std::vector<cv::Point2f>& points) {
  if (points.empty()) return {kNaN, kNaN};
  double x = 0, y = 0;
  for (const cv::Point2f& p : points) {
    x += p.x;
    y += p.y;
  }
  return {x / points.size(), y / points.size()};
}

}  // namespace armmimic::lk
