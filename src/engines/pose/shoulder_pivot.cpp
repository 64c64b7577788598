#include "pose/shoulder_pivot.h"

#include <algorithm>
#include <cmath>

namespace armmimic::internal {
namespace {

// The torso's frame: `up` from the hips towards the shoulders, `across` a quarter turn from it,
// both one torso length long.
struct TorsoFrame {
  cv::Point2d up, across;
  double length2;
  cv::Point2d To(const cv::Point2d& v) const {
    return {v.dot(up) / length2, v.dot(across) / length2};
  }
  cv::Point2d From(const cv::Point2d& p) const { return p.x * up + p.y * across; }
};

}  // namespace

cv::Point2d ShoulderPivot::Add(const cv::Point2d& shoulder, const cv::Point2d& elbow,
                               const cv::Point2d& hips, const cv::Point2d& shoulders) {
  const cv::Point2d up = shoulders - hips;
  const double length2 = up.dot(up);
  if (length2 < 1) return shoulder;
  const TorsoFrame frame{up, cv::Point2d(-up.y, up.x), length2};
  elbows_.push_back(frame.To(elbow - shoulder));
  if (elbows_.size() > kWindow) elbows_.erase(elbows_.begin());
  Fit();
  return sure_ ? shoulder + frame.From(centre_) : shoulder;
}

void ShoulderPivot::Fit() {
  sure_ = false;
  if (elbows_.size() < kMinFrames) return;
  // Kasa's algebraic circle: x^2 + y^2 + D x + E y + F = 0 in the least-squares sense.
  cv::Matx33d a = cv::Matx33d::zeros();
  cv::Vec3d b(0, 0, 0);
  for (const cv::Point2d& p : elbows_) {
    const cv::Vec3d row(p.x, p.y, 1);
    a += row * row.t();
    b -= (p.x * p.x + p.y * p.y) * row;
  }
  if (!(std::abs(cv::determinant(a)) > 1e-12)) return;  // the elbows lie on a line or a point
  const cv::Vec3d def = a.solve(b, cv::DECOMP_LU);
  const cv::Point2d centre(-def[0] / 2, -def[1] / 2);
  const double r2 = centre.dot(centre) - def[2];
  if (!(r2 > 0)) return;
  const double r = std::sqrt(r2);
  double spread = 0;
  std::vector<double> angles;
  angles.reserve(elbows_.size());
  for (const cv::Point2d& p : elbows_) {
    const cv::Point2d d = p - centre;
    spread += (cv::norm(d) - r) * (cv::norm(d) - r);
    angles.push_back(std::atan2(d.y, d.x));
  }
  spread = std::sqrt(spread / static_cast<double>(elbows_.size())) / r;
  // The arc the elbows span: the circle less its widest empty gap.
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * M_PI - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i) gap = std::max(gap, angles[i] - angles[i - 1]);
  const double arc_deg = (2 * M_PI - gap) * 180 / M_PI;
  if (arc_deg < kMinArcDeg || spread > kMaxSpread || cv::norm(centre) > kMaxOffset * r) return;
  centre_ = centre;
  sure_ = true;
}

}  // namespace armmimic::internal
