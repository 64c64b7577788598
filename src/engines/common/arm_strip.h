// One strip of the two-segment arm model (arm_model_fit.h) sampled on the evidence map: its steps
// along it, the samples across it and on its two flanks, and its score, exactly or given up once
// it can no longer reach a bar. Shared, inlined, by the local search and the scoring of poses
// (arm_model_fit.cpp) and the search over every pose (arm_wide_search.cpp). Qt-free.
#pragma once

#include <algorithm>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "common/arm_appearance.h"
#include "common/pair_sampler.h"
#include "common/segment_score.h"

namespace armmimic::arm::strips {

using pairs::Add;
using pairs::Pair;
using pairs::PairOf;
using pairs::PairSampler;
using pairs::Scale;
using pairs::X;
using pairs::Y;

// The strips: the upper arm from just past the shoulder (where it merges with the body) to the
// elbow; the forearm from just past the elbow through the hand.
inline constexpr double kUpperFrom = 0.15, kUpperTo = 0.95;
inline constexpr double kForeFrom = 0.1;
inline constexpr double kHandShare = 0.8;  // of the hand's length: its tip narrows

inline double ForeTo(const ArmShape& shape) {
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

// A strip's steps along it, as distances from its start (pixels): the same in every direction,
// so a search over directions takes them once.
struct Steps {
  int along = 0;  // 0: an empty strip
  bool coarse = false;
  double t[16] = {};
};

inline Steps StepsOf(double length_px, double t0, double t1, bool coarse) {
  Steps s;
  s.coarse = coarse;
  const double span = (t1 - t0) * length_px;
  if (!(span > 0)) return s;
  s.along = coarse ? 6 : std::clamp(static_cast<int>(span / 2.5), 6, 16);
  for (int k = 0; k < s.along; ++k) s.t[k] = (t0 + (t1 - t0) * (k + 0.5) / s.along) * length_px;
  return s;
}

// A coarse strip's samples across it lie this share of its half-width from its middle.
inline constexpr double kCoarseAcross = 0.4;

// Evidence samples lie in [0, 1] (probabilities times shares, blended): a bound a little above,
// and a margin far above the rounding of the sums, for a score that can no longer be reached.
inline constexpr double kMostSample = 1.001, kReachMargin = 1e-6;

// One strip's samples, step by step: the offsets across it and to its flanks are the same at
// every step, so they are set up once.
class StripSampler {
 public:
  StripSampler(const PairSampler& map, const Steps& steps, const cv::Point2d& from_px,
               const cv::Point2d& u, double hw_px, const cv::Point2d& avoid_a,
               const cv::Point2d& avoid_b, double avoid_hw_px)
      : map_(map),
        steps_(steps),
        from_(PairOf(from_px)),
        along_(PairOf(u)),
        n_across_(steps.coarse ? 2 : 4),
        avoid_(avoid_hw_px > 0),
        avoid_a_(avoid_a),
        avoid_b_(avoid_b),
        avoid2_(avoid_hw_px * avoid_hw_px) {
    static constexpr double kFine[4] = {-0.6, -0.2, 0.2, 0.6};
    static constexpr double kCoarse[2] = {-kCoarseAcross, kCoarseAcross};
    const cv::Point2d n(-u.y, u.x);
    const double* across = steps.coarse ? kCoarse : kFine;
    const double flank = hw_px + std::max(2.0, 0.75 * hw_px);
    for (int a = 0; a < n_across_; ++a) inner_[a] = PairOf(across[a] * hw_px * n);
    outer_[0] = PairOf(-1 * flank * n);
    outer_[1] = PairOf(1 * flank * n);
    // A flank sample farther than the avoided half-width beyond the avoided segment's bounding
    // box on either axis is surely not within it (the margin is far above rounding): the exact
    // distance is then not needed.
    const double reach = avoid_hw_px + 1e-3;
    box_x0_ = std::min(avoid_a.x, avoid_b.x) - reach;
    box_x1_ = std::max(avoid_a.x, avoid_b.x) + reach;
    box_y0_ = std::min(avoid_a.y, avoid_b.y) - reach;
    box_y1_ = std::max(avoid_a.y, avoid_b.y) + reach;
  }

  int across() const { return n_across_; }

  // Step k's samples: inside the strip into ins[0..across()), on the flanks not avoided into
  // fl[0..), their count returned.
  int Sample(int k, float* ins, float* fl) const {
    const Pair p = Add(from_, Scale(steps_.t[k], along_));
    for (int a = 0; a < n_across_; ++a) ins[a] = map_.At(Add(p, inner_[a]));
    int nf = 0;
    for (const Pair& side : outer_) {
      const Pair q = Add(p, side);
      const double qx = X(q), qy = Y(q);
      if (avoid_ && qx > box_x0_ && qx < box_x1_ && qy > box_y0_ && qy < box_y1_ &&
          SquaredDistanceToSegment({qx, qy}, avoid_a_, avoid_b_) < avoid2_) {
        continue;
      }
      fl[nf++] = map_.At(q);
    }
    return nf;
  }

 private:
  const PairSampler& map_;
  const Steps& steps_;
  Pair from_, along_;
  int n_across_;
  Pair inner_[4], outer_[2];
  bool avoid_;
  cv::Point2d avoid_a_, avoid_b_;
  double avoid2_, box_x0_ = 0, box_x1_ = 0, box_y0_ = 0, box_y1_ = 0;
};

// The sums of a strip's samples inside it and on its flanks (and the flanks' count), unless the
// score can no longer reach `at_least` (false): after every step, the samples still to take
// counted at their most inside the strip and at their least on the flanks. From the strip's far
// end: a pose away from the arm is seen to be away there first (near its start the strip still
// lies on the segment it joins). The samples are kept and summed at the end in the order the
// exact path sums them, so sums not given up are that path's to the bit; the bound's sums, in
// another order, differ from them by rounding far below the margin.
inline bool SumUnless(const StripSampler& strip, const Steps& steps, double at_least,
                      double* inside, double* flanks, int* n_flank) {
  const int n_across = strip.across();
  float ins[16][4], fl[16][2];
  int nf[16];
  double inside_any = 0, flanks_any = 0;
  int n_flank_any = 0;
  for (int m = 0; m < steps.along; ++m) {
    const int k = steps.along - 1 - m;
    nf[k] = strip.Sample(k, ins[k], fl[k]);
    for (int a = 0; a < n_across; ++a) inside_any += ins[k][a];
    for (int f = 0; f < nf[k]; ++f) flanks_any += fl[k][f];
    n_flank_any += nf[k];
    const int left = k;
    if (left > 0) {
      const double most_inside =
          (inside_any + left * n_across * kMostSample) / (steps.along * n_across);
      const int most_flank = n_flank_any + 2 * left;
      const double least_flank = flanks_any / most_flank;
      if (most_inside - least_flank < at_least - kReachMargin) return false;
    }
  }
  for (int k = 0; k < steps.along; ++k) {
    for (int a = 0; a < n_across; ++a) *inside += ins[k][a];
    for (int f = 0; f < nf[k]; ++f) *flanks += fl[k][f];
    *n_flank += nf[k];
  }
  return true;
}

// ScoreSegment with its steps and its direction's unit vector `u` given, into *out. With
// kMayGiveUp, it gives up (false, *out unset) once the score can no longer reach `at_least`
// (SumUnless).
template <bool kMayGiveUp>
bool ScoreStripUnless(const PairSampler& map, const Steps& steps, const cv::Point2d& from_px,
                      const cv::Point2d& u, double hw_px, const cv::Point2d& avoid_a,
                      const cv::Point2d& avoid_b, double avoid_hw_px, double at_least,
                      SegmentScore* out) {
  *out = SegmentScore();
  if (steps.along == 0) return true;
  const StripSampler strip(map, steps, from_px, u, hw_px, avoid_a, avoid_b, avoid_hw_px);
  const int n_across = strip.across();
  double inside = 0, flanks = 0;
  int n_flank = 0;
  if constexpr (kMayGiveUp) {
    if (!SumUnless(strip, steps, at_least, &inside, &flanks, &n_flank)) return false;
  } else {
    for (int k = 0; k < steps.along; ++k) {
      float ins[4], fl[2];
      const int n = strip.Sample(k, ins, fl);
      for (int a = 0; a < n_across; ++a) inside += ins[a];
      for (int f = 0; f < n; ++f) flanks += fl[f];
      n_flank += n;
    }
  }
  out->inside = inside / (steps.along * n_across);
  out->score = out->inside - (n_flank > 0 ? flanks / n_flank : 0.0);
  return true;
}

inline SegmentScore ScoreStrip(const PairSampler& map, const Steps& steps,
                               const cv::Point2d& from_px, const cv::Point2d& u, double hw_px,
                               const cv::Point2d& avoid_a = {}, const cv::Point2d& avoid_b = {},
                               double avoid_hw_px = 0) {
  SegmentScore out;
  ScoreStripUnless<false>(map, steps, from_px, u, hw_px, avoid_a, avoid_b, avoid_hw_px, 0, &out);
  return out;
}

// DirectionVector of the whole degrees -kTableDeg..kTableDeg, computed once: the wide search's
// directions are all whole degrees.
inline constexpr int kTableDeg = 360;
inline const cv::Point2d& WholeDegreeDirection(int deg) {
  static const std::vector<cv::Point2d> table = [] {
    std::vector<cv::Point2d> t(2 * kTableDeg + 1);
    for (int d = -kTableDeg; d <= kTableDeg; ++d) t[d + kTableDeg] = DirectionVector(d);
    return t;
  }();
  return table[static_cast<std::size_t>(deg + kTableDeg)];
}

}  // namespace armmimic::arm::strips
