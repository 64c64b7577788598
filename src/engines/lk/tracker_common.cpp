// Helpers shared by the thesis and the anchored tracker.
#include <cmath>
#include <utility>

#include "lk/tracker.h"

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

TrackerPose MakeTrackerPose(double upper_deg, double fore_deg, bool side_decided,
                            const cv::Point2d& shoulder, const cv::Point2d& elbow,
                            const cv::Point2d& wrist, std::vector<cv::Point2f> upper_features,
                            std::vector<cv::Point2f> fore_features, std::string note) {
  TrackerPose pose;
  pose.ok = true;
  pose.upper_deg = upper_deg;
  pose.fore_deg = fore_deg;
  if (!side_decided) {
    pose.note = "waiting for the first motion to decide the arm's side";
    return pose;
  }
  pose.have_shoulder = true;
  pose.shoulder = shoulder;
  pose.elbow = elbow;
  pose.wrist = wrist;
  pose.upper_features = std::move(upper_features);
  pose.fore_features = std::move(fore_features);
  pose.upper_com =
      pose.upper_features.empty() ? 0.5 * (shoulder + elbow) : MeanPoint(pose.upper_features);
  pose.fore_com =
      pose.fore_features.empty() ? 0.5 * (elbow + wrist) : MeanPoint(pose.fore_features);
  pose.note = std::move(note);
  return pose;
}

}  // namespace armmimic::lk
