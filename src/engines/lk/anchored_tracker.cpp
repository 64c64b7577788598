// The anchored tracker: the improvement over thesis 6.4. Every feature keeps its reference
// position in its part's own frame (origin at the shoulder or the elbow, x along the part), taken
// from the pose when the feature was seeded. Each frame the absolute motion of each part is
// re-fitted (eq. 6-16) from the reference positions to the tracked ones, so the angles are not
// sums of increments and the error does not grow with the sequence length. Features whose
// residual stays large (shadows, the body behind the arm, noise) are dropped; new ones are
// seeded on the arm along the current estimate; the elbow position is learned from which
// features follow which part once the elbow bends.
#include <algorithm>
#include <cmath>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "lk/arm_bar.h"
#include "lk/fit.h"
#include "lk/flow.h"
#include "lk/tracker.h"

namespace armmimic::lk {
namespace {

enum Part { kUpper = 0, kFore = 1 };

struct Feature {
  cv::Point2f p;          // current position
  cv::Point2f prev;       // position in the previous frame
  cv::Point2d seed_p;     // position when seeded
  double seed_upper = 0;  // pose when seeded
  double seed_fore = 0;
  int side = 0;            // shoulder candidate it was seeded for
  int label = kUpper;      // which part it follows
  bool confirmed = false;  // followed its part's motion far enough to be trusted
  int still = 0;           // consecutive frames without motion
  int outlier = 0;         // consecutive frames with a large residual
  int agree = 0;           // consecutive frames a candidate followed its part
  double along = 0;        // place along the arm from the shoulder, in the seeding pose
  // Per-frame scratch.
  cv::Point2d cu, cf;     // reference position in the upper-arm and forearm frames
  double ru = 0, rf = 0;  // residuals under the two fits
  bool in_fit = false;
};

// Position of `d` in a part's frame whose x axis points along direction `deg`.
cv::Point2d ToPartFrame(const cv::Point2d& d, double deg) {
  const cv::Point2d u = DirectionVector(deg);
  const cv::Point2d v(-u.y, u.x);  // image-axes normal: (sin, cos) of the CCW angle
  return {d.dot(u), d.dot(v)};
}

// The motion that puts a part's frame at `origin` with direction `deg`.
Motion2D PartMotion(double deg, const cv::Point2d& origin) {
  Motion2D m;
  const cv::Point2d u = DirectionVector(deg);
  m.a = u.x;
  m.b = u.y;
  m.t = origin;
  return m;
}

double SegmentDistance(const cv::Point2d& p, const cv::Point2d& a, const cv::Point2d& b) {
  const cv::Point2d ab = b - a;
  const double len2 = ab.dot(ab);
  double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const cv::Point2d q = a + t * ab;
  return std::hypot(p.x - q.x, p.y - q.y);
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  return v[mid];
}

double Dist(const cv::Point2d& a, const cv::Point2d& b) { return std::hypot(a.x - b.x, a.y - b.y); }

class AnchoredTracker : public Tracker {
 public:
  explicit AnchoredTracker(const LkOptions& options) : o_(options), flow_(options) {}

  TrackerPose Start(const TrackerStart& start) override {
    size_ = start.gray.size();
    flow_.Reset(start.gray);
    shoulders_ = start.shoulders;
    head_limit_y_ = start.head_limit_y;
    arm_len_ = start.arm_length_px > 0 ? start.arm_length_px : 0.4 * size_.height;
    lu_ = o_.upper_fraction * arm_len_;
    lf_ = arm_len_ - lu_;
    support_ = 1;
    prev_gray_.release();
    lengths_measured_ = start.upper_length_px > 0 && start.fore_length_px > 0;
    if (lengths_measured_) {
      lu_ = start.upper_length_px;
      lf_ = start.fore_length_px;
      arm_len_ = lu_ + lf_;
    }
    upper_deg_ = Wrap180(o_.initial_upper_deg);
    fore_deg_ = Wrap180(o_.initial_fore_deg);
    side_ = shoulders_.size() == 1 ? 0 : -1;
    feats_.clear();
    bar_widths_[kUpper].clear();
    bar_widths_[kFore].clear();
    frame_ = 0;
    side_lengths_.assign(shoulders_.size(), cv::Vec3d(arm_len_, lu_, lf_));
    upper_bar_.assign(shoulders_.size(), ArmBar());
    fore_bar_.assign(shoulders_.size(), ArmBar());
    bar_bias_.assign(shoulders_.size(), cv::Vec2d(0, 0));
    start_half_width_.assign(shoulders_.size(), cv::Vec2d(0, 0));
    sleeve_measured_.assign(shoulders_.size(), false);
    reach_ = 1;
    for (int s = 0; s < static_cast<int>(shoulders_.size()); ++s) {
      shoulder_ = shoulders_[s];
      SetPoseMotions();
      LearnBars(start.bgr, s);
      UseSideLengths(s);
      SetPoseMotions();
      CalibrateBars(start.bgr, s);
      Seed(start.gray, s, 1.25);
    }
    if (side_ == 0) {
      shoulder_ = shoulders_[0];
      UseSideLengths(0);
    }
    shoulder_start_ = shoulder_;
    refine_shoulder_ = o_.refine_shoulder;
    // A shoulder given by the user (a click) is only nudged onto the sleeves' lines.
    shoulder_reach_ =
        (start.shoulder_fixed ? kGivenShoulderReach : kBodyBoxShoulderReach) * arm_len_;
    line_a_ = cv::Matx22d::zeros();
    line_b_ = cv::Vec2d(0, 0);
    line_count_ = 0;
    SetPoseMotions();
    last_seed_ = 0;
    elbow_num_ = elbow_den_ = 0;
    elbow_from_bar_ = false;
    return MakePose();
  }

  TrackerPose Track(const cv::Mat& gray, const cv::Mat& bgr) override {
    ++frame_;
    TrackFeatures(gray);
    if (side_ < 0) {
      std::vector<cv::Point2f> seeds, now;
      for (const Feature& f : feats_) {
        seeds.emplace_back(static_cast<float>(f.seed_p.x), static_cast<float>(f.seed_p.y));
        now.push_back(f.p);
      }
      side_ = DecideSide(shoulders_, seeds, now, 2 * o_.motion_threshold_px, head_limit_y_, 3);
      if (side_ < 0) return MakePose();
      shoulder_ = shoulders_[side_];
      shoulder_start_ = shoulder_;
      UseSideLengths(side_);
      feats_.erase(std::remove_if(feats_.begin(), feats_.end(),
                                  [&](const Feature& f) { return f.side != side_; }),
                   feats_.end());
      SetPoseMotions();
    }
    FitPose(bgr);
    RateSupport(gray);
    UpdateFeatures();
    LearnElbow();
    const bool sparse =
        CountPart(kUpper) < o_.min_part_features || CountPart(kFore) < o_.min_part_features;
    if (reach_ == 1 &&
        (frame_ - last_seed_ >= o_.reseed_interval || (sparse && frame_ - last_seed_ >= 1))) {
      Seed(gray, side_, 1.1);
      last_seed_ = frame_;
    }
    return MakePose();
  }

 private:
  // Reads the sleeve's colour and width along both parts in the known starting posture, and
  // when the arm starts straight, its length (shoulder to cuff) for the elbow prior.
  void LearnBars(const cv::Mat& bgr, int side) {
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

  void UseSideLengths(int side) {
    if (side < 0 || side >= static_cast<int>(side_lengths_.size())) return;
    arm_len_ = side_lengths_[side][0];
    lu_ = side_lengths_[side][1];
    lf_ = side_lengths_[side][2];
  }

  void SetPoseMotions() {
    tu_ = PartMotion(upper_deg_, shoulder_);
    tf_ = PartMotion(fore_deg_, Elbow());
  }
  // The joints as seen: a straight arm turned out of the picture is shorter by reach_.
  cv::Point2d Elbow() const { return tu_.Apply({reach_ * lu_, 0}); }
  cv::Point2d Wrist() const { return tf_.Apply({reach_ * lf_, 0}); }
  double HalfWidth() const { return std::max(3.0, o_.arm_width_ratio * arm_len_); }
  // Widest half-width a sleeve is looked for across.
  double MaxHalfWidth() const { return std::max(3.0, 0.15 * arm_len_); }

  void TrackFeatures(const cv::Mat& gray) {
    lk::TrackFeatures(&flow_, gray, &feats_);
    for (Feature& f : feats_) {
      const cv::Point2f d = f.p - f.prev;
      f.still = std::hypot(d.x, d.y) < o_.motion_threshold_px ? f.still + 1 : 0;
    }
  }

  // Reference positions of every feature for the current shoulder and upper-arm length, and its
  // part: a feature belongs to the upper arm when its place along the arm (measured in the pose it
  // was seeded in) lies before the elbow.
  void ComputeReferences() {
    for (Feature& f : feats_) {
      const cv::Point2d elbow_at_seed = shoulder_ + lu_ * DirectionVector(f.seed_upper);
      f.cu = ToPartFrame(f.seed_p - shoulder_, f.seed_upper);
      f.cf = ToPartFrame(f.seed_p - elbow_at_seed, f.seed_fore);
      f.label = f.along < lu_ ? kUpper : kFore;
    }
  }

  // Fits one part. Each feature implies the part's direction by how it turned about the part's
  // joint since it was seeded; the weighted median of those is robust to features that do not
  // belong (the body behind the arm, shadows). The features near the median are then fitted by
  // least squares (eq. 6-16) from their reference to their current positions, with the joint as
  // a pseudo-feature; the fitted rotation is the part's absolute direction. Returns false when
  // no feature tells the part's direction. Sets in_fit for the features used.
  bool FitPart(int part, const cv::Point2d& joint_px, double previous_deg, double prior_deg,
               double prior_weight, bool bootstrap, Motion2D* out) {
    std::vector<std::pair<double, double>> votes;  // (angle offset from previous, weight)
    std::vector<int> idx;
    for (int i = 0; i < static_cast<int>(feats_.size()); ++i) {
      Feature& f = feats_[i];
      if (f.label != part) continue;
      bool use = f.confirmed;
      if (!use && bootstrap) use = Dist(cv::Point2d(f.p), f.seed_p) > o_.confirm_motion_px;
      if (!use) continue;
      const cv::Point2d ref = part == kUpper ? f.cu : f.cf;
      const double lever = std::hypot(ref.x, ref.y);
      if (lever < kMinLeverPx || Dist(cv::Point2d(f.p), joint_px) < kMinLeverPx) continue;
      // Direction of the feature from the joint, minus its angle in the part's own frame.
      const double ref_deg = -DegFromRad(std::atan2(ref.y, ref.x));
      const double implied = DirectionDeg(joint_px, cv::Point2d(f.p)) - ref_deg;
      votes.emplace_back(AngleDiff(implied, previous_deg), lever);
      idx.push_back(i);
    }
    if (votes.empty()) return false;
    const std::size_t n_features = votes.size();
    // The prior (where the part would be if it kept its pose) votes like a few features at the
    // part's end, so one stray feature cannot turn a part that has no trusted ones.
    votes.emplace_back(AngleDiff(prior_deg, previous_deg), prior_weight);
    std::vector<std::pair<double, double>> sorted = votes;
    std::sort(sorted.begin(), sorted.end());
    double total = 0;
    for (const auto& v : sorted) total += v.second;
    double acc = 0, median = sorted.back().first;
    for (const auto& v : sorted) {
      acc += v.second;
      if (acc >= 0.5 * total) {
        median = v.first;
        break;
      }
    }
    std::vector<cv::Point2d> from, to;
    std::vector<double> w;
    std::vector<int> used;
    for (std::size_t k = 0; k < n_features; ++k) {
      if (std::abs(votes[k].first - median) > o_.inlier_deg) continue;
      const Feature& f = feats_[idx[k]];
      from.push_back(part == kUpper ? f.cu : f.cf);
      to.emplace_back(f.p);
      w.push_back(1.0);
      used.push_back(idx[k]);
    }
    const double median_deg = Wrap180(previous_deg + median);
    Motion2D m = PartMotion(median_deg, joint_px);
    from.emplace_back(0, 0);
    to.push_back(joint_px);
    w.push_back(o_.joint_weight);
    Motion2D fitted;
    if (used.size() >= 2 && FitRigidMotion(from, to, w, &fitted) &&
        std::abs(AngleDiff(fitted.RotationCcwDeg(), median_deg)) <= o_.inlier_deg) {
      m = fitted;
    }
    for (int i : used) feats_[i].in_fit = true;
    *out = m;
    return true;
  }

  // Refines a part's direction with the bar search when the part stands out of its
  // surroundings (over the wall, not in front of the body in the same cloth).
  // For the forearm (`avoid_fold`), directions folded back onto the upper arm beyond
  // `max_bend_deg` are not searched: there the forearm's strip lies on the upper arm's sleeve.
  // Sets axis_[part] when the sleeve's axis was found (CentreArmBar).
  double RefineWithBar(const cv::Mat& bgr, int part, const cv::Point2d& joint_px, double deg,
                       double length_px, bool* used, double range_deg = 0) {
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
  void UpdateReach(const cv::Mat& bgr, double upper_deg, double bend_deg) {
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
  void LearnBarWidth(const cv::Mat& bgr, int part, const cv::Point2d& joint_px, double deg,
                     double length_px) {
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
  void CalibrateBars(const cv::Mat& bgr, int side) {
    if (!o_.use_bar || bgr.empty()) return;
    const BarSearch u = upper_bar_[side].valid
                            ? SearchArmBar(bgr, upper_bar_[side], shoulder_, upper_deg_, lu_,
                                           kBiasSearchDeg, o_.bar_min_score)
                            : BarSearch();
    const BarSearch f = fore_bar_[side].valid
                            ? SearchArmBar(bgr, fore_bar_[side], Elbow(), fore_deg_, lf_,
                                           kBiasSearchDeg, o_.bar_min_score)
                            : BarSearch();
    bar_bias_[side] = cv::Vec2d(u.found ? AngleDiff(u.deg, upper_deg_) : 0,
                                f.found ? AngleDiff(f.deg, fore_deg_) : 0);
  }

  // The shoulder from the body box is a rule of thumb; the upper arm's sleeve, wherever it stands
  // clear, lies on a line through the true shoulder. Each such line (the sleeve's axis found by
  // RefineWithBar) is accumulated, and the shoulder becomes their least-squares intersection once
  // lines at different angles are in.
  void RefineShoulder() {
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

  void FitPose(const cv::Mat& bgr) {
    ComputeReferences();
    for (Feature& f : feats_) f.in_fit = false;
    const double bend = AngleDiff(fore_deg_, upper_deg_);
    Motion2D tu;
    double up = upper_deg_;
    const bool fitted_up = FitPart(kUpper, shoulder_, upper_deg_, upper_deg_, o_.prior_weight * lu_,
                                   CountConfirmed(kUpper) < 3, &tu);
    if (fitted_up) up = Wrap180(tu.RotationCcwDeg());
    // A strip much shorter than the sleeve's width tells no direction: the upper arm is searched
    // over at least half its length even when it is seen shorter.
    const double lu = std::max(reach_, kEndOnReach) * lu_;
    up = RefineWithBar(bgr, kUpper, shoulder_, up, lu, &upper_bar_used_);
    if (!upper_bar_used_) {
      // The features may have been misled (too few, or on the background); the sleeve may still
      // be where the part was.
      up = RefineWithBar(bgr, kUpper, shoulder_, upper_deg_, lu, &upper_bar_used_);
      if (!upper_bar_used_ && fitted_up) up = Wrap180(tu.RotationCcwDeg());
    }
    if (upper_bar_used_ && refine_shoulder_) RefineShoulder();
    if (upper_bar_used_ && reach_ == 1) LearnBarWidth(bgr, kUpper, shoulder_, up, lu_);
    UpdateReach(bgr, up, bend);
    upper_deg_ = up;
    tu_ = PartMotion(upper_deg_, shoulder_);
    fore_bar_used_ = false;
    // Seen nearly end-on, a short forearm tells no direction: the arm was straight when it turned
    // away and is taken so.
    double fo = reach_ < kEndOnReach ? upper_deg_ : FitForearm(bgr, bend);
    if (reach_ < 1) {
      const double bent = std::abs(AngleDiff(fo, upper_deg_));
      if (bent > kFoldedDeg) {
        fo = upper_deg_;  // a short forearm's strip folded back onto the upper arm: an artefact
      } else if (bent > kStraightDeg) {
        reach_ = 1;  // the forearm is bent: the sleeve ended at the elbow, not early
      }
    }
    fore_deg_ = fo;
    tf_ = PartMotion(fore_deg_, Elbow());
    for (Feature& f : feats_) {
      f.ru = Dist(tu_.Apply(f.cu), cv::Point2d(f.p));
      f.rf = Dist(tf_.Apply(f.cf), cv::Point2d(f.p));
    }
  }

  // The forearm's direction about the elbow: features, then its sleeve around their estimate,
  // around the previous bend, and over every bend the elbow allows; the elbow itself is located
  // where the two sleeves meet.
  double FitForearm(const cv::Mat& bgr, double bend) {
    const cv::Point2d elbow = Elbow();
    const double fo_prior = Wrap180(upper_deg_ + bend);
    double fo = fo_prior;
    Motion2D tf;
    if (FitPart(kFore, elbow, fore_deg_, fo, o_.prior_weight * lf_, CountConfirmed(kFore) < 3,
                &tf)) {
      fo = Wrap180(tf.RotationCcwDeg());
    }
    const double fo_feat = fo;
    const double lf = reach_ * lf_;
    fo = RefineWithBar(bgr, kFore, elbow, fo_feat, lf, &fore_bar_used_);
    if (!fore_bar_used_) {
      fo = RefineWithBar(bgr, kFore, elbow, fo_prior, lf, &fore_bar_used_);
    }
    if (!fore_bar_used_) {
      // Lost (the forearm foreshortened, turned out of the picture, or the features ran off):
      // every bend the elbow allows is searched.
      fo = RefineWithBar(bgr, kFore, elbow, upper_deg_, lf, &fore_bar_used_, o_.max_bend_deg);
      if (!fore_bar_used_) fo = fo_feat;
    }
    // No estimate bends the elbow past its limit.
    const double bent = AngleDiff(fo, upper_deg_);
    if (std::abs(bent) > o_.max_bend_deg) {
      fo = Wrap180(upper_deg_ + std::copysign(o_.max_bend_deg, bent));
    }
    if (fore_bar_used_ && reach_ == 1) {
      LocateElbowOnBar(bgr, fo);
      // The forearm's sleeve about the elbow found so far.
      fo = RefineWithBar(bgr, kFore, Elbow(), fo, lf_, &fore_bar_used_);
    }
    if (fore_bar_used_) LearnBarWidth(bgr, kFore, Elbow(), fo, lf);
    return fo;
  }

  void UpdateFeatures() {
    std::vector<double> r;
    for (const Feature& f : feats_) {
      if (f.in_fit) r.push_back(f.label == kUpper ? f.ru : f.rf);
    }
    const double limit = std::max(o_.outlier_px, 2.5 * Median(r));
    const double band = 2 * HalfWidth();
    const cv::Point2d elbow = Elbow(), wrist = Wrist();
    std::size_t w = 0;
    for (std::size_t i = 0; i < feats_.size(); ++i) {
      Feature f = feats_[i];
      const Motion2D& m = f.label == kUpper ? tu_ : tf_;
      const cv::Point2d ref = f.label == kUpper ? f.cu : f.cf;
      const cv::Point2d predicted = m.Apply(ref);
      const double res = Dist(predicted, cv::Point2d(f.p));
      const double moved_by_model = Dist(predicted, f.seed_p);
      const double moved = Dist(cv::Point2d(f.p), f.seed_p);
      bool keep = true;
      f.outlier = res > (f.confirmed ? limit : o_.outlier_px) ? f.outlier + 1 : 0;
      if (f.confirmed) {
        keep = f.outlier <= o_.outlier_frames_drop;
      } else if (moved_by_model > o_.confirm_motion_px) {
        if (moved < 2 * o_.motion_threshold_px) {
          keep = false;  // the part moved, the feature did not: background or body behind it
        } else if (f.outlier == 0) {
          f.confirmed = ++f.agree >= kConfirmFrames;
        } else {
          f.agree = 0;
          keep = f.outlier <= kCandidateOutlierFrames;  // moves, but not with the arm: a shadow
        }
      } else if (f.still > o_.still_frames_drop) {
        // Thesis rule for features not (yet) on the arm: far from it and still, dropped.
        const double d =
            std::min(SegmentDistance(f.p, shoulder_, elbow), SegmentDistance(f.p, elbow, wrist));
        keep = d <= band;
      }
      if (keep) feats_[w++] = f;
    }
    feats_.resize(w);
  }

  // Where the elbow lies along the upper arm, from the sleeves in the current frame: once the arm
  // is bent, the forearm's sleeve is found by moving its pivot along the upper arm as well as
  // turning it, and the best pivot is where the two sleeves meet. Each frame's pivot is averaged
  // with weight sin^2(bend), as a straighter arm tells less.
  void LocateElbowOnBar(const cv::Mat& bgr, double fore_deg) {
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

  // How well this frame's evidence backs the pose. A part found on its sleeve is fully
  // supported; otherwise its share of agreeing features counts. A part with neither keeps the
  // support it had while the image around the arm did not change (an arm at rest sheds its
  // features but is still where it was); once the image there changes it has none.
  void RateSupport(const cv::Mat& gray) {
    int n[2] = {0, 0};
    for (const Feature& f : feats_) n[f.label] += f.in_fit ? 1 : 0;
    const double need = std::max(1, o_.min_part_features / 2);
    const double upper = upper_bar_used_ ? 1.0 : std::min(1.0, n[kUpper] / need);
    const double fore =
        fore_bar_used_ || reach_ < kEndOnReach ? 1.0 : std::min(1.0, n[kFore] / need);
    double support = std::min(upper, fore);
    if (support < 1 && !prev_gray_.empty() && !ArmRegionChanged(gray)) {
      support = std::max(support, support_);
    }
    support_ = support;
    gray.copyTo(prev_gray_);
  }

  // True when more than a few pixels in the band around the current pose differ clearly from
  // the previous frame.
  bool ArmRegionChanged(const cv::Mat& gray) const {
    const double hw = std::max(3.0, 1.5 * HalfWidth());
    const cv::Point2d joints[3] = {shoulder_, Elbow(), Wrist()};
    int changed = 0, total = 0;
    for (int seg = 0; seg < 2; ++seg) {
      const cv::Point2d a = joints[seg], b = joints[seg + 1];
      const double len = Dist(a, b);
      if (!(len > 1)) continue;
      const cv::Point2d u = (b - a) / len, nrm(-u.y, u.x);
      for (double t = 0; t <= len; t += 2) {
        for (double o = -hw; o <= hw; o += 2) {
          const cv::Point p(cvRound(a.x + t * u.x + o * nrm.x), cvRound(a.y + t * u.y + o * nrm.y));
          if (p.x < 0 || p.y < 0 || p.x >= gray.cols || p.y >= gray.rows) continue;
          ++total;
          changed += std::abs(int(gray.at<uchar>(p)) - int(prev_gray_.at<uchar>(p))) > kChangeGrey;
        }
      }
    }
    return total > 0 && changed > kChangedShare * total;
  }

  // Once the elbow bends, the features seeded on a straight arm tell where it is: those that
  // follow the upper arm lie before it, those that follow the forearm beyond it.
  void LearnElbow() {
    if (reach_ < 1 || lengths_measured_) return;
    if (std::abs(AngleDiff(fore_deg_, upper_deg_)) < o_.bend_for_elbow_deg) return;
    std::vector<std::pair<double, int>> samples;
    for (const Feature& f : feats_) {
      if (!f.confirmed || f.outlier > 0) continue;
      if (std::abs(f.ru - f.rf) < 1.5) continue;
      samples.emplace_back(f.along, f.ru < f.rf ? kUpper : kFore);
    }
    int n_upper = 0;
    for (const auto& s : samples) n_upper += s.second == kUpper;
    const int n_fore = static_cast<int>(samples.size()) - n_upper;
    if (n_upper < 3 || n_fore < 3) return;
    std::sort(samples.begin(), samples.end());
    // Errors of a split before sample k: forearm samples before it + upper samples after it.
    int fore_before = 0, upper_after = n_upper;
    int best_err = upper_after, best_k = 0;
    for (std::size_t k = 0; k < samples.size(); ++k) {
      if (samples[k].second == kUpper)
        --upper_after;
      else
        ++fore_before;
      const int err = fore_before + upper_after;
      if (err < best_err) {
        best_err = err;
        best_k = static_cast<int>(k) + 1;
      }
    }
    if (best_k <= 0 || best_k >= static_cast<int>(samples.size())) return;
    const double split = 0.5 * (samples[best_k - 1].first + samples[best_k].first);
    if (split <= 0.15 * arm_len_ || split >= 0.85 * arm_len_) return;
    if (!elbow_from_bar_) lu_ = std::clamp(0.9 * lu_ + 0.1 * split, 0.3 * arm_len_, 0.7 * arm_len_);
    // The forearm reaches as far as its farthest features (robustly).
    std::vector<double> reach;
    for (const Feature& f : feats_) {
      if (f.confirmed && f.label == kFore && f.outlier == 0) reach.push_back(f.cf.x);
    }
    if (reach.size() >= 5) {
      std::sort(reach.begin(), reach.end());
      const double far = reach[reach.size() * 9 / 10];
      if (far > 0.2 * arm_len_) lf_ = 0.9 * lf_ + 0.1 * far;
    }
  }

  int CountPart(int part) const {
    int n = 0;
    for (const Feature& f : feats_) n += f.label == part && (f.confirmed || f.in_fit);
    return n;
  }
  int CountConfirmed(int part) const {
    int n = 0;
    for (const Feature& f : feats_) n += f.label == part && f.confirmed;
    return n;
  }

  // Seeds corners in a band along the current estimate of the arm (both parts), reaching
  // `reach` times the estimated lengths.
  void Seed(const cv::Mat& gray, int side, double reach) {
    const int room = o_.max_corners - static_cast<int>(feats_.size());
    if (room <= 0) return;
    const cv::Point2d s = shoulder_;
    const cv::Point2d e = s + lu_ * tu_.Scale() * DirectionVector(upper_deg_);
    const cv::Point2d w = e + reach * lf_ * tf_.Scale() * DirectionVector(fore_deg_);
    cv::Mat mask(gray.size(), CV_8U, cv::Scalar(0));
    const int thickness = std::max(3, static_cast<int>(2 * HalfWidth() + 1));
    cv::line(mask, cv::Point(cvRound(s.x), cvRound(s.y)), cv::Point(cvRound(e.x), cvRound(e.y)),
             cv::Scalar(255), thickness);
    cv::line(mask, cv::Point(cvRound(e.x), cvRound(e.y)), cv::Point(cvRound(w.x), cvRound(w.y)),
             cv::Scalar(255), thickness);
    std::vector<cv::Point2f> existing;
    existing.reserve(feats_.size());
    for (const Feature& f : feats_) existing.push_back(f.p);
    const std::vector<cv::Point2f> corners = DetectCorners(gray, mask, existing, room, o_);
    for (const cv::Point2f& c : corners) {
      Feature f;
      f.p = f.prev = c;
      f.seed_p = c;
      f.seed_upper = upper_deg_;
      f.seed_fore = fore_deg_;
      f.side = side;
      const bool upper = SegmentDistance(c, s, e) <= SegmentDistance(c, e, w);
      f.along = upper ? ToPartFrame(cv::Point2d(c) - s, upper_deg_).x
                      : lu_ + ToPartFrame(cv::Point2d(c) - e, fore_deg_).x;
      f.label = f.along < lu_ ? kUpper : kFore;
      feats_.push_back(f);
    }
  }

  TrackerPose MakePose() const {
    if (side_ < 0) return MakeTrackerPose(upper_deg_, fore_deg_, false, {}, {}, {}, {}, {}, {});
    std::vector<cv::Point2f> upper, fore;
    for (const Feature& f : feats_) {
      if (!(f.confirmed || f.in_fit)) continue;
      (f.label == kUpper ? upper : fore).push_back(f.p);
    }
    const std::string note = "anchored: " + std::to_string(upper.size()) + " upper, " +
                             std::to_string(fore.size()) + " forearm features";
    TrackerPose pose = MakeTrackerPose(upper_deg_, fore_deg_, true, shoulder_, Elbow(), Wrist(),
                                       std::move(upper), std::move(fore), note);
    pose.support = support_;
    return pose;
  }

  static constexpr double kMinLeverPx = 4;
  static constexpr int kConfirmFrames = 3;            // agreeing frames before a feature is used
  static constexpr int kCandidateOutlierFrames = 15;  // disagreeing frames before it is dropped

  LkOptions o_;
  PyramidFlow flow_;
  cv::Size size_;
  std::vector<cv::Point2d> shoulders_;
  int side_ = -1;
  cv::Point2d shoulder_;
  double head_limit_y_ = -1;
  double arm_len_ = 0, lu_ = 0, lf_ = 0;
  bool lengths_measured_ = false;  // lu_ and lf_ from clicked joints: not re-learnt
  double support_ = 1;             // RateSupport(): the start pose is fully supported
  cv::Mat prev_gray_;
  static constexpr int kChangeGrey = 25;         // a clear change, well above sensor noise
  static constexpr double kChangedShare = 0.05;  // of the band's pixels
  double upper_deg_ = -90, fore_deg_ = -90;
  Motion2D tu_, tf_;
  std::vector<Feature> feats_;
  std::vector<ArmBar> upper_bar_, fore_bar_;      // per shoulder candidate
  std::vector<cv::Vec2d> bar_bias_;               // per shoulder candidate: upper, fore (degrees)
  std::vector<double> bar_widths_[2];             // recent half-width readings, per part
  std::vector<bool> sleeve_measured_;             // per shoulder candidate: arm_len_ read at start
  double reach_ = 1;                              // projected / true arm length (UpdateReach)
  static constexpr double kStraightStartDeg = 5;  // bent less: straight enough to measure reach
  static constexpr double kShortReach = 0.85;     // shorter than this: turned out of the picture
  static constexpr double kStraightDeg = 15;  // a shortened arm found bent more is not shortened
  static constexpr double kEndOnReach = 0.5;  // shorter: the forearm is taken in line, and the
                                              // upper arm searched over this much of it
  static constexpr double kFoldedDeg = 90;    // unless folded back this far (an end-on artefact)
  static constexpr double kMinReach = 0.2;
  static constexpr double kSleeveBesideEnd = 0.2;  // more sleeve past the end: a bend
  static constexpr double kClearEnd = 0.15;        // past a real end, at most this share is sleeve
  std::vector<cv::Vec2d> start_half_width_;        // per shoulder candidate: as read at the start
  BarAxis axis_[2];                                // the sleeves' axes found in this frame
  static constexpr std::size_t kWidthReadings = 15;
  static constexpr std::size_t kMinWidthReadings = 3;
  static constexpr double kBiasSearchDeg = 10;  // calibration search around the known pose
  static constexpr double kBiasFadeDeg = 20;    // the correction fades out over this turn
  std::vector<cv::Vec3d> side_lengths_;         // per shoulder candidate: arm, upper, forearm
  bool upper_bar_used_ = false, fore_bar_used_ = false;
  bool refine_shoulder_ = false;
  double shoulder_reach_ = 0;  // how far the refined shoulder may be from where it started
  static constexpr double kBodyBoxShoulderReach = 0.35;  // times the arm's length
  static constexpr double kGivenShoulderReach = 0.1;
  cv::Point2d shoulder_start_;
  cv::Matx22d line_a_ = cv::Matx22d::zeros();
  cv::Vec2d line_b_ = cv::Vec2d(0, 0);
  int line_count_ = 0;
  int frame_ = 0;
  int last_seed_ = 0;
  // Elbow from the sleeves (LocateElbowOnBar).
  static constexpr int kElbowShiftPx = 8;  // pivot searched this far along the upper arm
  static constexpr int kElbowTurnDeg = 4;  // and the forearm turned this far
  // Only the forearm's sleeve near the elbow is scored there: the hand and the cuff beyond it
  // would favour a pivot that pulls the strip back.
  static constexpr double kElbowStripFraction = 0.75;
  static constexpr double kElbowPriorWeight = 5;
  double elbow_num_ = 0, elbow_den_ = 0;
  bool elbow_from_bar_ = false;
};

}  // namespace

std::unique_ptr<Tracker> CreateAnchoredTracker(const LkOptions& options) {
  return std::make_unique<AnchoredTracker>(options);
}

}  // namespace armmimic::lk
