// Length: ArmFitter::FitLengths is one search (the upper arm's peaks, each one's forearm, the
// refinement, the chosen pose's counts) over one score table.
#include "bgsub/fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <opencv2/imgproc.hpp>

namespace armmimic::bgsub {
namespace {

// Bits of a pixel's code: differs from the empty room, differs from the standstill, the standing
// body of the standstill, the standstill's hanging arm.
constexpr int kPerson = 1, kMoved = 2, kBody = 4, kRest = 8;
constexpr int kArmNow = 2;  // the weight of the person where the standstill was not

// The weight of each code.
cv::Mat WeightTable() {
  cv::Mat lut(1, 256, CV_8SC1, cv::Scalar(0));
  for (int c = 0; c < 16; ++c) {
    const bool person = c & kPerson, moved = c & kMoved, body = c & kBody, rest = c & kRest;
    int w;
    if (person && moved) {
      w = kArmNow;  // the person where the standstill was not: the arm now
    } else if (person) {
      w = rest || !body ? 1 : 0;  // the hanging arm unchanged; the unchanged body says nothing
    } else {
      w = moved ? -2 : -1;  // the empty room: uncovered now, or as in the standstill
    }
    lut.at<schar>(0, c) = static_cast<schar>(w);
  }
  return lut;
}

// Peaks of a circular score (one per degree): local maxima over +-`half` degrees, best first.
std::vector<int> Peaks(const std::vector<int>& score, int half, std::size_t count) {
  std::vector<int> peaks;
  const int n = static_cast<int>(score.size());
  for (int k = 0; k < n; ++k) {
    bool top = true;
    for (int d = -half; d <= half && top; ++d) {
      const int j = ((k + d) % n + n) % n;
      top = score[static_cast<std::size_t>(j)] < score[static_cast<std::size_t>(k)] ||
            (score[static_cast<std::size_t>(j)] == score[static_cast<std::size_t>(k)] && j >= k);
    }
    if (top) peaks.push_back(k);
  }
  std::sort(peaks.begin(), peaks.end(), [&](int a, int b) {
    return score[static_cast<std::size_t>(a)] > score[static_cast<std::size_t>(b)];
  });
  if (peaks.size() > count) peaks.resize(count);
  return peaks;
}

// Sample lines across a segment, as shares of the calibrated half-width (the forearm is a little
// thinner than the upper arm, so the outer lines stay inside it).
constexpr double kAcrossInner = 0.35, kAcrossOuter = 0.7;
// The flanks: from this share of the half-width outside the segment, along its middle part (the
// ends touch the body at the shoulder and the other segment at the elbow).
constexpr double kFlankGap = 0.5, kFlankFrom = 0.25, kFlankTo = 0.8;

int Wrap360(int deg) { return ((deg % 360) + 360) % 360; }

// The yaws whose foreshortened lengths the directions are fitted with, and the largest yaw the
// lengths are refined to (degrees). Past about 75 degrees a segment is a blob: no direction.
constexpr double kCoarseYawDeg[] = {0, 25, 40, 55};
constexpr int kMaxYawDeg = 75;
// The upper arm's lengths tried besides the calibrated one, as shares of it (the forearm takes the
// rest of the reach): a tenth shorter and a tenth longer than the calibration's share of the
// reach, about the spread of adults' arm proportions around the anthropometric mean.
constexpr double kElbowSplits[] = {0.9, 1.1};
// Another split wins only by more than this share of the arm's best score (every sample the arm
// now): where the forearm hides (in the room's colour), a shorter one always gains by leaving
// room pixels out, which says nothing of where the elbow is.
constexpr double kSplitMargin = 0.015;
// Another split moves the elbow along the upper arm the other lengths found: its upper arm is
// looked for within this many degrees of theirs (the forearm in its whole range).
constexpr int kSplitNearDeg = 6;

// How many lines along a segment MakeRay samples: five across an arm at least 2 px in half-width,
// the axis alone across a thinner one.
int LinesAcross(double half_width) { return half_width >= 2 ? 5 : 1; }

// The upper arm's direction with the highest score within `half` degrees of `deg`.
int BestNear(const std::vector<int>& score, int deg, int half) {
  int best = Wrap360(deg);
  for (int d = -half; d <= half; ++d) {
    const int k = Wrap360(deg + d);
    if (score[static_cast<std::size_t>(k)] > score[static_cast<std::size_t>(best)]) best = k;
  }
  return best;
}

}  // namespace

void ArmEvidence::Begin(const ArmCalibration& cal, const cv::Size& region, double rest_deg) {
  const double r = cal.half_width_px;
  const int reach = static_cast<int>(std::ceil(1.3 * cal.reach_px + 2 * r + 2));
  const cv::Point s(cvRound(cal.shoulder_px.x), cvRound(cal.shoulder_px.y));
  window_tl_ = s - cv::Point(reach, reach);
  origin_ = cv::Point(reach, reach);
  weights_ = cv::Mat::zeros(2 * reach + 1, 2 * reach + 1, CV_8SC1);
  rect_ = cv::Rect(window_tl_, weights_.size()) & cv::Rect(cv::Point(), region);
  static_code_ = cv::Mat::zeros(rect_.size(), CV_8UC1);
  if (rect_.area() == 0) return;
  if (!cal.body.empty()) {
    cv::bitwise_and(cal.body(rect_), cv::Scalar(kBody), static_code_);
  }
  cv::Mat rest = cv::Mat::zeros(rect_.size(), CV_8UC1);
  const cv::Point2d from = cal.shoulder_px - cv::Point2d(rect_.tl());
  const cv::Point2d to = from + DirectionVector(rest_deg) * cal.reach_px;
  cv::line(rest, from, to, cv::Scalar(kRest), 2 * static_cast<int>(std::lround(r)) + 1);
  static_code_ |= rest;
}

void ArmEvidence::Update(const cv::Mat& person, const cv::Mat& moved) {
  static const cv::Mat kTable = WeightTable();
  if (rect_.area() == 0) return;
  cv::bitwise_and(person, cv::Scalar(kPerson), code_);
  cv::bitwise_and(moved, cv::Scalar(kMoved), bits_);
  code_ |= bits_;
  code_ |= static_code_;
  cv::Mat out = weights_(rect_ - window_tl_);
  cv::LUT(code_, kTable, out);
}

ArmFitter::Ray ArmFitter::MakeRay(int stride, int deg, double t0, double t1, double half_width) {
  Ray ray;
  // Lines along the segment across most of its width: a ray off the arm's axis loses its outer
  // samples, so a straight arm is fitted along its axis and not bent within its own thickness.
  const int n_across = LinesAcross(half_width);
  const double across[5] = {-kAcrossOuter * half_width, -kAcrossInner * half_width, 0,
                            kAcrossInner * half_width, kAcrossOuter * half_width};
  const double* first = n_across == 5 ? across : across + 2;
  const cv::Point2d d = DirectionVector(deg), n(-d.y, d.x);
  if (t1 >= t0) ray.offsets.reserve(static_cast<std::size_t>(n_across * (t1 - t0 + 2)));
  for (double t = t0; t <= t1; t += 1.0) {
    for (int k = 0; k < n_across; ++k) {
      const cv::Point2d p = d * t + n * first[k];
      ray.offsets.push_back(cvRound(p.y) * stride + cvRound(p.x));
    }
  }
  return ray;
}

std::vector<ArmFitter::Ray> ArmFitter::MakeRays(int stride, double t0, double t1,
                                                double half_width) {
  std::vector<Ray> rays(360);
  for (int k = 0; k < 360; ++k) {
    rays[static_cast<std::size_t>(k)] = MakeRay(stride, k, t0, t1, half_width);
  }
  return rays;
}

std::vector<ArmFitter::Ray> ArmFitter::MakeFlanks(int stride, double len, double half_width,
                                                  int side) {
  std::vector<Ray> rays(360);
  const double gap = std::max(2.0, kFlankGap * half_width);
  const double across[] = {side * (half_width + gap), side * (2 * half_width + gap)};
  for (int k = 0; k < 360; ++k) {
    const cv::Point2d d = DirectionVector(k), n(-d.y, d.x);
    for (double t = kFlankFrom * len; t <= kFlankTo * len; t += 1.0) {
      for (double a : across) {
        const cv::Point2d p = d * t + n * a;
        rays[static_cast<std::size_t>(k)].offsets.push_back(cvRound(p.y) * stride + cvRound(p.x));
      }
    }
  }
  return rays;
}

double ArmFitter::Clutter(const cv::Mat& weights, int from, int deg,
                          const std::vector<Ray> (&flanks)[2]) const {
  // Only new arm evidence (the person where the standstill was not) counts: beside an arm at
  // rest lies the standstill's own arm or body, unchanged.
  double clearer = 1;
  const schar* w = weights.ptr<schar>() + from;
  for (const std::vector<Ray>& side : flanks) {
    const std::vector<int>& offsets = side[static_cast<std::size_t>(Wrap360(deg))].offsets;
    int now = 0;
    for (int off : offsets) now += w[off] >= kArmNow;
    clearer = std::min(clearer, offsets.empty() ? 0.0 : static_cast<double>(now) / offsets.size());
  }
  return clearer;
}

ArmFitter::Lengths ArmFitter::MakeLengths(double scale, double split) const {
  Lengths l;
  l.scale = scale;
  l.split = split;
  const SplitLengths lengths(upper_len_, fore_len_, split);
  l.upper = scale * lengths.upper;
  l.fore = scale * lengths.fore;
  const double hw = half_width_;
  // The upper arm from one arm radius out (its first part is the shoulder, under the standstill's
  // arm), the forearm from half a radius past the elbow to the fingertip.
  l.upper_rays = MakeRays(stride_, std::min(hw, 0.5 * l.upper), l.upper, hw);
  l.fore_rays = MakeRays(stride_, std::min(0.5 * hw, 0.5 * l.fore), l.fore, hw);
  for (int i = 0; i < 2; ++i) {
    l.upper_flank[i] = MakeFlanks(stride_, l.upper, hw, i == 0 ? 1 : -1);
    l.fore_flank[i] = MakeFlanks(stride_, l.fore, hw, i == 0 ? 1 : -1);
  }
  return l;
}

void ArmFitter::Begin(int stride, double upper_len, double fore_len, double half_width,
                      int max_bend_deg) {
  stride_ = stride;
  max_bend_deg_ = max_bend_deg;
  upper_len_ = upper_len;
  fore_len_ = fore_len;
  half_width_ = half_width;
  lengths_.clear();
  for (double yaw : kCoarseYawDeg) lengths_.push_back(MakeLengths(std::cos(RadFromDeg(yaw))));
  for (double split : kElbowSplits) lengths_.push_back(MakeLengths(1, split));
  split_margin_ = static_cast<int>(
      std::lround(kSplitMargin * LinesAcross(half_width) * (upper_len + fore_len) * kArmNow));
  longest_upper_ = 0;
  for (std::size_t i = 1; i < lengths_.size(); ++i) {
    if (lengths_[i].upper > lengths_[longest_upper_].upper) longest_upper_ = i;
  }
  for (Lengths& l : lengths_) {
    l.upper_prefix = true;
    for (int k = 0; k < 360 && l.upper_prefix; ++k) {
      const std::vector<int>& mine = l.upper_rays[static_cast<std::size_t>(k)].offsets;
      const std::vector<int>& first =
          lengths_[longest_upper_].upper_rays[static_cast<std::size_t>(k)].offsets;
      l.upper_prefix =
          mine.size() <= first.size() && std::equal(mine.begin(), mine.end(), first.begin());
    }
  }
}

void ArmFitter::ScoreUppers(const cv::Mat& weights, int from) const {
  upper_scores_.resize(lengths_.size());
  for (std::vector<int>& up : upper_scores_) up.assign(360, 0);
  const schar* w = weights.ptr<schar>() + from;
  std::vector<int> partial;  // partial[n]: the sum of the longest ray's first n samples
  for (int k = 0; k < 360; ++k) {
    const std::vector<int>& first =
        lengths_[longest_upper_].upper_rays[static_cast<std::size_t>(k)].offsets;
    partial.resize(first.size() + 1);
    partial[0] = 0;
    for (std::size_t n = 0; n < first.size(); ++n) partial[n + 1] = partial[n] + w[first[n]];
    for (std::size_t i = 0; i < lengths_.size(); ++i) {
      const Lengths& l = lengths_[i];
      upper_scores_[i][static_cast<std::size_t>(k)] =
          l.upper_prefix ? partial[l.upper_rays[static_cast<std::size_t>(k)].offsets.size()]
                         : Score(weights, from, k, l.upper_rays);
    }
  }
}

int ArmFitter::Score(const cv::Mat& weights, int from, int deg,
                     const std::vector<Ray>& rays) const {
  const schar* w = weights.ptr<schar>() + from;
  const std::vector<int>& offsets = rays[static_cast<std::size_t>(Wrap360(deg))].offsets;
  // Four running sums (integers: the order does not matter), so the loads overlap.
  const int* off = offsets.data();
  const std::size_t n = offsets.size();
  int s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    s0 += w[off[i]];
    s1 += w[off[i + 1]];
    s2 += w[off[i + 2]];
    s3 += w[off[i + 3]];
  }
  for (; i < n; ++i) s0 += w[off[i]];
  return (s0 + s1) + (s2 + s3);
}

void ArmFitter::Count(const cv::Mat& weights, int from, int deg, const std::vector<Ray>& rays,
                      int* pos, int* neg, int* n) const {
  const schar* w = weights.ptr<schar>() + from;
  for (int off : rays[static_cast<std::size_t>(Wrap360(deg))].offsets) {
    *pos += w[off] > 0;
    *neg += w[off] < 0;
    ++*n;
  }
}

const cv::Mat& ArmFitter::WithoutUpper(const cv::Mat& weights, const cv::Point& origin, int deg,
                                       double len) const {
  // The buffer holds `weights` (copied once per Fit) but for the last cleared line, whose
  // surroundings are copied back: a whole copy per call was a tenth of the engine's time. The
  // same line again (a length that rounds to the same elbow) leaves it as it is.
  const cv::Point elbow = cv::Point2d(origin) + DirectionVector(deg) * len;
  if (cleared_.area() > 0 && origin == cleared_from_ && elbow == cleared_to_) {
    return without_upper_;
  }
  if (cleared_.area() > 0) weights(cleared_).copyTo(without_upper_(cleared_));
  cleared_from_ = origin;
  cleared_to_ = elbow;
  const int thickness = 2 * static_cast<int>(half_width_) + 1;
  cv::line(without_upper_, origin, elbow, cv::Scalar(0), thickness);
  const int margin = thickness + 2;  // more than the line's half-width and its round caps
  const cv::Point lo(std::min(origin.x, elbow.x) - margin, std::min(origin.y, elbow.y) - margin);
  const cv::Point hi(std::max(origin.x, elbow.x) + margin + 1,
                     std::max(origin.y, elbow.y) + margin + 1);
  cleared_ = cv::Rect(lo, hi) & cv::Rect(cv::Point(), weights.size());
  return without_upper_;
}

ArmFit ArmFitter::Fit(const cv::Mat& weights, const cv::Point& origin) const {
  ArmFit best;
  if (lengths_.empty() || weights.empty()) return best;
  weights.copyTo(without_upper_);
  cleared_ = cv::Rect();
  // The lengths that fit best: beyond the arm's end lie the room's pixels, which count against
  // it, and a shorter arm leaves the end's pixels out. Of equal scores the longer arm.
  int best_score = std::numeric_limits<int>::min();
  ScoreUppers(weights, origin.y * stride_ + origin.x);
  for (std::size_t i = 0; i < lengths_.size(); ++i) {
    int score = 0;
    const bool split = lengths_[i].split != 1;
    if (split && !best.found) break;
    const ArmFit fit =
        FitLengths(weights, origin, lengths_[i], upper_scores_[i], &score,
                   split ? std::optional<int>(std::lround(best.upper_deg)) : std::nullopt);
    if (split) score -= split_margin_;
    if (fit.found && score > best_score) {
      best = fit;
      best_score = score;
    }
  }
  if (best.found) RefineScale(weights, origin, &best);
  return best;
}

void ArmFitter::RefineScale(const cv::Mat& weights, const cv::Point& origin, ArmFit* fit) const {
  const int from = origin.y * stride_ + origin.x;
  const int u = Wrap360(static_cast<int>(std::lround(fit->upper_deg)));
  const int f = Wrap360(static_cast<int>(std::lround(fit->fore_deg)));
  const double hw = half_width_;
  int best_score = std::numeric_limits<int>::min();
  double best_scale = fit->scale;
  // The fit's split of the reach.
  const SplitLengths lengths(upper_len_, fore_len_, fit->split);
  const double upper_len = lengths.upper, fore_len = lengths.fore;
  // A yaw's ray that starts where the full length's starts (the segment long enough against its
  // width) is that ray's first samples: counted off it, not made again; the upper arm's sums are
  // taken once.
  const double upper_t0 = std::min(hw, 0.5 * upper_len),
               fore_t0 = std::min(0.5 * hw, 0.5 * fore_len);
  const Ray upper_full = MakeRay(stride_, u, upper_t0, upper_len, hw);
  const Ray fore_full = MakeRay(stride_, f, fore_t0, fore_len, hw);
  const int lines = LinesAcross(hw);
  auto samples = [lines](double t0, double t1) {
    int n = 0;
    for (double t = t0; t <= t1; t += 1.0) ++n;  // MakeRay's steps
    return static_cast<std::size_t>(lines * n);
  };
  const schar* w = weights.ptr<schar>();
  std::vector<int> upper_sums(upper_full.offsets.size() + 1, 0);
  for (std::size_t i = 0; i < upper_full.offsets.size(); ++i) {
    upper_sums[i + 1] = upper_sums[i] + w[from + upper_full.offsets[i]];
  }
  for (int yaw = 0; yaw <= kMaxYawDeg; ++yaw) {
    const double scale = std::cos(RadFromDeg(yaw));
    const double ul = scale * upper_len, fl = scale * fore_len;
    const double ut0 = std::min(hw, 0.5 * ul), ft0 = std::min(0.5 * hw, 0.5 * fl);
    const cv::Point2d e = DirectionVector(u) * ul;
    const int elbow = from + cvRound(e.y) * stride_ + cvRound(e.x);
    const schar* wr = WithoutUpper(weights, origin, u, ul).ptr<schar>();
    int score = 0;
    if (ut0 == upper_t0) {
      score += upper_sums[samples(ut0, ul)];
    } else {
      for (int off : MakeRay(stride_, u, ut0, ul, hw).offsets) score += w[from + off];
    }
    if (ft0 == fore_t0) {
      const std::size_t n = samples(ft0, fl);
      for (std::size_t i = 0; i < n; ++i) score += wr[elbow + fore_full.offsets[i]];
    } else {
      for (int off : MakeRay(stride_, f, ft0, fl, hw).offsets) score += wr[elbow + off];
    }
    if (score > best_score) {
      best_score = score;
      best_scale = scale;
    }
  }
  fit->scale = best_scale;
  fit->elbow_px = cv::Point2d(origin) + DirectionVector(u) * (best_scale * upper_len);
  fit->wrist_px = fit->elbow_px + DirectionVector(f) * (best_scale * fore_len);
}

ArmFit ArmFitter::FitLengths(const cv::Mat& weights, const cv::Point& origin, const Lengths& l,
                             const std::vector<int>& up, int* score,
                             std::optional<int> near_deg) const {
  ArmFit fit;
  const int from = origin.y * stride_ + origin.x;
  struct Pose {
    int up, fore, score;
  };
  std::vector<Pose> poses;  // the best forearm of each upper-arm peak
  // Of equal scores the straighter arm: a straight arm's segments can tilt within its width.
  auto better = [](int score, int u, int f, const Pose& than) {
    return score > than.score ||
           (score == than.score &&
            std::abs(AngleDiff(f, u)) < std::abs(AngleDiff(than.fore, than.up)));
  };
  auto elbow_at = [&](int deg) {
    const cv::Point2d e = DirectionVector(deg) * l.upper;
    return from + cvRound(e.y) * stride_ + cvRound(e.x);
  };
  // Each peak's best forearm (u - max_bend .. u + max_bend by 2).
  const int bend = max_bend_deg_;
  const std::vector<int> peaks =
      near_deg ? std::vector<int>{BestNear(up, *near_deg, kSplitNearDeg)} : Peaks(up, 4, 4);
  for (int u : peaks) {
    const int e = elbow_at(u);
    const cv::Mat& rest = WithoutUpper(weights, origin, u, l.upper);
    Pose best{u, u, std::numeric_limits<int>::min() / 2};
    for (int f = u - bend; f <= u + bend; f += 2) {
      const int s = Score(rest, e, f, l.fore_rays);
      if (better(s, u, f, best)) best = {u, Wrap360(f), s};
    }
    best.score += up[static_cast<std::size_t>(u)];
    poses.push_back(best);
  }
  if (poses.empty()) return fit;
  std::sort(poses.begin(), poses.end(),
            [](const Pose& a, const Pose& b) { return a.score > b.score; });
  // Refine the best to a degree: the upper arm +-1, the forearm +-2 from each elbow.
  Pose best = poses.front();
  const Pose coarse = best;
  for (int du = -1; du <= 1; ++du) {
    const int u = Wrap360(coarse.up + du), e = elbow_at(u);
    const cv::Mat& rest = WithoutUpper(weights, origin, u, l.upper);
    for (int df = -2; df <= 2; ++df) {
      const int f = Wrap360(coarse.fore + df);
      if (std::abs(AngleDiff(f, u)) > bend) continue;
      const int s = up[static_cast<std::size_t>(u)] + Score(rest, e, f, l.fore_rays);
      if (better(s, u, f, best)) best = {u, f, s};
    }
  }
  const int e = elbow_at(best.up);
  int upos = 0, uneg = 0, un = 0, fpos = 0, fneg = 0, fn = 0;
  Count(weights, from, best.up, l.upper_rays, &upos, &uneg, &un);
  Count(weights, e, best.fore, l.fore_rays, &fpos, &fneg, &fn);
  fit.clutter = std::max(Clutter(weights, from, best.up, l.upper_flank),
                         Clutter(weights, e, best.fore, l.fore_flank));
  fit.found = true;
  fit.upper_deg = Wrap180(best.up);
  fit.fore_deg = Wrap180(best.fore);
  fit.scale = l.scale;
  fit.split = l.split;
  fit.elbow_px = cv::Point2d(origin) + DirectionVector(best.up) * l.upper;
  fit.wrist_px = fit.elbow_px + DirectionVector(best.fore) * l.fore;
  fit.upper_support = un > 0 ? static_cast<double>(upos) / un : 0;
  fit.fore_support = fn > 0 ? static_cast<double>(fpos) / fn : 0;
  fit.against = un + fn > 0 ? static_cast<double>(uneg + fneg) / (un + fn) : 1;
  *score = best.score;
  return fit;
}

}  // namespace armmimic::bgsub
