// The anchored tracker's sleeves: their colour and width learnt in the starting posture, the
// search that refines a part's direction, the arm's reach when it turns out of the picture, the
// shoulder refined from the sleeve's lines and the elbow where the two sleeves meet.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "lk/anchored_tracker.h"

namespace armmimic::lk::anchored {

// Reads the sleeve's colour and width along both parts in the known starting posture, and
// when the arm starts straight, its length (shoulder to cuff) for the elbow prior.
void AnchoredTracker::LearnBars(const cv::Mat& bgr, int side) {
  if (!o_.use_bar || bgr.empty()) return;
  const double max_hw = MaxHalfWidth();
  upper_bar_[side] = LearnArmBar(bgr, shoulder_, upper_deg_, lu_, max_hw);
  const double prior_len = arm_len_, prior_lu = lu_, prior_lf = lf_;
  if (!lengths_measured_ && upper_bar_[side].valid &&
      std::abs(AngleDiff(fore_deg_, upper_deg_)) < 5) {
    const double sleeve =
        MeasureBarLength(bgr, upper_bar_[side], shoulder_, upper_deg_, 1.6 * arm_len_);
    if (sleeve > 0.5 * arm_len_ && sleeve < 1.5 * arm_len_) {
      sleeve_measured_[side] = true;
      arm_len_ = sleeve;
      lu_ = o_.upper_fraction * arm_len_;
      lf_ = arm_len_ - lu_;
      SetPoseMotions();
      upper_bar_[side] = LearnArmBar(bgr, shoulder_, upper_deg_, lu_, max_hw);
    }
  }
  fore_bar_[side] = LearnArmBar(bgr, Elbow(), fore_deg_, lf_, max_hw);
  start_half_width_[side] =
      cv::Vec2d(upper_bar_[side].half_width_px, fore_bar_[side].half_width_px);
  side_lengths_[side] = cv::Vec3d(arm_len_, lu_, lf_);
  arm_len_ = prior_len;
  lu_ = prior_lu;
  lf_ = prior_lf;
  SetPoseMotions();
}

// Refines a part's direction with the bar search when the part stands out of its
// surroundings (over the wall, not in front of the body in the same cloth).
// For the forearm (`avoid_fold`), directions folded back onto the upper arm beyond
// `max_bend_deg` are not searched: there the forearm's strip lies on the upper arm's sleeve.
// Sets axis_[part] when the sleeve's axis was found (CentreArmBar).
double AnchoredTracker::RefineWithBar(const cv::Mat& bgr, int part, const cv::Point2d& joint_px,
                                      double deg, double length_px, bool* used, double range_deg) {
  *used = false;
  axis_[part] = BarAxis();
  const ArmBar& learned = part == kUpper ? upper_bar_[side_] : fore_bar_[side_];
  if (!o_.use_bar || !learned.valid) return deg;
  // Near the starting direction, where the sleeve lies against the body, the search runs as at
  // the start (the width read then) so that the lean measured then (CalibrateBars) applies,
  // fading out over kBiasFadeDeg; only a sleeve clear on both sides is centred there.
  const double start_deg = part == kUpper ? o_.initial_upper_deg : o_.initial_fore_deg;
  const bool near_start = std::abs(AngleDiff(deg, start_deg)) < kBiasFadeDeg;
  ArmBar bar = learned;
  if (near_start) bar.half_width_px = start_half_width_[side_][part];
  const BarSearch r = SearchArmBar(
      bgr, bar, joint_px, deg, length_px, range_deg > 0 ? range_deg : o_.bar_search_deg,
      o_.bar_min_score, Wrap180(upper_deg_ + 180), part == kFore ? 180 - o_.max_bend_deg : 0);
  if (!r.found) return deg;
  *used = true;
  // The search's best strip may lean inside a sleeve wider than the strip; the sleeve's own
  // centre line gives the direction.
  const double fade = 1 - std::abs(AngleDiff(r.deg, start_deg)) / kBiasFadeDeg;
  axis_[part] = CentreArmBar(bgr, learned, joint_px, r.deg, length_px, MaxHalfWidth(), fade <= 0);
  if (axis_[part].found) return axis_[part].deg;
  return fade > 0 ? Wrap180(r.deg - fade * bar_bias_[side_][part]) : r.deg;
}

// A straight arm turned towards or away from the camera looks shorter: its sleeve, measured
// from the shoulder along the upper arm, ends before the length it had at the start. The joints
// are then placed on the shorter arm (reach_ < 1), so the forearm is searched where it is seen.
// Only when the sleeve's length was read at a straight start and its end now is clear. Entered
// from a straight arm (a bent arm's sleeve also ends early, at the elbow); left when the sleeve
// is long again (here) or the forearm is found bent (FitPose).
void AnchoredTracker::UpdateReach(const cv::Mat& bgr, double upper_deg, double bend_deg) {
  if (!sleeve_measured_[side_]) return;
  if (!upper_bar_used_) return;  // no sleeve to measure in this frame: keep the last reach
  double beyond = 1;
  const double run =
      MeasureBarLength(bgr, upper_bar_[side_], shoulder_, upper_deg, 1.6 * arm_len_, &beyond);
  // A sleeve that fades into its surroundings (a shirt close to the wall's colour) gives no
  // length.
  double k = beyond < kClearEnd ? run / arm_len_ : 1;
  if (k < kShortReach && reach_ == 1) {
    // An elbow starting to bend also ends the run early, but there the forearm's sleeve goes
    // on beside the end; past a shortened straight arm's end there is no sleeve.
    const ArmBar& fore = fore_bar_[side_];
    const double r = 2 * fore.half_width_px;
    const cv::Point2d past = shoulder_ + (run + r) * DirectionVector(upper_deg);
    if (BarShareAround(bgr, fore, past, r) > kSleeveBesideEnd) k = 1;
  }
  const bool straight = std::abs(bend_deg) < kStraightStartDeg;
  const bool shortened = k < kShortReach && (straight || reach_ < 1);
  reach_ = shortened ? std::max(kMinReach, k) : 1;
}

// The sleeve's width read at the start is a guess: against the body only its outer half shows,
// from an axis that may be off centre. Wherever the part stands clear (its sleeve ends on both
// sides), the width is measured across it; the median of the latest such readings becomes the
// bar's width. A width read too narrow makes the flanks fall inside the sleeve, so the search
// prefers a strip along either edge and the direction flips by several degrees frame to frame.
void AnchoredTracker::LearnBarWidth(const cv::Mat& bgr, int part, const cv::Point2d& joint_px,
                                    double deg, double length_px) {
  ArmBar& bar = part == kUpper ? upper_bar_[side_] : fore_bar_[side_];
  const double hw = MeasureBarHalfWidth(bgr, bar, joint_px, deg, length_px, MaxHalfWidth());
  if (hw <= 0) return;
  std::vector<double>& seen = bar_widths_[part];
  seen.push_back(hw);
  if (seen.size() > kWidthReadings) seen.erase(seen.begin());
  if (seen.size() >= kMinWidthReadings) {
    bar.half_width_px = std::max(1.5, Median(seen));
    bar.width_measured = true;
  }
}

// The sleeve search in the known starting posture: where a sleeve lies against the body in
// the same cloth, one flank tells nothing and the best strip leans a few degrees. That lean,
// measured here where the truth is known, is taken off readings near the same direction.
void AnchoredTracker::CalibrateBars(const cv::Mat& bgr, int side) {
  if (!o_.use_bar || bgr.empty()) return;
  const BarSearch u = upper_bar_[side].valid
                          ? SearchArmBar(bgr, upper_bar_[side], shoulder_, upper_deg_, lu_,
                                         kBiasSearchDeg, o_.bar_min_score)
                          : BarSearch();
  const BarSearch f = fore_bar_[side].valid ? SearchArmBar(bgr, fore_bar_[side], Elbow(), fore_deg_,
                                                           lf_, kBiasSearchDeg, o_.bar_min_score)
                                            : BarSearch();
  bar_bias_[side] = cv::Vec2d(u.found ? AngleDiff(u.deg, upper_deg_) : 0,
                              f.found ? AngleDiff(f.deg, fore_deg_) : 0);
}

// The shoulder from the body box is a rule of thumb; the upper arm's sleeve, wherever it stands
// clear, lies on a line through the true shoulder. Each such line (the sleeve's axis found by
// RefineWithBar) is accumulated, and the shoulder becomes their least-squares intersection once
// lines at different angles are in.
void AnchoredTracker::RefineShoulder() {
  const BarAxis& axis = axis_[kUpper];
  if (!axis.found) return;
  const cv::Point2d u = DirectionVector(axis.deg);
  const cv::Vec2d n(-u.y, u.x);
  const double c = n[0] * axis.point_px.x + n[1] * axis.point_px.y;
  line_a_ += cv::Matx22d(n[0] * n[0], n[0] * n[1], n[0] * n[1], n[1] * n[1]);
  line_b_ += cv::Vec2d(n[0] * c, n[1] * c);
  ++line_count_;
  // Lines must span some angle: the smaller eigenvalue of the mean of n n^T.
  const cv::Matx22d mean = line_a_ * (1.0 / line_count_);
  const double tr = mean(0, 0) + mean(1, 1);
  const double det = mean(0, 0) * mean(1, 1) - mean(0, 1) * mean(1, 0);
  const double min_eig = 0.5 * tr - std::sqrt(std::max(0.0, 0.25 * tr * tr - det));
  if (min_eig < 0.03) return;  // about 10 degrees of spread
  const cv::Vec2d sol = line_a_.inv() * line_b_;
  const cv::Point2d refined(sol[0], sol[1]);
  if (Dist(refined, shoulder_start_) > shoulder_reach_) return;
  shoulder_ = refined;
}

// Where the elbow lies along the upper arm, from the sleeves in the current frame: once the arm
// is bent, the forearm's sleeve is found by moving its pivot along the upper arm as well as
// turning it, and the best pivot is where the two sleeves meet. Each frame's pivot is averaged
// with weight sin^2(bend), as a straighter arm tells less.
void AnchoredTracker::LocateElbowOnBar(const cv::Mat& bgr, double fore_deg) {
  const double bend = AngleDiff(fore_deg, upper_deg_);
  if (std::abs(bend) < o_.bend_for_elbow_deg) return;
  const ArmBar& bar = fore_bar_[side_];
  const cv::Point2d u = DirectionVector(upper_deg_);
  const int n_l = 2 * kElbowShiftPx + 1;
  std::vector<double> best_per_l(n_l, -2);
  int best_i = -1;
  for (int i = 0; i < n_l; ++i) {
    const cv::Point2d pivot = shoulder_ + (lu_ + i - kElbowShiftPx) * u;
    for (int a = -kElbowTurnDeg; a <= kElbowTurnDeg; ++a) {
      best_per_l[i] = std::max(
          best_per_l[i], ArmBarScore(bgr, bar, pivot, fore_deg + a, kElbowStripFraction * lf_));
    }
    if (best_i < 0 || best_per_l[i] > best_per_l[best_i]) best_i = i;
  }
  // A best pivot at the edge of the search is no measurement.
  if (best_i <= 0 || best_i >= n_l - 1 || best_per_l[best_i] < o_.bar_min_score) return;
  double offset = best_i - kElbowShiftPx;
  const double a = best_per_l[best_i - 1], b = best_per_l[best_i], c = best_per_l[best_i + 1];
  const double den = a - 2 * b + c;
  if (den < 0) offset += std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
  if (elbow_den_ == 0) {
    // The prior (upper_fraction of the arm) counts like a few fully bent frames, so a burst of
    // misleading frames early on (a sleeve close to the wall's colour) cannot pull the elbow
    // away.
    elbow_num_ = kElbowPriorWeight * lu_;
    elbow_den_ = kElbowPriorWeight;
  }
  const double s = std::sin(bend * kPi / 180);
  elbow_num_ += s * s * (lu_ + offset);
  elbow_den_ += s * s;
  if (!lengths_measured_)
    lu_ = std::clamp(elbow_num_ / elbow_den_, 0.3 * arm_len_, 0.75 * arm_len_);
  elbow_from_bar_ = true;
}

}  // namespace armmimic::lk::anchored
