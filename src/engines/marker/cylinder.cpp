// The lower part as a cylinder seen by a level pinhole camera (docs/marker.md, "The cylinder
// model"). In the horizontal plane through a surface point the camera sees a circle of radius 1
// whose centre is `distance` away in direction phi0 from the optical axis; the point at angle
// theta lies at (sin theta, distance - cos theta) across and along that direction, so the ray to it
// turns by beta = atan2(sin theta, distance - cos theta) from the axis' direction, and
// sin(theta + beta) = distance * sin(beta) inverts it. The silhouette is where
// distance * sin(beta) = +-1.
#include "marker/cylinder.h"

#include <algorithm>
#include <cmath>

namespace armmimic::internal {

MarkerCamera MarkerCamera::FromFov(double fov_deg, cv::Size size) {
  MarkerCamera c;
  c.principal_px = cv::Point2d(size.width / 2.0, size.height / 2.0);
  constexpr double kParallelFocalPx = 1e6;
  c.focal_px =
      fov_deg > 0 ? 0.5 * size.width / std::tan(0.5 * fov_deg * CV_PI / 180) : kParallelFocalPx;
  return c;
}

CylinderView::CylinderView(const MarkerCamera& camera, double left_edge_px, double right_edge_px)
    : camera_(camera) {
  const double f = camera.focal_px;
  const double gl = std::atan((left_edge_px - camera.principal_px.x) / f);
  const double gr = std::atan((right_edge_px - camera.principal_px.x) / f);
  const double half = 0.5 * (gr - gl);
  if (!(half > 0)) return;
  phi0_ = 0.5 * (gl + gr);
  distance_ = 1 / std::sin(half);
  limb_ = 0.5 * CV_PI - half;
  axis_x_ = camera.principal_px.x + f * std::tan(phi0_);
  half_width_px_ = 0.5 * (right_edge_px - left_edge_px);
}

double CylinderView::ThetaFromX(double x) const {
  const double beta = std::atan((x - camera_.principal_px.x) / camera_.focal_px) - phi0_;
  const double s = std::clamp(distance_ * std::sin(beta), -1.0, 1.0);
  return std::asin(s) - beta;
}

double CylinderView::XFromTheta(double theta) const {
  const double beta = std::atan2(std::sin(theta), distance_ - std::cos(theta));
  return camera_.principal_px.x + camera_.focal_px * std::tan(phi0_ + beta);
}

double CylinderView::ThetaSlope(double x) const {
  constexpr double kStep = 0.25;
  return (ThetaFromX(x + kStep) - ThetaFromX(x - kStep)) / (2 * kStep);
}

double CylinderView::Facing(double theta) const {
  return theta + std::atan2(std::sin(theta), distance_ - std::cos(theta));
}

double CylinderView::Depth(double theta) const { return Horizontal(theta).y; }

cv::Point2d CylinderView::Horizontal(double theta) const {
  const double along = distance_ - std::cos(theta);
  const double across = std::sin(theta);
  return {along * std::sin(phi0_) + across * std::cos(phi0_),
          along * std::cos(phi0_) - across * std::sin(phi0_)};
}

void ColumnProfile(const cv::Mat& gray, const std::vector<int>& rows, int x0, int width,
                   std::vector<double>* out) {
  out->assign(width, 0.0);
  if (rows.empty()) return;
  const int a = std::max(0, x0);
  const int b = std::min(gray.cols, x0 + width);
  for (int y : rows) {
    const uchar* row = gray.ptr<uchar>(y);
    for (int x = a; x < b; ++x) (*out)[x - x0] += row[x];
  }
  const double inv = 1.0 / rows.size();
  for (int x = a; x < b; ++x) (*out)[x - x0] *= inv;
}

ProfileEdge FindProfileEdge(const std::vector<double>& p, int x0, int from, int to, int sign) {
  ProfileEdge out;
  const int n = static_cast<int>(p.size());
  from = std::max(from, 2);
  to = std::min(to, n - 3);
  auto g = [&](int i) { return 0.5 * (p[i + 1] - p[i - 1]); };
  auto score = [&](int i) { return sign == 0 ? std::abs(g(i)) : sign * g(i); };
  int best = -1;
  double best_score = 0;
  for (int i = from; i <= to; ++i) {
    const double s = score(i);
    if (s > best_score) {
      best_score = s;
      best = i;
    }
  }
  if (best < 0) return out;
  // A step between pixels i and i+1 of an antialiased edge puts the parabola's vertex through
  // the three gradients exactly on the edge.
  const double gm = score(best - 1), g0 = score(best), gp = score(best + 1);
  const double denom = gm - 2 * g0 + gp;
  const double offset = denom < 0 ? std::clamp(0.5 * (gm - gp) / denom, -0.5, 0.5) : 0.0;
  out.x = x0 + best + offset;
  out.strength = g(best);
  out.found = true;
  return out;
}

double FitProfileEdge(const std::vector<double>& p, int x0, double start, double range,
                      int inside) {
  constexpr int kOutside = 4, kInside = 9;
  constexpr double kSample = 0.05;  // pixels between the model's samples
  constexpr double kBlurs[] = {0.0, 0.5, 0.8, 1.1, 1.4};
  const int n = static_cast<int>(p.size());
  double best_t = start, best_sse = 1e300;
  std::vector<double> weight;
  for (const double blur : kBlurs) {
    // A pixel's response to the scene at offset v from its centre: its own width seen through
    // the blur (a unit box convolved with a Gaussian of standard deviation `blur`).
    const double reach = 0.5 + 4 * blur;
    const int samples = static_cast<int>(std::ceil(2 * reach / kSample));
    weight.assign(samples, 0.0);
    double total = 0;
    for (int j = 0; j < samples; ++j) {
      const double v = -reach + (j + 0.5) * kSample;
      weight[j] = blur == 0 ? (std::abs(v) <= 0.5 ? 1.0 : 0.0)
                            : 0.5 * (std::erf((v + 0.5) / (blur * std::sqrt(2.0))) -
                                     std::erf((v - 0.5) / (blur * std::sqrt(2.0))));
      total += weight[j];
    }
    for (double& w : weight) w /= total;
    // The squared misfit of the best model with the edge at t (1e300 when too few pixels).
    auto misfit = [&](double t) {
      cv::Matx<double, 5, 5> a = cv::Matx<double, 5, 5>::zeros();
      cv::Vec<double, 5> b(0, 0, 0, 0, 0);
      double yy = 0;
      int used = 0;
      const int centre = static_cast<int>(std::lround(t));
      for (int x = centre - kInside - 1; x <= centre + kInside + 1; ++x) {
        const int i = x - x0;
        if (i < 0 || i >= n) continue;
        // Signed distance into the cylinder of the pixel's two ends.
        const double d0 = inside * (x - 0.5 - t), d1 = inside * (x + 0.5 - t);
        if (std::max(d0, d1) < -kOutside || std::min(d0, d1) > kInside) continue;
        cv::Vec<double, 5> f(0, 0, 0, 0, 0);
        for (int j = 0; j < samples; ++j) {
          if (weight[j] == 0) continue;
          const double d = inside * (x - reach + (j + 0.5) * kSample - t);
          if (d > 0) {  // the surface
            f[0] += weight[j];
            f[1] += weight[j] * std::sqrt(d);
            f[2] += weight[j] * d;
          } else {  // the background
            f[3] += weight[j];
            f[4] += weight[j] * d;
          }
        }
        a += f * f.t();
        b += f * p[i];
        yy += p[i] * p[i];
        ++used;
      }
      cv::Vec<double, 5> c;
      if (used < 8 || !cv::solve(a, b, c, cv::DECOMP_SVD)) return 1e300;
      return yy - 2 * c.dot(b) + (c.t() * a * c)(0);
    };
    // A tenth of a pixel at a time, then a fiftieth round the best.
    double coarse = start, coarse_sse = 1e300;
    for (double t = start - range; t <= start + range + 1e-9; t += 0.1) {
      const double sse = misfit(t);
      if (sse < coarse_sse) coarse_sse = sse, coarse = t;
    }
    for (double t = coarse - 0.08; t <= coarse + 0.08 + 1e-9; t += 0.02) {
      const double sse = misfit(t);
      if (sse < best_sse) best_sse = sse, best_t = t;
    }
  }
  return best_t;
}

double DiscCentroidFactor(double delta) {
  if (!(delta > 0)) return 1;
  constexpr int kSteps = 200;
  double num = 0, den = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double t = -delta + (i + 0.5) * 2 * delta / kSteps;
    const double chord = std::sqrt(std::max(0.0, delta * delta - t * t));
    num += std::cos(2 * t) * chord;
    den += std::cos(t) * chord;
  }
  return den > 0 ? num / den : 1;
}

}  // namespace armmimic::internal
