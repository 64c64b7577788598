#include "lk/arm_bar.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "armmimic/core/angles.h"

namespace armmimic::lk {
namespace {

// Grey levels: how far a pixel may be from the bar colour. Wide enough for the shading of a
// sleeve that turned away from the light since its colour was learned, and for its cuff.
constexpr double kColourSigma = 45;
constexpr int kAlongSamples = 10;
constexpr double kAlongFrom = 0.2, kAlongTo = 0.8;
constexpr int kCentreIterations = 2;
constexpr std::size_t kMinCentreSamples = 5;
constexpr double kMaxCentreTurnDeg = 10;
constexpr double kRunStepPx = 0.5;  // across the sleeve when centring it and measuring its width

bool Sample(const cv::Mat& bgr, const cv::Point2d& p, cv::Vec3f* out) {
  const int x = cvRound(p.x), y = cvRound(p.y);
  if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) return false;
  const cv::Vec3b& v = bgr.at<cv::Vec3b>(y, x);
  *out = cv::Vec3f(v[0], v[1], v[2]);
  return true;
}

double Likeness(const cv::Vec3f& a, const cv::Vec3f& b) {
  const cv::Vec3f d = a - b;
  return std::exp(-d.dot(d) / (2 * 3 * kColourSigma * kColourSigma / 3));
}

// Likeness at p, or `outside` when p is outside the picture.
double LikenessAt(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& p, double outside) {
  cv::Vec3f c;
  return Sample(bgr, p, &c) ? Likeness(c, bar.colour) : outside;
}

// Where along the strip the k-th of its kAlongSamples sample points lies, as a fraction of its
// length.
double AlongFraction(int k) {
  return kAlongFrom + (kAlongTo - kAlongFrom) * k / (kAlongSamples - 1);
}

// Where the run of the bar's colour through `p` ends on each side along `n`, stepping `step_px`
// (half a step before the first unlike sample); `max_px` when it does not end within it. Pixels
// outside the picture count as `outside`.
void RunEnds(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& p, const cv::Point2d& n,
             double max_px, double step_px, double outside, double ends[2]) {
  for (int s = 0; s < 2; ++s) {
    ends[s] = max_px;
    for (double d = step_px; d <= max_px; d += step_px) {
      if (LikenessAt(bgr, bar, p + (s == 0 ? d : -d) * n, outside) < 0.5) {
        ends[s] = d - 0.5 * step_px;
        break;
      }
    }
  }
}

}  // namespace

ArmBar LearnArmBar(const cv::Mat& bgr, const cv::Point2d& joint_px, double deg, double length_px,
                   double max_half_width_px) {
  ArmBar bar;
  const cv::Point2d u = DirectionVector(deg), n(-u.y, u.x);
  std::vector<float> ch[3];
  std::vector<cv::Point2d> axis;
  for (int k = 0; k < kAlongSamples; ++k) {
    const cv::Point2d p = joint_px + AlongFraction(k) * length_px * u;
    cv::Vec3f c;
    if (!Sample(bgr, p, &c)) continue;
    axis.push_back(p);
    for (int i = 0; i < 3; ++i) ch[i].push_back(c[i]);
  }
  if (axis.size() < 3) return bar;
  for (int i = 0; i < 3; ++i) {
    std::nth_element(ch[i].begin(), ch[i].begin() + ch[i].size() / 2, ch[i].end());
    bar.colour[i] = ch[i][ch[i].size() / 2];
  }
  // Half-width: on each side, the first offset where the colour is no longer the bar's; the
  // narrower side counts (the other may run into the body).
  std::vector<double> widths;
  for (const cv::Point2d& p : axis) {
    double side_w[2];
    RunEnds(bgr, bar, p, n, max_half_width_px, 1, 0, side_w);
    widths.push_back(std::min(side_w[0], side_w[1]));
  }
  std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
  bar.half_width_px = std::max(1.5, widths[widths.size() / 2]);
  bar.valid = true;
  return bar;
}

double ArmBarScore(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px, double deg,
                   double length_px) {
  const cv::Point2d u = DirectionVector(deg), n(-u.y, u.x);
  const double hw = bar.half_width_px;
  const double axis_offsets[3] = {-0.4 * hw, 0, 0.4 * hw};
  const double flank = hw + std::max(2.0, 0.6 * hw);
  double on = 0, off = 0;
  int count = 0;
  for (int k = 0; k < kAlongSamples; ++k) {
    const cv::Point2d p = joint_px + AlongFraction(k) * length_px * u;
    double a = 0;
    for (double o : axis_offsets) a += LikenessAt(bgr, bar, p + o * n, 0);
    const double left = LikenessAt(bgr, bar, p + flank * n, 1);
    const double right = LikenessAt(bgr, bar, p - flank * n, 1);
    on += a / 3;
    // A flank like the bar (the body in the same cloth) says nothing against this direction
    // as long as the other flank is unlike it.
    off += std::min(left, right);
    ++count;
  }
  return (on - off) / count;
}

BarSearch SearchArmBar(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px,
                       double predicted_deg, double length_px, double range_deg, double min_score,
                       double avoid_deg, double avoid_half_deg) {
  BarSearch out;
  if (!bar.valid || !(length_px > 2)) return out;
  const int steps = static_cast<int>(std::ceil(range_deg));
  std::vector<double> scores(2 * steps + 1);
  int best = -1;
  for (int i = 0; i <= 2 * steps; ++i) {
    const double deg = predicted_deg + (i - steps);
    if (avoid_half_deg > 0 && std::abs(AngleDiff(deg, avoid_deg)) < avoid_half_deg) {
      scores[i] = -2;  // lowest possible score
      continue;
    }
    scores[i] = ArmBarScore(bgr, bar, joint_px, deg, length_px);
    if (best < 0 || scores[i] > scores[best]) best = i;
  }
  if (best < 0 || scores[best] < min_score) return out;
  double offset = best - steps;
  if (best > 0 && best < 2 * steps) {
    const double a = scores[best - 1], b = scores[best], c = scores[best + 1];
    const double den = a - 2 * b + c;
    if (den < 0) offset += std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
  }
  out.found = true;
  out.deg = Wrap180(predicted_deg + offset);
  out.score = scores[best];
  return out;
}

double MeasureBarLength(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px,
                        double deg, double max_px, double* beyond) {
  const cv::Point2d u = DirectionVector(deg);
  int misses = 0;
  double last = 0;
  for (double d = 1; d <= max_px; d += 1) {
    if (LikenessAt(bgr, bar, joint_px + d * u, 0) >= 0.5) {
      last = d;
      misses = 0;
    } else if (++misses > 2) {
      break;
    }
  }
  if (beyond) {
    // Past the gap that ended the run, up to max_px: the share of pixels like the bar again.
    int like = 0, count = 0;
    for (double d = last + 4; d <= max_px; d += 1, ++count) {
      like += LikenessAt(bgr, bar, joint_px + d * u, 0) >= 0.5;
    }
    *beyond = count ? static_cast<double>(like) / count : 0;
  }
  return last;
}

BarAxis CentreArmBar(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px, double deg,
                     double length_px, double max_half_width_px, bool one_sided) {
  BarAxis out;
  if (!bar.valid || !(length_px > 2)) return out;
  double current = deg;
  cv::Point2d point;
  for (int iteration = 0; iteration < kCentreIterations; ++iteration) {
    const cv::Point2d u = DirectionVector(current), n(-u.y, u.x);
    std::vector<double> ds, cs;
    for (int k = 0; k < kAlongSamples; ++k) {
      const double d = AlongFraction(k) * length_px;
      const cv::Point2d p = joint_px + d * u;
      if (LikenessAt(bgr, bar, p, 0) < 0.5) continue;
      double ends[2];
      RunEnds(bgr, bar, p, n, max_half_width_px, kRunStepPx, 1, ends);
      const bool clear[2] = {ends[0] < max_half_width_px, ends[1] < max_half_width_px};
      double c;  // centre of the sleeve along +n from the axis
      if (clear[0] && clear[1]) {
        c = 0.5 * (ends[0] - ends[1]);
      } else if (one_sided && bar.width_measured && (clear[0] || clear[1])) {
        c = clear[0] ? ends[0] - bar.half_width_px : bar.half_width_px - ends[1];
      } else {
        continue;
      }
      ds.push_back(d);
      cs.push_back(c);
    }
    if (ds.size() < kMinCentreSamples) return out;
    // Least-squares line c = a + b d through the centres; its slope turns the direction.
    double md = 0, mc = 0;
    for (std::size_t i = 0; i < ds.size(); ++i) {
      md += ds[i];
      mc += cs[i];
    }
    md /= ds.size();
    mc /= ds.size();
    double sdd = 0, sdc = 0;
    for (std::size_t i = 0; i < ds.size(); ++i) {
      sdd += (ds[i] - md) * (ds[i] - md);
      sdc += (ds[i] - md) * (cs[i] - mc);
    }
    if (sdd <= 0) return out;
    point = joint_px + md * u + mc * n;  // the centres' mean lies on the axis
    // An offset along +n turns the direction clockwise on screen.
    current = Wrap180(current - DegFromRad(std::atan(sdc / sdd)));
  }
  if (std::abs(AngleDiff(current, deg)) > kMaxCentreTurnDeg) return out;
  out.found = true;
  out.deg = current;
  out.point_px = point;
  return out;
}

double BarShareAround(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& centre_px,
                      double radius_px) {
  int like = 0, count = 0;
  const int r = static_cast<int>(std::ceil(radius_px));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy > radius_px * radius_px) continue;
      ++count;
      like += LikenessAt(bgr, bar, centre_px + cv::Point2d(dx, dy), 0) >= 0.5;
    }
  }
  return count ? static_cast<double>(like) / count : 0;
}

double MeasureBarHalfWidth(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px,
                           double deg, double length_px, double max_half_width_px) {
  if (!bar.valid || !(length_px > 2)) return -1;
  const cv::Point2d u = DirectionVector(deg), n(-u.y, u.x);
  std::vector<double> widths;
  for (int k = 0; k < kAlongSamples; ++k) {
    const cv::Point2d p = joint_px + AlongFraction(k) * length_px * u;
    if (LikenessAt(bgr, bar, p, 0) < 0.5) continue;  // the axis is off the sleeve here
    double ends[2];
    RunEnds(bgr, bar, p, n, max_half_width_px, kRunStepPx, 1, ends);
    if (ends[0] < max_half_width_px && ends[1] < max_half_width_px) {
      widths.push_back(0.5 * (ends[0] + ends[1]));
    }
  }
  if (widths.size() * 2 < static_cast<std::size_t>(kAlongSamples)) return -1;
  std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
  return widths[widths.size() / 2];
}

}  // namespace armmimic::lk
