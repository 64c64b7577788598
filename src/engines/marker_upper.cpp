// The upper marker and the bend (docs/marker.md, "Bend"). The pivot lies on the lower part's axis
// at the height the reference gave; the upper part's axis leaves it at bend beta in the plane
// that turns with the yaw, and the upper marker sits e along that axis and one radius in front
// of it, on the side that faced the camera at zero yaw (plus the yaw). Its coverage-weighted
// centroid lies k times closer to the axis sideways than the disc's centre (DiscCentroidFactor).
#include "marker_upper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "armmimic/core/angles.h"
#include "marker_detect.h"

namespace armmimic::internal {
namespace {

// Bends beyond this would fold the upper part down past the pivot's height onto the lower one.
constexpr double kMaxBendDeg = 120;

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

// Mean of the 3x3 pixels around p, and the level of the ring at `radius` around it (its third
// brightest of twelve samples: the surface, even where the ring crosses a limb).
bool Darkness(const cv::Mat& gray, cv::Point p, int radius, double* score) {
  if (p.x < radius + 1 || p.y < radius + 1 || p.x >= gray.cols - radius - 1 ||
      p.y >= gray.rows - radius - 1) {
    return false;
  }
  double centre = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    const uchar* row = gray.ptr<uchar>(p.y + dy);
    centre += row[p.x - 1] + row[p.x] + row[p.x + 1];
  }
  static const std::array<cv::Point2d, 12> kRing = [] {
    std::array<cv::Point2d, 12> r;
    for (int i = 0; i < 12; ++i) r[i] = {std::cos(i * kPi / 6), std::sin(i * kPi / 6)};
    return r;
  }();
  std::array<double, 12> ring;
  for (int i = 0; i < 12; ++i) {
    ring[i] = gray.at<uchar>(p.y + static_cast<int>(std::lround(radius * kRing[i].y)),
                             p.x + static_cast<int>(std::lround(radius * kRing[i].x)));
  }
  std::nth_element(ring.begin(), ring.begin() + 2, ring.end(), std::greater<double>());
  if (ring[2] < 20) return false;
  *score = centre / 9 / ring[2];
  return true;
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

namespace {

// The upper marker's centroid in the camera frame (x right, y up, z depth).
cv::Vec3d UpperMarkerPoint(const CylinderView& cyl, const UpperCalibration& cal, double yaw,
                           double bend) {
  const Frame3 h = Horizontal(cyl);
  const double tf = cal.theta0 + yaw;
  const cv::Point2d front = std::cos(tf) * h.towards + cal.k * std::sin(tf) * h.across;
  const cv::Point2d side = -std::sin(tf) * h.towards + std::cos(tf) * h.across;
  const cv::Point2d m = h.axis - cal.e * std::sin(bend) * side + front;
  return {m.x, cal.pivot_height + cal.e * std::cos(bend), m.y};
}

}  // namespace

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

UpperMeasurement MeasureUpperMarker(const cv::Mat& gray, const CylinderView& cyl,
                                    const UpperCalibration& cal, double yaw, double tolerance) {
  UpperMeasurement out;
  const cv::Point2d pivot = ProjectPivot(cyl, cal);
  const double e_px = cv::norm(ProjectUpperMarker(cyl, cal, yaw, 0) - pivot);
  const int h = std::max(3, cal.marker_height_px);
  const int ring = std::max(3, static_cast<int>(std::lround(0.85 * h)));
  // A marker's centre is nearly as dark as the paper against the surface round it; shading
  // (a limb, the shadowed side) is only a little darker than its surroundings.
  const double threshold = cal.marker_ratio + 0.3 * (1 - cal.marker_ratio);
  const double turn = cal.theta0 + yaw;
  // Darkness along the model's curve (every bend), a pixel either side.
  struct Spot {
    double bend, score;
    cv::Point p;
  };
  std::vector<Spot> curve;
  const double step = 0.8 / std::max(8.0, e_px);
  for (double b = RadFromDeg(-kMaxBendDeg); b <= RadFromDeg(kMaxBendDeg); b += step) {
    const cv::Point2d q = ProjectUpperMarker(cyl, cal, yaw, b);
    Spot s{b, 1e9, {}};
    for (int dx : {0, -2, 2}) {
      const cv::Point p(static_cast<int>(std::lround(q.x)) + dx,
                        static_cast<int>(std::lround(q.y)));
      double score = 0;
      if (Darkness(gray, p, ring, &score) && score < s.score) s.score = score, s.p = p;
    }
    curve.push_back(s);
  }
  // Dark spots: runs of the curve below the threshold, each at the middle of its darkest part (a
  // marker's inside is evenly dark along the curve), at least a marker apart.
  std::vector<Spot> spots;
  for (std::size_t i = 0; i < curve.size();) {
    if (curve[i].score >= threshold) {
      ++i;
      continue;
    }
    std::size_t j = i, darkest = i;
    for (; j < curve.size() && curve[j].score < threshold; ++j) {
      if (curve[j].score < curve[darkest].score) darkest = j;
    }
    std::size_t first = j, last = i;
    for (std::size_t k = i; k < j; ++k) {
      if (curve[k].score <= curve[darkest].score + 0.03) first = std::min(first, k), last = k;
    }
    Spot spot = curve[(first + last) / 2];
    spot.score = curve[darkest].score;
    if (!spots.empty() && cv::norm(spots.back().p - spot.p) < h) {
      if (spot.score < spots.back().score) spots.back() = spot;
    } else {
      spots.push_back(spot);
    }
    i = j;
  }
  std::sort(spots.begin(), spots.end(),
            [](const Spot& a, const Spot& b) { return a.score < b.score; });
  if (spots.size() > 6) spots.resize(6);  // clutter along the curve can be darker than paper
  struct Candidate {
    double score, support, bend, residual;
    cv::Point2d centre;
  };
  std::vector<Candidate> found;
  for (const Spot& s : spots) {
    out.spots.emplace_back(s.p.x - h / 2, s.p.y - h / 2, h, h);
    MarkerBlob blob;
    blob.box = cv::Rect(s.p.x - h / 2, s.p.y - h / 2, h, h);
    blob.centre = s.p;
    if (!RefineMarker(gray, gray, cal.marker_ratio, h, &blob)) continue;
    // The stretch from the pivot to the marker lies on the upper part: smooth shading, about as
    // bright as in the reference.
    const SurfaceStretch st = SampleStretch(gray, pivot, blob.centre);
    const double level = cal.stretch_level > 0 ? st.level / cal.stretch_level : 1;
    if (st.uneven > 0.3 || level < 0.5 || level > 2) continue;
    Candidate c{s.score, 0, 0, 0, blob.centre};
    c.bend = SolveBend(cyl, cal, yaw, blob.centre, &c.residual);
    if (c.residual > tolerance * e_px + 1.5) continue;
    // A disc turned by the yaw shows cos(yaw) of its face, larger as it comes nearer the camera:
    // a shadow or a blot does not.
    const double nearer =
        UpperMarkerPoint(cyl, cal, 0, 0)[2] / UpperMarkerPoint(cyl, cal, yaw, c.bend)[2];
    const double area =
        blob.coverage_px / (cal.face_area_px * std::max(0.2, std::cos(turn)) * nearer * nearer);
    if (cal.face_area_px > 0 && (area < 0.55 || area > 1.4)) continue;
    c.support = UpperSilhouetteSupport(gray, cyl, cal, yaw, c.bend);
    // A dark spot where the upper part shows no silhouette at all is not on it.
    if (c.support < 0.35 * cal.support) continue;
    found.push_back(c);
  }
  if (found.empty()) {
    out.note = "no dark spot where the model puts the upper marker";
    return out;
  }
  // Dark spots beside the upper part (clutter) put its silhouette where the image shows none:
  // the spot whose bend the silhouette bears out clearly best wins; otherwise the darkest, if
  // clearly the darkest.
  std::sort(found.begin(), found.end(),
            [](const Candidate& a, const Candidate& b) { return a.support > b.support; });
  const Candidate* pick = &found[0];
  if (found.size() > 1 && !(found[0].support >= 4 && found[0].support >= 1.5 * found[1].support)) {
    std::sort(found.begin(), found.end(),
              [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
    pick = &found[0];
    out.ambiguous = found[1].score < found[0].score + 0.1;
  }
  out.found = true;
  out.bend = pick->bend;
  out.support = pick->support;
  out.residual_px = pick->residual;
  out.centre_px = pick->centre;
  // The centroid again with the surface's shading taken along the upper part's axis.
  cv::Point2d refined = pick->centre;
  if (UpperCentroid(gray, cyl, cal, yaw, pick->bend, &refined)) {
    double residual = 0;
    const double bend = SolveBend(cyl, cal, yaw, refined, &residual);
    if (residual <= tolerance * e_px + 1.5) {
      out.bend = bend;
      out.residual_px = residual;
      out.centre_px = refined;
    }
  }
  if (out.ambiguous) out.note = "two dark spots fit the upper marker";
  return out;
}

}  // namespace armmimic::internal
