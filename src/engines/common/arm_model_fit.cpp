#include "common/arm_model_fit.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "armmimic/core/angles.h"
#include "common/arm_strip.h"

namespace armmimic::arm {
namespace {

using pairs::PairSampler;
using strips::ForeTo;
using strips::kForeFrom;
using strips::kUpperFrom;
using strips::kUpperTo;
using strips::ScoreStrip;
using strips::ScoreStripUnless;
using strips::Steps;
using strips::StepsOf;

// Offset of the peak of a parabola through (-1, a), (0, b), (1, c), within half a step.
double ParabolaPeak(double a, double b, double c) {
  const double den = a - 2 * b + c;
  return den < 0 ? std::clamp(0.5 * (a - c) / den, -0.5, 0.5) : 0.0;
}

}  // namespace

double DistanceToSegment(const cv::Point2d& p, const cv::Point2d& a, const cv::Point2d& b) {
  return std::sqrt(strips::SquaredDistanceToSegment(p, a, b));
}

ArmJoints JointsOf(const ArmPose& pose, const ArmShape& shape) {
  ArmJoints j;
  j.shoulder = pose.shoulder;
  j.elbow = pose.shoulder + shape.upper_px * DirectionVector(pose.upper_deg);
  j.wrist = j.elbow + shape.fore_px * DirectionVector(pose.fore_deg);
  return j;
}

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
