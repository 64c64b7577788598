// Least-squares fits of the LK engine (thesis 6.3): eq. 6-16, the motion p' = R p + t of one arm
// part with R = [[a, -b], [b, a]], solved with Eigen; and the 2-means clustering of the moving
// features into upper arm and forearm. Pure functions, no state.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace armmimic::lk {

// p' = [[a, -b], [b, a]] p + t in image pixels (y down). atan2(b, a) is the rotation in image
// axes, i.e. clockwise on screen; the contract's counter-clockwise angle is its negative.
struct Motion2D {
  double a = 1, b = 0;
  cv::Point2d t{0, 0};
  cv::Point2d Apply(const cv::Point2d& p) const {
    return {a * p.x - b * p.y + t.x, b * p.x + a * p.y + t.y};
  }
  // Rotation counter-clockwise on screen, degrees (the contract's sense).
  double RotationCcwDeg() const;
  double Scale() const;
};

// Weighted least squares of eq. 6-16 mapping `from` onto `to` (same size; `weights` empty means
// all 1). Returns false when fewer than two points carry weight or the points coincide.
bool FitMotion(const std::vector<cv::Point2d>& from, const std::vector<cv::Point2d>& to,
               const std::vector<double>& weights, Motion2D* out);

// The same fit with the scale fixed to 1: the rotation of eq. 6-16 (in 2-D the similarity and
// the rigid least squares share it) and the translation that maps the weighted centroids.
bool FitRigidMotion(const std::vector<cv::Point2d>& from, const std::vector<cv::Point2d>& to,
                    const std::vector<double>& weights, Motion2D* out);

// 2-means of (x, y, dx, dy) (thesis 6.3). Deterministic: the two seeds are the features farthest
// apart in position. Returns the label (0 or 1) of each feature; cluster 0 holds the first seed.
std::vector<int> TwoMeans(const std::vector<cv::Point2f>& points,
                          const std::vector<cv::Point2f>& motions, int iterations = 10);

}  // namespace armmimic::lk
