#include "lk/fit.h"

#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "armmimic/core/angles.h"

namespace armmimic::lk {

double Motion2D::RotationCcwDeg() const { return -DegFromRad(std::atan2(b, a)); }

double Motion2D::Scale() const { return std::hypot(a, b); }

bool FitMotion(const std::vector<cv::Point2d>& from, const std::vector<cv::Point2d>& to,
               const std::vector<double>& weights, Motion2D* out) {
  // Normal equations of the stacked rows
  //   [x -y 1 0] [a b tx ty]^T = x'
  //   [y  x 0 1] [a b tx ty]^T = y'
  Eigen::Matrix4d ata = Eigen::Matrix4d::Zero();
  Eigen::Vector4d atb = Eigen::Vector4d::Zero();
  int used = 0;
  for (std::size_t i = 0; i < from.size() && i < to.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    if (!(w > 0)) continue;
    ++used;
    const Eigen::Vector4d r1(from[i].x, -from[i].y, 1, 0);
    const Eigen::Vector4d r2(from[i].y, from[i].x, 0, 1);
    ata.noalias() += w * (r1 * r1.transpose() + r2 * r2.transpose());
    atb.noalias() += w * (r1 * to[i].x + r2 * to[i].y);
  }
  if (used < 2) return false;
  const Eigen::LDLT<Eigen::Matrix4d> ldlt(ata);
  if (ldlt.info() != Eigen::Success) return false;
  // A rank-deficient system (all points in one place) has a tiny pivot.
  const Eigen::Vector4d d = ldlt.vectorD().cwiseAbs();
  if (d.minCoeff() <= 1e-9 * std::max(1.0, d.maxCoeff())) return false;
  const Eigen::Vector4d x = ldlt.solve(atb);
  if (!x.allFinite()) return false;
  out->a = x[0];
  out->b = x[1];
  out->t = {x[2], x[3]};
  return true;
}

bool FitRigidMotion(const std::vector<cv::Point2d>& from, const std::vector<cv::Point2d>& to,
                    const std::vector<double>& weights, Motion2D* out) {
  Motion2D m;
  if (!FitMotion(from, to, weights, &m)) return false;
  const double scale = m.Scale();
  if (!(scale > 1e-9)) return false;
  m.a /= scale;
  m.b /= scale;
  cv::Point2d cf(0, 0), ct(0, 0);
  double total = 0;
  for (std::size_t i = 0; i < from.size() && i < to.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    if (!(w > 0)) continue;
    cf += w * from[i];
    ct += w * to[i];
    total += w;
  }
  cf *= 1.0 / total;
  ct *= 1.0 / total;
  m.t = {0, 0};
  m.t = ct - m.Apply(cf);
  *out = m;
  return true;
}

std::vector<int> TwoMeans(const std::vector<cv::Point2f>& points,
                          const std::vector<cv::Point2f>& motions, int iterations) {
  const std::size_t n = points.size();
  std::vector<int> labels(n, 0);
  if (n < 2) return labels;
  auto vec = [&](std::size_t i) {
    return cv::Vec4d(points[i].x, points[i].y, motions[i].x, motions[i].y);
  };
  // Seeds: the two features farthest apart in position (deterministic).
  std::size_t s0 = 0, s1 = 1;
  double best = -1;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const cv::Point2f d = points[i] - points[j];
      const double dd = d.dot(d);
      if (dd > best) {
        best = dd;
        s0 = i;
        s1 = j;
      }
    }
  }
  cv::Vec4d c[2] = {vec(s0), vec(s1)};
  for (int it = 0; it < iterations; ++it) {
    bool changed = false;
    cv::Vec4d sum[2] = {cv::Vec4d::all(0), cv::Vec4d::all(0)};
    int count[2] = {0, 0};
    for (std::size_t i = 0; i < n; ++i) {
      const cv::Vec4d v = vec(i);
      const int l =
          cv::norm(v - c[0], cv::NORM_L2SQR) <= cv::norm(v - c[1], cv::NORM_L2SQR) ? 0 : 1;
      if (l != labels[i] || it == 0) changed = changed || l != labels[i];
      labels[i] = l;
      sum[l] += v;
      ++count[l];
    }
    for (int k = 0; k < 2; ++k) {
      if (count[k] > 0) c[k] = sum[k] * (1.0 / count[k]);
    }
    if (!changed && it > 0) break;
  }
  return labels;
}

}  // namespace armmimic::lk
