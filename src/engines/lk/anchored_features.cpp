// The anchored tracker's features: tracking and seeding them on the arm, fitting a part's
// absolute motion from their reference positions (eq. 6-16), dropping those that do not follow,
// the support they give the pose and the elbow position they tell.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "lk/anchored_tracker.h"

namespace armmimic::lk::anchored {

void AnchoredTracker::TrackFeatures(const cv::Mat& gray) {
  lk::TrackFeatures(&flow_, gray, &feats_);
  for (Feature& f : feats_) {
    const cv::Point2f d = f.p - f.prev;
    f.still = std::hypot(d.x, d.y) < o_.motion_threshold_px ? f.still + 1 : 0;
  }
}

// Reference positions of every feature for the current shoulder and upper-arm length, and its
// part: a feature belongs to the upper arm when its place along the arm (measured in the pose it
// was seeded in) lies before the elbow.
void AnchoredTracker::ComputeReferences() {
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
bool AnchoredTracker::FitPart(int part, const cv::Point2d& joint_px, double previous_deg,
                              double prior_deg, double prior_weight, bool bootstrap,
                              Motion2D* out) {
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

void AnchoredTracker::UpdateFeatures() {
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

// How well this frame's evidence backs the pose. A part found on its sleeve is fully
// supported; otherwise its share of agreeing features counts. A part with neither keeps the
// support it had while the image around the arm did not change (an arm at rest sheds its
// features but is still where it was); once the image there changes it has none.
void AnchoredTracker::RateSupport(const cv::Mat& gray) {
  int n[2] = {0, 0};
  for (const Feature& f : feats_) n[f.label] += f.in_fit ? 1 : 0;
  const double need = std::max(1, o_.min_part_features / 2);
  const double upper = upper_bar_used_ ? 1.0 : std::min(1.0, n[kUpper] / need);
  const double fore = fore_bar_used_ || reach_ < kEndOnReach ? 1.0 : std::min(1.0, n[kFore] / need);
  double support = std::min(upper, fore);
  if (support < 1 && !prev_gray_.empty() && !ArmRegionChanged(gray)) {
    support = std::max(support, support_);
  }
  support_ = support;
  gray.copyTo(prev_gray_);
}

// True when more than a few pixels in the band around the current pose differ clearly from
// the previous frame.
bool AnchoredTracker::ArmRegionChanged(const cv::Mat& gray) const {
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
void AnchoredTracker::LearnElbow() {
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

int AnchoredTracker::CountPart(int part) const {
  int n = 0;
  for (const Feature& f : feats_) n += f.label == part && (f.confirmed || f.in_fit);
  return n;
}

int AnchoredTracker::CountConfirmed(int part) const {
  int n = 0;
  for (const Feature& f : feats_) n += f.label == part && f.confirmed;
  return n;
}

// Seeds corners in a band along the current estimate of the arm (both parts), reaching
// `reach` times the estimated lengths.
void AnchoredTracker::Seed(const cv::Mat& gray, int side, double reach) {
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

}  // namespace armmimic::lk::anchored
