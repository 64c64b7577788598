// The anchored tracker's start and its fit of each frame: the shoulder candidates, the side the
// first motion decides, the upper arm then the forearm from features and sleeves, and the pose
// handed to the engine. The class is declared in anchored_tracker.h.
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "lk/anchored_tracker.h"

namespace armmimic::lk::anchored {

TrackerPose AnchoredTracker::Start(const TrackerStart& start) {
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
  shoulder_reach_ = (start.shoulder_fixed ? kGivenShoulderReach : kBodyBoxShoulderReach) * arm_len_;
  line_a_ = cv::Matx22d::zeros();
  line_b_ = cv::Vec2d(0, 0);
  line_count_ = 0;
  SetPoseMotions();
  last_seed_ = 0;
  elbow_num_ = elbow_den_ = 0;
  elbow_from_bar_ = false;
  return MakePose();
}

TrackerPose AnchoredTracker::Track(const cv::Mat& gray, const cv::Mat& bgr) {
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

void AnchoredTracker::FitPose(const cv::Mat& bgr) {
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
double AnchoredTracker::FitForearm(const cv::Mat& bgr, double bend) {
  const cv::Point2d elbow = Elbow();
  const double fo_prior = Wrap180(upper_deg_ + bend);
  double fo = fo_prior;
  Motion2D tf;
  if (FitPart(kFore, elbow, fore_deg_, fo, o_.prior_weight * lf_, CountConfirmed(kFore) < 3, &tf)) {
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

TrackerPose AnchoredTracker::MakePose() const {
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

}  // namespace armmimic::lk::anchored

namespace armmimic::lk {

std::unique_ptr<Tracker> CreateAnchoredTracker(const LkOptions& options) {
  return std::make_unique<anchored::AnchoredTracker>(options);
}

}  // namespace armmimic::lk
