// Looking for the upper marker (docs/marker.md, "Bend"): dark spots along the path the model
// allows it for the yaw found (every bend), each weighed as a marker on the upper part; the best
// one's centroid gives the bend.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "armmimic/core/angles.h"
#include "marker/detect.h"
#include "marker/upper.h"

namespace armmimic::internal {
namespace {

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

struct Spot {
  double bend, score;
  cv::Point p;
};

struct Candidate {
  double score, support, bend, residual;
  cv::Point2d centre;
};

// Darkness along the model's curve (every bend, a pixel either side): runs below the threshold,
// each at the middle of its darkest part (a marker's inside is evenly dark along the curve), at
// least a marker apart, darkest first, at most six (clutter can be darker than paper).
std::vector<Spot> DarkSpots(const cv::Mat& gray, const CylinderView& cyl,
                            const UpperCalibration& cal, double yaw, double e_px, int h) {
  const int ring = std::max(3, static_cast<int>(std::lround(0.85 * h)));
  // A marker's centre is nearly as dark as the paper against the surface round it; shading
  // (a limb, the shadowed side) is only a little darker than its surroundings.
  const double threshold = cal.marker_ratio + 0.3 * (1 - cal.marker_ratio);
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
  if (spots.size() > 6) spots.resize(6);
  return spots;
}

// Is the spot the upper marker on the upper part? Its centroid, bend and evidence.
bool WeighSpot(const cv::Mat& gray, const CylinderView& cyl, const UpperCalibration& cal,
               double yaw, const Spot& s, int h, double max_residual, Candidate* c) {
  MarkerBlob blob;
  blob.box = cv::Rect(s.p.x - h / 2, s.p.y - h / 2, h, h);
  blob.centre = s.p;
  if (!RefineMarker(gray, gray, cal.marker_ratio, h, &blob)) return false;
  // The stretch from the pivot to the marker lies on the upper part: smooth shading, at most
  // twice as bright as in the reference, and at least half as bright or as dark as the lower
  // part's darkest shading there (turned away from the light, the upper part is shaded as a
  // limb is: a spot refused at 0.38-0.49 of the reference's level had been the marker).
  const SurfaceStretch st = SampleStretch(gray, ProjectPivot(cyl, cal), blob.centre);
  const double level = cal.stretch_level > 0 ? st.level / cal.stretch_level : 1;
  if (st.uneven > 0.3 || level < std::min(0.5, cal.darkest_level) || level > 2) return false;
  *c = Candidate{s.score, 0, 0, 0, blob.centre};
  c->bend = SolveBend(cyl, cal, yaw, blob.centre, &c->residual);
  if (c->residual > max_residual) return false;
  // A disc turned by the yaw shows cos(yaw) of its face, larger as it comes nearer the camera:
  // a shadow or a blot does not.
  const double nearer =
      UpperMarkerPoint(cyl, cal, 0, 0)[2] / UpperMarkerPoint(cyl, cal, yaw, c->bend)[2];
  const double turn = std::max(0.2, std::cos(cal.theta0 + yaw));
  const double area = blob.coverage_px / (cal.face_area_px * turn * nearer * nearer);
  if (cal.face_area_px > 0 && (area < 0.55 || area > 1.4)) return false;
  // A dark spot where the upper part shows no silhouette at all is not on it.
  c->support = UpperSilhouetteSupport(gray, cyl, cal, yaw, c->bend);
  return c->support >= 0.35 * cal.support;
}

}  // namespace

double UpperMarkerDarkness(const cv::Mat& gray, cv::Point2d centre, int marker_height_px) {
  const int h = std::max(3, marker_height_px);
  const int ring = std::max(3, static_cast<int>(std::lround(0.85 * h)));
  double score = 0;
  const cv::Point p(static_cast<int>(std::lround(centre.x)),
                    static_cast<int>(std::lround(centre.y)));
  return Darkness(gray, p, ring, &score) ? score : 0;
}

double UpperSpotQuality(const UpperCalibration& cal, double support, double darkness) {
  const double plain = cal.support > 0 ? std::min(support / cal.support, 1.2) : 1;
  return plain - 2 * std::abs(darkness - cal.darkness);
}

UpperMeasurement MeasureUpperMarker(const cv::Mat& gray, const CylinderView& cyl,
                                    const UpperCalibration& cal, double yaw, double tolerance) {
  UpperMeasurement out;
  const cv::Point2d pivot = ProjectPivot(cyl, cal);
  const double e_px = cv::norm(ProjectUpperMarker(cyl, cal, yaw, 0) - pivot);
  const int h = std::max(3, cal.marker_height_px);
  const double max_residual = tolerance * e_px + 1.5;
  std::vector<Candidate> found;
  for (const Spot& s : DarkSpots(gray, cyl, cal, yaw, e_px, h)) {
    out.spots.emplace_back(s.p.x - h / 2, s.p.y - h / 2, h, h);
    Candidate c;
    if (WeighSpot(gray, cyl, cal, yaw, s, h, max_residual, &c)) found.push_back(c);
  }
  if (found.empty()) {
    out.note = "no dark spot where the model puts the upper marker";
    return out;
  }
  // Dark spots beside the upper part (clutter) put its silhouette where the image shows none,
  // and are seldom as dark as the marker's paper: the spot whose silhouette is as plain as the
  // reference's and whose darkness is the reference marker's wins, clearly or not at all.
  auto quality = [&](const Candidate& c) { return UpperSpotQuality(cal, c.support, c.score); };
  std::sort(found.begin(), found.end(),
            [&](const Candidate& a, const Candidate& b) { return quality(a) > quality(b); });
  const Candidate* pick = &found[0];
  out.ambiguous = found.size() > 1 && quality(found[1]) > quality(found[0]) - kClearQuality;
  out.found = true;
  out.quality = quality(*pick);
  out.bend = pick->bend;
  out.support = pick->support;
  out.residual_px = pick->residual;
  out.centre_px = pick->centre;
  // The centroid again with the surface's shading taken along the upper part's axis.
  cv::Point2d refined = pick->centre;
  if (UpperCentroid(gray, cyl, cal, yaw, pick->bend, &refined)) {
    double residual = 0;
    const double bend = SolveBend(cyl, cal, yaw, refined, &residual);
    if (residual <= max_residual) {
      out.bend = bend;
      out.residual_px = residual;
      out.centre_px = refined;
    }
  }
  if (out.ambiguous) out.note = "two dark spots fit the upper marker";
  return out;
}

}  // namespace armmimic::internal
