// The arm's geometry from its mask (thesis 5.2.5-5.2.7): contour, hull and defects, the 30 %
// rule, the split at the elbow and the two parts' moments.
// Length: AnalyzeArm follows the thesis' steps in order, each step using the contour and defects of
// the last.
#include "bgsub/arm.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"

namespace armmimic::bgsub {
namespace {

constexpr int kMinPartPixels = 12;

double Dot(const cv::Point2d& a, const cv::Point2d& b) { return a.x * b.x + a.y * b.y; }

cv::Point2d Centre(const RegionMoments& m) { return {m.cx, m.cy}; }

// The outline of the largest region of `mask` inside `box`, in mask coordinates.
std::vector<cv::Point> LargestContour(const cv::Mat& mask, const cv::Rect& box) {
  std::vector<std::vector<cv::Point>> contours;
  cv::Mat sub = mask(box).clone();
  cv::findContours(sub, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE, box.tl());
  std::size_t best = 0;
  double best_area = -1;
  for (std::size_t i = 0; i < contours.size(); ++i) {
    const double area = std::fabs(cv::contourArea(contours[i])) + contours[i].size();
    if (area > best_area) {
      best_area = area;
      best = i;
    }
  }
  if (contours.empty()) return {};
  return std::move(contours[best]);
}

// Farthest projection of the points of `contour` (a region's outline) from `origin` along
// `direction_deg`: how far the region reaches from `origin` in that direction.
double ReachAlong(const std::vector<cv::Point>& contour, const cv::Point2d& origin,
                  double direction_deg) {
  const cv::Point2d v = DirectionVector(direction_deg);
  double reach = 0;
  for (const cv::Point& p : contour)
    reach = std::max(reach, (p.x - origin.x) * v.x + (p.y - origin.y) * v.y);
  return reach;
}

// Straight arm: one axis for both segments; the elbow is put half-way along the reach so the
// overlay and the centres of the two halves are meaningful.
void FinishStraight(const cv::Mat& mask, const cv::Rect& box, const cv::Point2d& shoulder,
                    ArmGeometry* g) {
  const cv::Point2d towards = Centre(g->whole);
  const double dir = ResolveDirection(g->axis_deg, shoulder, towards);
  g->upper_deg = dir;
  g->fore_deg = dir;
  g->reach_px = ReachAlong(g->contour, shoulder, dir);
  const cv::Point2d v = DirectionVector(dir);
  g->wrist_px = shoulder + v * g->reach_px;
  g->elbow_px = shoulder + v * (g->reach_px / 2);
  MomentAccumulator upper, fore;
  const double half = g->reach_px / 2;
  for (int y = box.y; y < box.y + box.height; ++y) {
    const uchar* m = mask.ptr<uchar>(y);
    for (int x = box.x; x < box.x + box.width; ++x) {
      if (!m[x]) continue;
      const double s = (x - shoulder.x) * v.x + (y - shoulder.y) * v.y;
      (s < half ? upper : fore).Add(x, y);
    }
  }
  const cv::Point2d c = Centre(g->whole);
  g->upper_com_px = upper.count() > 0 ? Centre(upper.Moments()) : c;
  g->fore_com_px = fore.count() > 0 ? Centre(fore.Moments()) : c;
}

// Splits the arm pixels in two by `upper_side(x, y)`, returns false when a part is too small.
template <typename Pred>
bool Split(const cv::Mat& mask, const cv::Rect& box, Pred upper_side, MomentAccumulator* a,
           MomentAccumulator* b) {
  *a = MomentAccumulator();
  *b = MomentAccumulator();
  for (int y = box.y; y < box.y + box.height; ++y) {
    const uchar* m = mask.ptr<uchar>(y);
    for (int x = box.x; x < box.x + box.width; ++x) {
      if (!m[x]) continue;
      (upper_side(x, y) ? a : b)->Add(x, y);
    }
  }
  return a->count() >= kMinPartPixels && b->count() >= kMinPartPixels;
}

cv::Point2d FarthestFrom(const cv::Mat& mask, const cv::Rect& box, const cv::Point2d& from,
                         const std::vector<cv::Point>& contour, const cv::Point2d& fore_com) {
  // The wrist: the outline point farthest from the elbow on the forearm's side.
  cv::Point2d best_p = fore_com;
  double best = -1;
  const cv::Point2d side = fore_com - from;
  for (const cv::Point& p : contour) {
    const cv::Point2d d(p.x - from.x, p.y - from.y);
    if (Dot(d, side) <= 0) continue;
    const double dist = d.x * d.x + d.y * d.y;
    if (dist > best) {
      best = dist;
      best_p = p;
    }
  }
  return best_p;
}

}  // namespace

RegionMoments MomentAccumulator::Moments() const {
  RegionMoments m;
  m.m00 = n_;
  m.m10 = sx_;
  m.m01 = sy_;
  if (n_ <= 0) return m;
  m.cx = sx_ / n_;
  m.cy = sy_ / n_;
  m.mu20 = sxx_ - sx_ * m.cx;
  m.mu02 = syy_ - sy_ * m.cy;
  m.mu11 = sxy_ - sx_ * m.cy;
  return m;
}

ArmGeometry AnalyzeArm(const cv::Mat& mask, const cv::Rect& box, const cv::Point2d& shoulder_px,
                       const BgsubOptions& options) {
  ArmGeometry g;
  // Contour and hull (thesis 5.2.5, Sklansky's scan of section 3.6).
  g.contour = LargestContour(mask, box);
  if (g.contour.size() < 5) {
    g.note = "arm region too small for a contour";
    return g;
  }
  g.whole = ComputeMoments(mask, box);
  if (g.whole.m00 < kMinPartPixels) {
    g.note = "arm region too small";
    return g;
  }
  g.axes = ComputeSemiAxes(g.whole);
  g.axis_deg = OrientationDeg(g.whole);
  const std::vector<int> hull_idx = ConvexHullIndices(g.contour);
  g.hull.reserve(hull_idx.size());
  for (int i : hull_idx) g.hull.push_back(g.contour[static_cast<std::size_t>(i)]);
  const std::vector<ConvexityDefect> defects = ConvexityDefects(g.contour, hull_idx);
  g.defect_depth_px = defects.empty() ? 0 : defects.front().depth_px;
  g.found = true;

  // The 30 % rule (5.2.6): a defect shallower than 30 % of the semi-major axis is a straight arm.
  const double ratio = options.straight_ratio;
  g.bent = !defects.empty() && g.defect_depth_px > ratio * g.axes.major;
  if (!g.bent) {
    g.note = "straight arm";
    FinishStraight(mask, box, shoulder_px, &g);
    return g;
  }

  // Bent: split perpendicular to the major axis through the elbow (the deepest defect point).
  const ConvexityDefect& d = defects.front();
  const cv::Point2d crease = g.contour[static_cast<std::size_t>(d.deepest_index)];
  const cv::Point2d u = DirectionVector(g.axis_deg);
  MomentAccumulator a, b;
  if (!Split(
          mask, box, [&](int x, int y) { return (x - crease.x) * u.x + (y - crease.y) * u.y < 0; },
          &a, &b)) {
    g.bent = false;
    g.note = "elbow split left an empty part: straight arm";
    FinishStraight(mask, box, shoulder_px, &g);
    return g;
  }
  // The part nearer the shoulder is the upper arm.
  auto dist = [&](const MomentAccumulator& acc) {
    const RegionMoments m = acc.Moments();
    return std::hypot(m.cx - shoulder_px.x, m.cy - shoulder_px.y);
  };
  const RegionMoments upper = dist(a) <= dist(b) ? a.Moments() : b.Moments();
  const RegionMoments fore = dist(a) <= dist(b) ? b.Moments() : a.Moments();
  const cv::Point2d elbow = crease;
  g.note = "bent arm (thesis split)";
  g.elbow_px = elbow;
  g.upper_com_px = Centre(upper);
  g.fore_com_px = Centre(fore);
  g.upper_deg = ResolveDirection(OrientationDeg(upper), shoulder_px, elbow);
  g.fore_deg = ResolveDirection(OrientationDeg(fore), elbow, g.fore_com_px);
  g.wrist_px = FarthestFrom(mask, box, elbow, g.contour, g.fore_com_px);
  g.reach_px = ReachAlong(g.contour, shoulder_px, g.upper_deg);
  return g;
}

}  // namespace armmimic::bgsub
