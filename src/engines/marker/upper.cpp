// The upper marker and the bend (docs/marker.md, "Bend"). The pivot lies on the lower part's axis
// at the height the reference gave; the upper part's axis leaves it at bend beta in the plane
// that turns with the yaw, and the upper marker sits e along that axis and one radius in front
// of it, on the side that faced the camera at zero yaw (plus the yaw). Its coverage-weighted
// centroid lies k times closer to the axis sideways than the disc's centre (DiscCentroidFactor).
#include "marker/upper.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "armmimic/core/angles.h"
#include "marker/detect.h"

namespace armmimic::internal {
namespace {

struct Frame3 {
  cv::Point2d axis, towards, across;  // horizontal (x, z): axis position, unit vectors
};

Frame3 Horizontal(const CylinderView& cyl) {
  const double p = cyl.axis_angle(), d = cyl.distance();
  return {{d * std::sin(p), d * std::cos(p)},
          {-std::sin(p), -std::cos(p)},
          {std::cos(p), -std::sin(p)}};
}

cv::Point2d Project(const CylinderView& cyl, double x, double y, double z) {
  const MarkerCamera& c = cyl.camera();
  return {c.principal_px.x + c.focal_px * x / z, c.principal_px.y - c.focal_px * y / z};
}

double Sample(const cv::Mat& gray, cv::Point2d p) {
  const int x = static_cast<int>(std::lround(p.x)), y = static_cast<int>(std::lround(p.y));
  if (x < 0 || y < 0 || x >= gray.cols || y >= gray.rows) return kNaN;
  return gray.at<uchar>(y, x);
}

double Bilinear(const cv::Mat& gray, cv::Point2d p) {
  const int x = static_cast<int>(std::floor(p.x)), y = static_cast<int>(std::floor(p.y));
  if (x < 0 || y < 0 || x + 1 >= gray.cols || y + 1 >= gray.rows) return kNaN;
  const double fx = p.x - x, fy = p.y - y;
  const uchar* r0 = gray.ptr<uchar>(y);
  const uchar* r1 = gray.ptr<uchar>(y + 1);
  return (1 - fy) * ((1 - fx) * r0[x] + fx * r0[x + 1]) + fy * ((1 - fx) * r1[x] + fx * r1[x + 1]);
}

// The upper part's axis and silhouette near the marker for `bend`: image unit vectors along and
// across the axis, and the silhouette's two edges as offsets across from `at`.
struct UpperFrame {
  cv::Point2d along, across;
  double edge_lo = -1e9, edge_hi = 1e9;
};

UpperFrame FrameAt(const CylinderView& cyl, const UpperCalibration& cal, double yaw, double bend,
                   cv::Point2d at);

}  // namespace

namespace {

UpperFrame FrameAt(const CylinderView& cyl, const UpperCalibration& cal, double yaw, double bend,
                   cv::Point2d at) {
  const Frame3 h = Horizontal(cyl);
  const double tf = cal.theta0 + yaw;
  const cv::Point2d side = -std::sin(tf) * h.towards + std::cos(tf) * h.across;
  const cv::Vec3d u(-std::sin(bend) * side.x, std::cos(bend), -std::sin(bend) * side.y);
  const cv::Vec3d a = cv::Vec3d(h.axis.x, cal.pivot_height, h.axis.y) + cal.e * u;
  const cv::Vec3d b = a + 0.1 * u;
  const cv::Point2d pa = Project(cyl, a[0], a[1], a[2]), pb = Project(cyl, b[0], b[1], b[2]);
  UpperFrame f;
  f.along = (pb - pa) * (1.0 / std::max(1e-9, cv::norm(pb - pa)));
  f.across = {-f.along.y, f.along.x};
  const cv::Vec3d out = cv::normalize(u.cross(a));
  const cv::Vec3d e0 = a - out, e1 = a + out;
  const double c0 = (Project(cyl, e0[0], e0[1], e0[2]) - at).dot(f.across);
  const double c1 = (Project(cyl, e1[0], e1[1], e1[2]) - at).dot(f.across);
  f.edge_lo = std::min(c0, c1);
  f.edge_hi = std::max(c0, c1);
  return f;
}

}  // namespace

bool UpperCentroid(const cv::Mat& gray, const CylinderView& cyl, const UpperCalibration& cal,
                   double yaw, double bend, cv::Point2d* centre) {
  // Twice: the second pass along the axis of the bend the first centroid gives.
  const double r = 0.5 * std::max(3, cal.marker_height_px);
  const double half_a = 1.3 * r + 2, half_c = 1.3 * r + 2;
  constexpr int kStrip = 4;
  const double keep = 1 - cal.marker_ratio;
  for (int pass = 0; pass < 2; ++pass) {
    const UpperFrame f = FrameAt(cyl, cal, yaw, bend, *centre);
    const int c_lo = static_cast<int>(std::ceil(std::max(-half_c, f.edge_lo + 1)));
    const int c_hi = static_cast<int>(std::floor(std::min(half_c, f.edge_hi - 1)));
    const int a_max = static_cast<int>(std::ceil(half_a));
    if (c_hi - c_lo < 2) return false;
    double sum = 0, sa = 0, sc = 0;
    for (int c = c_lo; c <= c_hi; ++c) {
      // The surface's level at this offset across the axis: the strips beyond the marker along
      // the axis (shading on a cylinder does not change along it).
      double level = 0;
      int n = 0;
      for (int k = 1; k <= kStrip; ++k) {
        for (double sign : {-1.0, 1.0}) {
          const double v = Bilinear(gray, *centre + sign * (a_max + k) * f.along + c * f.across);
          if (!std::isnan(v)) level += v, ++n;
        }
      }
      if (n < kStrip) return false;
      level /= n;
      if (level * keep < 8) continue;
      for (int a = -a_max; a <= a_max; ++a) {
        const double v = Bilinear(gray, *centre + a * f.along + c * f.across);
        if (std::isnan(v)) return false;
        const double w = std::clamp((level - v) / (level * keep), 0.0, 1.0);
        sum += w;
        sa += w * a;
        sc += w * c;
      }
    }
    if (sum < 1) return false;
    *centre += (sa / sum) * f.along + (sc / sum) * f.across;
    bend = SolveBend(cyl, cal, yaw, *centre, nullptr);
  }
  return true;
}

double UpperSilhouetteSupport(const cv::Mat& gray, const CylinderView& cyl,
                              const UpperCalibration& cal, double yaw, double bend) {
  const cv::Point2d pivot_h = Horizontal(cyl).axis;
  const cv::Vec3d pivot(pivot_h.x, cal.pivot_height, pivot_h.y);
  // The upper axis in the camera frame (x right, y up, z depth), as in ProjectUpperMarker.
  const Frame3 h = Horizontal(cyl);
  const double tf = cal.theta0 + yaw;
  const cv::Point2d side = -std::sin(tf) * h.towards + std::cos(tf) * h.across;
  const cv::Vec3d u(-std::sin(bend) * side.x, std::cos(bend), -std::sin(bend) * side.y);
  double sum = 0;
  int n = 0;
  for (double along : {0.45, 0.75, 1.05, 1.35}) {
    const cv::Vec3d a = pivot + along * cal.e * u;
    const cv::Vec3d across = cv::normalize(u.cross(a));  // perpendicular to the axis and the ray
    const cv::Point2d axis_px = Project(cyl, a[0], a[1], a[2]);
    for (double sign : {-1.0, 1.0}) {
      const cv::Vec3d edge = a + sign * across;
      const cv::Point2d q = Project(cyl, edge[0], edge[1], edge[2]);
      const cv::Point2d m = (q - axis_px) * (1.0 / std::max(1e-9, cv::norm(q - axis_px)));
      double best = 0;
      bool inside_image = false;
      for (double d = -1.5; d <= 1.5; d += 0.5) {
        const cv::Point2d c = q + d * m;
        const double in = 0.5 * (Sample(gray, c - 2.5 * m) + Sample(gray, c - 1.5 * m));
        const double out = 0.5 * (Sample(gray, c + 1.5 * m) + Sample(gray, c + 2.5 * m));
        if (std::isnan(in) || std::isnan(out)) continue;
        inside_image = true;
        best = std::max(best, std::abs(in - out));
      }
      if (!inside_image) continue;
      sum += best;
      ++n;
    }
  }
  return n > 0 ? sum / n : 0;
}

cv::Vec3d UpperMarkerPoint(const CylinderView& cyl, const UpperCalibration& cal, double yaw,
                           double bend) {
  const Frame3 h = Horizontal(cyl);
  const double tf = cal.theta0 + yaw;
  const cv::Point2d front = std::cos(tf) * h.towards + cal.k * std::sin(tf) * h.across;
  const cv::Point2d side = -std::sin(tf) * h.towards + std::cos(tf) * h.across;
  const cv::Point2d m = h.axis - cal.e * std::sin(bend) * side + front;
  return {m.x, cal.pivot_height + cal.e * std::cos(bend), m.y};
}

cv::Point2d ProjectUpperMarker(const CylinderView& cyl, const UpperCalibration& cal, double yaw,
                               double bend) {
  const cv::Vec3d m = UpperMarkerPoint(cyl, cal, yaw, bend);
  return Project(cyl, m[0], m[1], m[2]);
}

cv::Point2d ProjectPivot(const CylinderView& cyl, const UpperCalibration& cal) {
  const Frame3 h = Horizontal(cyl);
  return Project(cyl, h.axis.x, cal.pivot_height, h.axis.y);
}

double SolveBend(const CylinderView& cyl, const UpperCalibration& cal, double yaw,
                 cv::Point2d centroid_px, double* residual_px) {
  auto miss = [&](double b) {
    const cv::Point2d d = ProjectUpperMarker(cyl, cal, yaw, b) - centroid_px;
    return d;
  };
  double best = 0, best_d = 1e18;
  for (double deg = -kMaxBendDeg; deg <= kMaxBendDeg; deg += 2) {
    const cv::Point2d d = miss(RadFromDeg(deg));
    if (d.dot(d) < best_d) best_d = d.dot(d), best = RadFromDeg(deg);
  }
  // Gauss-Newton on the image distance.
  for (int it = 0; it < 8; ++it) {
    constexpr double kStep = 1e-4;
    const cv::Point2d d = miss(best);
    const cv::Point2d j = (miss(best + kStep) - miss(best - kStep)) * (0.5 / kStep);
    const double jj = j.dot(j);
    if (jj < 1e-12) break;
    const double step = -j.dot(d) / jj;
    best += std::clamp(step, -0.2, 0.2);
    if (std::abs(step) < 1e-7) break;
  }
  const cv::Point2d d = miss(best);
  if (residual_px) *residual_px = std::sqrt(d.dot(d));
  return best;
}

}  // namespace armmimic::internal
