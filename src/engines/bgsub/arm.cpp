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

// Squared distance from p to the segment ab (compared, never needed as a length).
double SquaredDistanceToSegment(const cv::Point2d& p, const cv::Point2d& a, const cv::Point2d& b) {
  const cv::Point2d ab = b - a;
  const double len2 = Dot(ab, ab);
  double t = len2 > 0 ? Dot(p - a, ab) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const cv::Point2d q = a + ab * t;
  return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
}

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

// Straight arm: one axis for both segments; the elbow is put half-way along the reach so the
// overlay and the centres of the two halves are meaningful.
void FinishStraight(const cv::Mat& mask, const cv::Rect& box, const cv::Point2d& shoulder,
                    const BgsubOptions& options, ArmGeometry* g) {
  cv::Point2d towards = Centre(g->whole);
  if (!options.thesis_mode) {
    // The hand end: the outline point farthest from the shoulder (the centre of mass can sit on
    // the wrong side of a misplaced shoulder).
    double best = -1;
    for (const cv::Point& p : g->contour) {
      const double d =
          (p.x - shoulder.x) * (p.x - shoulder.x) + (p.y - shoulder.y) * (p.y - shoulder.y);
      if (d > best) {
        best = d;
        towards = p;
      }
    }
  }
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

double ReachAlong(const std::vector<cv::Point>& contour, const cv::Point2d& origin,
                  double direction_deg) {
  const cv::Point2d v = DirectionVector(direction_deg);
  double reach = 0;
  for (const cv::Point& p : contour)
    reach = std::max(reach, (p.x - origin.x) * v.x + (p.y - origin.y) * v.y);
  return reach;
}

double RayFit(const cv::Mat& mask, const cv::Point2d& origin, double d0, double d1,
              double exclude_deg, double exclude_half_deg) {
  constexpr int kRays = 360;
  // The 1-degree ray directions, computed once (sin/cos were a tenth of the ray fit's time).
  static const std::vector<cv::Point2d> kDirections = [] {
    std::vector<cv::Point2d> v(kRays);
    for (int k = 0; k < kRays; ++k) v[static_cast<std::size_t>(k)] = DirectionVector(k - 179.0);
    return v;
  }();
  const int samples = std::max(2, static_cast<int>(d1 - d0));
  int score[kRays];
  int best = 0;
  for (int k = 0; k < kRays; ++k) {
    score[k] = 0;
    const double deg = k - 179.0;
    if (std::isfinite(exclude_deg) && std::fabs(AngleDiff(deg, exclude_deg)) < exclude_half_deg) {
      continue;
    }
    const cv::Point2d v = kDirections[static_cast<std::size_t>(k)];
    int covered = 0;
    for (int i = 0; i < samples; ++i) {
      const double t = d0 + (d1 - d0) * i / (samples - 1);
      const int x = cvRound(origin.x + v.x * t), y = cvRound(origin.y + v.y * t);
      if (static_cast<unsigned>(x) < static_cast<unsigned>(mask.cols) &&
          static_cast<unsigned>(y) < static_cast<unsigned>(mask.rows) &&
          mask.data[static_cast<std::size_t>(y) * mask.step[0] + static_cast<std::size_t>(x)]) {
        ++covered;
      }
    }
    score[k] = covered;
    best = std::max(best, score[k]);
  }
  if (best * 2 < samples) return kNaN;
  // The middle of the widest run of rays within 90 % of the best: the arm's axis, not its edge.
  const int level = static_cast<int>(std::ceil(0.9 * best));
  int run_start = -1, best_start = 0, best_len = 0;
  for (int k = 0; k < 2 * kRays; ++k) {
    const bool on = score[k % kRays] >= level;
    if (on && run_start < 0) run_start = k;
    if ((!on || k == 2 * kRays - 1) && run_start >= 0) {
      const int len = std::min(k - run_start, kRays);
      if (len > best_len) best_len = len, best_start = run_start;
      run_start = -1;
    }
  }
  return Wrap180(best_start + (best_len - 1) / 2.0 - 179.0);
}

// Improved bent/straight decision and segments by ray fit: the upper arm is the ray from the
// shoulder best covered by the arm between 35 and 95 % of the upper arm's length; the elbow is at
// that length; the forearm is the best ray from the elbow, not searched back along the upper arm.
// A forearm folded onto the upper arm, which the hull cannot separate, stays apart, and a slight
// bend the 30 % rule calls straight is seen. Returns false when no upper-arm ray is covered.
static bool RayFitArm(const cv::Mat& mask, const cv::Rect& box, const cv::Point2d& shoulder_px,
                      const BgsubOptions& options, bool was_bent, bool rule_bent,
                      double upper_len_px, double fore_len_px, ArmGeometry* g,
                      double fixed_up = kNaN) {
  const double up = std::isfinite(fixed_up) ? fixed_up
                                            : RayFit(mask, shoulder_px, 0.35 * upper_len_px,
                                                     0.95 * upper_len_px, kNaN, 0);
  if (!std::isfinite(up)) return false;
  const cv::Point2d e = shoulder_px + DirectionVector(up) * upper_len_px;
  const double fo = RayFit(mask, e, 0.25 * fore_len_px, 0.8 * fore_len_px, up + 180, 25);
  // A bend the 30 % rule missed must be clear: near the rest pose the visible part of a straight
  // arm is a sliver whose ray is off the arm's axis.
  const bool near_rest = std::fabs(AngleDiff(up, options.rest_deg)) < 25;
  const double min_bend = rule_bent || !near_rest ? (was_bent ? 8.0 : 12.0) : 22.0;
  if (!std::isfinite(fo) || std::fabs(AngleDiff(fo, up)) < min_bend) {
    g->bent = false;
    g->note = "straight arm (ray fit)";
    FinishStraight(mask, box, shoulder_px, options, g);
    return true;
  }
  const cv::Point2d w = e + DirectionVector(fo) * fore_len_px;
  MomentAccumulator ua, fa;
  Split(
      mask, box,
      [&](int x, int y) {
        const cv::Point2d p(x, y);
        return SquaredDistanceToSegment(p, shoulder_px, e) <= SquaredDistanceToSegment(p, e, w);
      },
      &ua, &fa);
  g->bent = true;
  g->elbow_px = e;
  g->wrist_px = w;
  g->upper_com_px = ua.count() > 0 ? Centre(ua.Moments()) : (shoulder_px + e) * 0.5;
  g->fore_com_px = fa.count() > 0 ? Centre(fa.Moments()) : (e + w) * 0.5;
  g->upper_deg = up;
  g->fore_deg = fo;
  g->reach_px = ReachAlong(g->contour, shoulder_px, up);
  g->note = "bent arm (ray fit)";
  return true;
}

void RefitWithUpper(const cv::Mat& mask, const cv::Rect& box, const cv::Point2d& shoulder_px,
                    const BgsubOptions& options, bool was_bent, double upper_deg,
                    double upper_len_px, double fore_len_px, ArmGeometry* g) {
  const bool rule_bent =
      g->defect_depth_px >
      (options.straight_ratio + (was_bent ? -1 : 1) * options.bend_hysteresis) * g->axes.major;
  RayFitArm(mask, box, shoulder_px, options, was_bent, rule_bent, upper_len_px, fore_len_px, g,
            upper_deg);
  if (!g->bent) {
    // Straight: one direction for both, the person-mask one near the shoulder.
    g->upper_deg = upper_deg;
    g->fore_deg = upper_deg;
    const cv::Point2d v = DirectionVector(upper_deg);
    g->reach_px = ReachAlong(g->contour, shoulder_px, upper_deg);
    g->wrist_px = shoulder_px + v * g->reach_px;
    g->elbow_px = shoulder_px + v * (g->reach_px / 2);
  }
}

ArmGeometry AnalyzeArm(const cv::Mat& mask, const cv::Rect& box, const cv::Point2d& shoulder_px,
                       const BgsubOptions& options, bool was_bent, double upper_len_px,
                       double fore_len_px) {
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
  double ratio = options.straight_ratio;
  if (!options.thesis_mode) ratio += was_bent ? -options.bend_hysteresis : options.bend_hysteresis;
  g.bent = !defects.empty() && g.defect_depth_px > ratio * g.axes.major;
  if (!options.thesis_mode && upper_len_px > 0 && fore_len_px > 0 &&
      RayFitArm(mask, box, shoulder_px, options, was_bent, g.bent, upper_len_px, fore_len_px, &g)) {
    return g;
  }
  if (!g.bent) {
    g.note = "straight arm";
    FinishStraight(mask, box, shoulder_px, options, &g);
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
    FinishStraight(mask, box, shoulder_px, options, &g);
    return g;
  }
  // The part nearer the shoulder is the upper arm.
  auto dist = [&](const MomentAccumulator& acc) {
    const RegionMoments m = acc.Moments();
    return std::hypot(m.cx - shoulder_px.x, m.cy - shoulder_px.y);
  };
  RegionMoments upper = dist(a) <= dist(b) ? a.Moments() : b.Moments();
  RegionMoments fore = dist(a) <= dist(b) ? b.Moments() : a.Moments();
  cv::Point2d elbow = crease;
  g.note = "bent arm (thesis split)";

  if (!options.thesis_mode) {
    // The crease is on the inside of the elbow; the joint is half an arm's width further in,
    // away from the hull edge the defect hangs from.
    const cv::Point2d e0 = g.contour[static_cast<std::size_t>(d.start_index)];
    const cv::Point2d e1 = g.contour[static_cast<std::size_t>(d.end_index)];
    cv::Point2d edge = e1 - e0;
    const double edge_len = std::hypot(edge.x, edge.y);
    cv::Point2d wrist = FarthestFrom(mask, box, crease, g.contour, Centre(fore));
    if (edge_len > 0) {
      cv::Point2d n(-edge.y / edge_len, edge.x / edge_len);  // a normal of the hull edge
      if (Dot(n, crease - e0) > 0) n = -n;                   // pointing from the crease outwards
      const double length = std::hypot(crease.x - shoulder_px.x, crease.y - shoulder_px.y) +
                            std::hypot(wrist.x - crease.x, wrist.y - crease.y);
      const double half_width = length > 0 ? std::min(g.whole.m00 / (2 * length), d.depth_px) : 0;
      elbow = crease - n * half_width;
    }
    // Two-line refinement: every pixel goes to the nearer of the segments shoulder-elbow and
    // elbow-wrist. This keeps a sharply folded forearm apart from the upper arm, where the
    // straight cut across the major axis slices through both.
    for (int iter = 0; iter < 2; ++iter) {
      MomentAccumulator ua, fa;
      const cv::Point2d s = shoulder_px, e = elbow, w = wrist;
      if (!Split(
              mask, box,
              [&](int x, int y) {
                const cv::Point2d p(x, y);
                return SquaredDistanceToSegment(p, s, e) <= SquaredDistanceToSegment(p, e, w);
              },
              &ua, &fa)) {
        break;
      }
      upper = ua.Moments();
      fore = fa.Moments();
      wrist = FarthestFrom(mask, box, elbow, g.contour, Centre(fore));
      g.note = "bent arm (two-line split)";
    }
    g.wrist_px = wrist;
  }

  g.elbow_px = elbow;
  g.upper_com_px = Centre(upper);
  g.fore_com_px = Centre(fore);
  g.upper_deg = ResolveDirection(OrientationDeg(upper), shoulder_px, elbow);
  g.fore_deg = ResolveDirection(OrientationDeg(fore), elbow, g.fore_com_px);
  if (options.thesis_mode) {
    g.wrist_px = FarthestFrom(mask, box, elbow, g.contour, g.fore_com_px);
  }
  g.reach_px = ReachAlong(g.contour, shoulder_px, g.upper_deg);
  return g;
}

}  // namespace armmimic::bgsub
