#include "common/arm_model_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "armmimic/core/angles.h"
#include "common/pair_sampler.h"

namespace armmimic::arm {
namespace {

using pairs::Add;
using pairs::Pair;
using pairs::PairOf;
using pairs::PairSampler;
using pairs::Scale;
using pairs::X;
using pairs::Y;

// The strips: the upper arm from just past the shoulder (where it merges with the body) to the
// elbow; the forearm from just past the elbow through the hand.
constexpr double kUpperFrom = 0.15, kUpperTo = 0.95;
constexpr double kForeFrom = 0.1;
constexpr double kHandShare = 0.8;  // of the hand's length: its tip narrows

// The wide search's grid (degrees) and the distance between its poses that counts as another
// pose.
constexpr double kWideUpperStep = 4, kWideBendStep = 5;
constexpr double kDistinctDeg = 12;
constexpr double kRefineDeg = 4;

double ForeTo(const ArmShape& shape) {
  return shape.fore_px > 0 ? 1 + kHandShare * shape.hand_px / shape.fore_px : 1;
}

// The squared distance of p from the segment a-b.
inline double SquaredDistanceToSegment(const cv::Point2d& p, const cv::Point2d& a,
                                       const cv::Point2d& b) {
  const cv::Point2d ab = b - a;
  const double len2 = ab.dot(ab);
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  const cv::Point2d d = p - (a + t * ab);
  return d.dot(d);
}

// Offset of the peak of a parabola through (-1, a), (0, b), (1, c), within half a step.
double ParabolaPeak(double a, double b, double c) {
  const double den = a - 2 * b + c;
  return den < 0 ? std::clamp(0.5 * (a - c) / den, -0.5, 0.5) : 0.0;
}

}  // namespace

double DistanceToSegment(const cv::Point2d& p, const cv::Point2d& a, const cv::Point2d& b) {
  return std::sqrt(SquaredDistanceToSegment(p, a, b));
}

ArmJoints JointsOf(const ArmPose& pose, const ArmShape& shape) {
  ArmJoints j;
  j.shoulder = pose.shoulder;
  j.elbow = pose.shoulder + shape.upper_px * DirectionVector(pose.upper_deg);
  j.wrist = j.elbow + shape.fore_px * DirectionVector(pose.fore_deg);
  return j;
}

namespace {

// A strip's steps along it, as distances from its start (pixels): the same in every direction,
// so a search over directions takes them once.
struct Steps {
  int along = 0;  // 0: an empty strip
  bool coarse = false;
  double t[16] = {};
};

Steps StepsOf(double length_px, double t0, double t1, bool coarse) {
  Steps s;
  s.coarse = coarse;
  const double span = (t1 - t0) * length_px;
  if (!(span > 0)) return s;
  s.along = coarse ? 6 : std::clamp(static_cast<int>(span / 2.5), 6, 16);
  for (int k = 0; k < s.along; ++k) s.t[k] = (t0 + (t1 - t0) * (k + 0.5) / s.along) * length_px;
  return s;
}

// Evidence samples lie in [0, 1] (probabilities times shares, blended): a bound a little above,
// and a margin far above the rounding of the sums, for a score that can no longer be reached.
constexpr double kMostSample = 1.001, kReachMargin = 1e-6;

// ScoreSegment with its steps and its direction's unit vector `u` given, into *out. With
// kMayGiveUp, it gives up (false, *out unset) once the score can no longer reach `at_least`:
// every fourth step, the samples still to take counted at their most inside the strip and at
// their least on the flanks.
template <bool kMayGiveUp>
bool ScoreStripUnless(const PairSampler& map, const Steps& steps, const cv::Point2d& from_px,
                      const cv::Point2d& u, double hw_px, const cv::Point2d& avoid_a,
                      const cv::Point2d& avoid_b, double avoid_hw_px, double at_least,
                      SegmentScore* out) {
  *out = SegmentScore();
  if (steps.along == 0) return true;
  const cv::Point2d n(-u.y, u.x);
  static constexpr double kFine[4] = {-0.6, -0.2, 0.2, 0.6};
  static constexpr double kCoarse[2] = {-0.4, 0.4};
  const double* across = steps.coarse ? kCoarse : kFine;
  const int n_across = steps.coarse ? 2 : 4;
  const double flank = hw_px + std::max(2.0, 0.75 * hw_px);
  // The offsets across the strip and to its flanks, the same at every step along it.
  Pair inner[4];
  for (int a = 0; a < n_across; ++a) inner[a] = PairOf(across[a] * hw_px * n);
  const Pair outer[2] = {PairOf(-1 * flank * n), PairOf(1 * flank * n)};
  const Pair from = PairOf(from_px), along = PairOf(u);
  // A flank sample farther than the avoided half-width beyond the avoided segment's bounding box
  // on either axis is surely not within it (the margin is far above rounding): the exact
  // distance is then not needed.
  const bool avoid = avoid_hw_px > 0;
  const double reach = avoid_hw_px + 1e-3;
  const double box_x0 = std::min(avoid_a.x, avoid_b.x) - reach;
  const double box_x1 = std::max(avoid_a.x, avoid_b.x) + reach;
  const double box_y0 = std::min(avoid_a.y, avoid_b.y) - reach;
  const double box_y1 = std::max(avoid_a.y, avoid_b.y) + reach;
  const double avoid2 = avoid_hw_px * avoid_hw_px;
  double inside = 0, flanks = 0;
  int n_flank = 0;
  for (int k = 0; k < steps.along; ++k) {
    const Pair p = Add(from, Scale(steps.t[k], along));
    for (int a = 0; a < n_across; ++a) inside += map.At(Add(p, inner[a]));
    for (const Pair& side : outer) {
      const Pair q = Add(p, side);
      const double qx = X(q), qy = Y(q);
      if (avoid && qx > box_x0 && qx < box_x1 && qy > box_y0 && qy < box_y1 &&
          SquaredDistanceToSegment({qx, qy}, avoid_a, avoid_b) < avoid2) {
        continue;
      }
      flanks += map.At(q);
      ++n_flank;
    }
    if constexpr (kMayGiveUp) {
      const int left = steps.along - 1 - k;
      if ((k & 3) == 3 && left > 0) {
        const double most_inside =
            (inside + left * n_across * kMostSample) / (steps.along * n_across);
        const int most_flank = n_flank + 2 * left;
        const double least_flank = flanks / most_flank;
        if (most_inside - least_flank < at_least - kReachMargin) return false;
      }
    }
  }
  out->inside = inside / (steps.along * n_across);
  out->score = out->inside - (n_flank > 0 ? flanks / n_flank : 0.0);
  return true;
}

SegmentScore ScoreStrip(const PairSampler& map, const Steps& steps, const cv::Point2d& from_px,
                        const cv::Point2d& u, double hw_px, const cv::Point2d& avoid_a = {},
                        const cv::Point2d& avoid_b = {}, double avoid_hw_px = 0) {
  SegmentScore out;
  ScoreStripUnless<false>(map, steps, from_px, u, hw_px, avoid_a, avoid_b, avoid_hw_px, 0, &out);
  return out;
}

// DirectionVector of the whole degrees -kTableDeg..kTableDeg, computed once: the wide search's
// directions are all whole degrees.
constexpr int kTableDeg = 360;
const cv::Point2d& WholeDegreeDirection(int deg) {
  static const std::vector<cv::Point2d> table = [] {
    std::vector<cv::Point2d> t(2 * kTableDeg + 1);
    for (int d = -kTableDeg; d <= kTableDeg; ++d) t[d + kTableDeg] = DirectionVector(d);
    return t;
  }();
  return table[static_cast<std::size_t>(deg + kTableDeg)];
}

}  // namespace

SegmentScore ScoreSegment(const EvidenceMap& evidence, const cv::Point2d& from_px, double deg,
                          double length_px, double hw_px, double t0, double t1, bool coarse,
                          const cv::Point2d& avoid_a, const cv::Point2d& avoid_b,
                          double avoid_hw_px) {
  const Steps steps = StepsOf(length_px, t0, t1, coarse);
  if (steps.along == 0) return {};
  return ScoreStrip(PairSampler(evidence), steps, from_px, DirectionVector(deg), hw_px, avoid_a,
                    avoid_b, avoid_hw_px);
}

PoseScore ScorePose(const EvidenceMap& evidence, const ArmPose& pose, const ArmShape& shape,
                    bool coarse) {
  PoseScore s;
  const ArmJoints j = JointsOf(pose, shape);
  s.upper = ScoreSegment(evidence, j.shoulder, pose.upper_deg, shape.upper_px, shape.upper_hw,
                         kUpperFrom, kUpperTo, coarse);
  s.fore = ScoreSegment(evidence, j.elbow, pose.fore_deg, shape.fore_px, shape.fore_hw, kForeFrom,
                        ForeTo(shape), coarse, j.shoulder, j.elbow, shape.upper_hw + 1);
  s.total = s.upper.score + s.fore.score;
  return s;
}

FitResult FitNear(const EvidenceMap& evidence, const ArmShape& shape, const ArmPose& predicted,
                  const LocalSearch& search) {
  const int ru = std::max(1, static_cast<int>(std::ceil(search.upper_range_deg)));
  const int rb = std::max(1, static_cast<int>(std::ceil(search.bend_range_deg)));
  const int nu = 2 * ru + 1, nb = 2 * rb + 1;
  const double bend0 = AngleDiff(predicted.fore_deg, predicted.upper_deg);
  const cv::Point2d s = predicted.shoulder;
  const PairSampler map(evidence);
  const Steps upper_steps = StepsOf(shape.upper_px, kUpperFrom, kUpperTo, false);
  const Steps fore_steps = StepsOf(shape.fore_px, kForeFrom, ForeTo(shape), false);
  // Each row's upper arm, scored once.
  std::vector<double> upper(static_cast<std::size_t>(nu));
  std::vector<cv::Point2d> elbows(static_cast<std::size_t>(nu));
  for (int i = 0; i < nu; ++i) {
    const cv::Point2d u = DirectionVector(predicted.upper_deg + (i - ru));
    upper[i] = ScoreStrip(map, upper_steps, s, u, shape.upper_hw).score;
    elbows[i] = s + shape.upper_px * u;
  }
  // A cell's total; with kMayGiveUp, kGaveUp once it can no longer reach `bar`.
  constexpr double kSkipped = -4, kGaveUp = -3;  // below any total (-2..2)
  auto cell = [&](auto may_give_up, int i, int j, double bar) {
    const double up = predicted.upper_deg + (i - ru);
    const double bend = bend0 + (j - rb);
    if (std::abs(bend) > kMaxBendDeg) return kSkipped;
    SegmentScore sf;
    const cv::Point2d& elbow = elbows[i];
    if (!ScoreStripUnless<decltype(may_give_up)::value>(
            map, fore_steps, elbow, DirectionVector(up + bend), shape.fore_hw, s, elbow,
            shape.upper_hw + 1, bar - upper[i], &sf)) {
      return kGaveUp;
    }
    return upper[i] + sf.score;
  };
  using Exact = std::false_type;
  using MayGiveUp = std::true_type;
  // The predicted pose first: the best total reaches at least its own, so a cell that can no
  // longer reach the best so far is given up (it is neither the best nor tied with it).
  std::vector<double> total(static_cast<std::size_t>(nu * nb), kSkipped);
  const int centre = ru * nb + rb;
  total[centre] = cell(Exact(), ru, rb, 0);
  double bar = total[centre] > kSkipped ? total[centre] : -std::numeric_limits<double>::infinity();
  int best = -1;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nb; ++j) {
      const int k = i * nb + j;
      if (k != centre) total[k] = cell(MayGiveUp(), i, j, bar);
      if (total[k] <= kGaveUp) continue;
      if (best < 0 || total[k] > total[best]) best = k;
      bar = std::max(bar, total[k]);
    }
  }
  FitResult r;
  r.pose = predicted;
  if (best < 0) {
    r.score = ScorePose(evidence, predicted, shape);
    return r;
  }
  const int bi = best / nb, bj = best % nb;
  double di = bi - ru, dj = bj - rb;
  // A neighbour of the best that was given up is scored in full.
  auto at = [&](int i, int j) {
    double& t = total[static_cast<std::size_t>(i * nb + j)];
    if (t == kGaveUp) t = cell(Exact(), i, j, 0);
    return t;
  };
  if (bi > 0 && bi < nu - 1 && at(bi - 1, bj) > kSkipped && at(bi + 1, bj) > kSkipped) {
    di += ParabolaPeak(at(bi - 1, bj), at(bi, bj), at(bi + 1, bj));
  }
  if (bj > 0 && bj < nb - 1 && at(bi, bj - 1) > kSkipped && at(bi, bj + 1) > kSkipped) {
    dj += ParabolaPeak(at(bi, bj - 1), at(bi, bj), at(bi, bj + 1));
  }
  r.pose.upper_deg = Wrap180(predicted.upper_deg + di);
  r.pose.fore_deg = Wrap180(r.pose.upper_deg + bend0 + dj);
  r.score = ScorePose(evidence, r.pose, shape);
  return r;
}

std::vector<FitResult> FitAnywhere(const EvidenceMap& evidence, const ArmShape& shape,
                                   const cv::Point2d& shoulder, int count) {
  const int nu = static_cast<int>(360 / kWideUpperStep);
  const int nb = 2 * static_cast<int>(kMaxBendDeg / kWideBendStep) + 1;
  std::vector<double> total(static_cast<std::size_t>(nu * nb));
  const PairSampler map(evidence);
  const Steps upper_steps = StepsOf(shape.upper_px, kUpperFrom, kUpperTo, true);
  const Steps fore_steps = StepsOf(shape.fore_px, kForeFrom, ForeTo(shape), true);
  // The grid's directions are whole degrees (whole steps from whole degrees).
  static_assert(kWideUpperStep == 4 && kWideBendStep == 5 && kMaxBendDeg == 150);
  for (int i = 0; i < nu; ++i) {
    const int up = -180 + 4 * (i + 1);
    const cv::Point2d& u = WholeDegreeDirection(up);
    const SegmentScore su = ScoreStrip(map, upper_steps, shoulder, u, shape.upper_hw);
    const cv::Point2d elbow = shoulder + shape.upper_px * u;
    for (int j = 0; j < nb; ++j) {
      const int bend = -150 + 5 * j;
      const SegmentScore sf = ScoreStrip(map, fore_steps, elbow, WholeDegreeDirection(up + bend),
                                         shape.fore_hw, shoulder, elbow, shape.upper_hw + 1);
      total[static_cast<std::size_t>(i * nb + j)] = su.score + sf.score;
    }
  }
  // Local maxima of the grid (the upper arm's direction wraps around), best first.
  std::vector<std::pair<double, int>> peaks;
  const int ri = static_cast<int>(std::ceil(kDistinctDeg / kWideUpperStep));
  const int rj = static_cast<int>(std::ceil(kDistinctDeg / kWideBendStep));
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nb; ++j) {
      const double v = total[static_cast<std::size_t>(i * nb + j)];
      bool peak = true;
      for (int di = -ri; di <= ri && peak; ++di) {
        for (int dj = -rj; dj <= rj && peak; ++dj) {
          const int jj = j + dj;
          if ((di == 0 && dj == 0) || jj < 0 || jj >= nb) continue;
          const int ii = (i + di + nu) % nu;
          const double w = total[static_cast<std::size_t>(ii * nb + jj)];
          // Ties go to the earlier cell, so a plateau gives one peak.
          peak = w < v || (w == v && ii * nb + jj > i * nb + j);
        }
      }
      if (peak) peaks.emplace_back(v, i * nb + j);
    }
  }
  std::sort(peaks.begin(), peaks.end(), [](const auto& a, const auto& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  std::vector<FitResult> out;
  LocalSearch refine;
  refine.upper_range_deg = refine.bend_range_deg = kRefineDeg;
  for (const auto& [v, k] : peaks) {
    if (static_cast<int>(out.size()) >= count) break;
    ArmPose p;
    p.shoulder = shoulder;
    const int upper_step = k / nb, bend_step = k % nb;  // the grid, row by row
    p.upper_deg = Wrap180(-180 + kWideUpperStep * (upper_step + 1));
    p.fore_deg = Wrap180(p.upper_deg - kMaxBendDeg + kWideBendStep * bend_step);
    out.push_back(FitNear(evidence, shape, p, refine));
  }
  std::sort(out.begin(), out.end(),
            [](const FitResult& a, const FitResult& b) { return a.score.total > b.score.total; });
  return out;
}

double ForeRivalScore(const EvidenceMap& evidence, const ArmShape& shape, const ArmPose& pose,
                      double apart_deg) {
  constexpr double kStepDeg = 3;
  const ArmJoints j = JointsOf(pose, shape);
  const double bend0 = AngleDiff(pose.fore_deg, pose.upper_deg);
  double best = -2;
  const PairSampler map(evidence);
  const Steps steps = StepsOf(shape.fore_px, kForeFrom, 1, false);
  for (double bend = -kMaxBendDeg; bend <= kMaxBendDeg; bend += kStepDeg) {
    if (std::abs(bend - bend0) < apart_deg) continue;
    const SegmentScore sf = ScoreStrip(map, steps, j.elbow, DirectionVector(pose.upper_deg + bend),
                                       shape.fore_hw, j.shoulder, j.elbow, shape.upper_hw + 1);
    best = std::max(best, sf.score);
  }
  return best;
}

double PoseDistanceDeg(const ArmPose& a, const ArmPose& b) {
  return std::max(std::abs(AngleDiff(a.upper_deg, b.upper_deg)),
                  std::abs(AngleDiff(a.fore_deg, b.fore_deg)));
}

}  // namespace armmimic::arm
