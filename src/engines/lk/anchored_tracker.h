// The anchored tracker: the improvement over thesis 6.4. Every feature keeps its reference
// position in its part's own frame (origin at the shoulder or the elbow, x along the part), taken
// from the pose when the feature was seeded. Each frame the absolute motion of each part is
// re-fitted (eq. 6-16) from the reference positions to the tracked ones, so the angles are not
// sums of increments and the error does not grow with the sequence length. Features whose
// residual stays large (shadows, the body behind the arm, noise) are dropped; new ones are
// seeded on the arm along the current estimate; the elbow position is learned from which
// features follow which part once the elbow bends.
//
// The class is shared by three files: anchored_tracker.cpp (start, each frame's fit, the pose),
// anchored_features.cpp (the tracked features: seeding, fitting a part, dropping, the elbow they
// tell) and anchored_sleeves.cpp (the sleeves: learning, searching, reach, shoulder, elbow).
// Private to the lk engine.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "lk/arm_bar.h"
#include "lk/fit.h"
#include "lk/flow.h"
#include "lk/tracker.h"

namespace armmimic::lk::anchored {

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
inline cv::Point2d ToPartFrame(const cv::Point2d& d, double deg) {
  const cv::Point2d u = DirectionVector(deg);
  const cv::Point2d v(-u.y, u.x);  // image-axes normal: (sin, cos) of the CCW angle
  return {d.dot(u), d.dot(v)};
}

// The motion that puts a part's frame at `origin` with direction `deg`.
inline Motion2D PartMotion(double deg, const cv::Point2d& origin) {
  Motion2D m;
  const cv::Point2d u = DirectionVector(deg);
  m.a = u.x;
  m.b = u.y;
  m.t = origin;
  return m;
}

inline double SegmentDistance(const cv::Point2d& p, const cv::Point2d& a, const cv::Point2d& b) {
  const cv::Point2d ab = b - a;
  const double len2 = ab.dot(ab);
  double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const cv::Point2d q = a + t * ab;
  return std::hypot(p.x - q.x, p.y - q.y);
}

inline double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  return v[mid];
}

inline double Dist(const cv::Point2d& a, const cv::Point2d& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

class AnchoredTracker : public Tracker {
 public:
  explicit AnchoredTracker(const LkOptions& options) : o_(options), flow_(options) {}

  TrackerPose Start(const TrackerStart& start) override;
  TrackerPose Track(const cv::Mat& gray, const cv::Mat& bgr) override;

 private:
  // anchored_tracker.cpp: each frame's fit and the pose.
  void FitPose(const cv::Mat& bgr);
  double FitForearm(const cv::Mat& bgr, double bend);
  TrackerPose MakePose() const;

  // anchored_features.cpp: the tracked features.
  void TrackFeatures(const cv::Mat& gray);
  void ComputeReferences();
  bool FitPart(int part, const cv::Point2d& joint_px, double previous_deg, double prior_deg,
               double prior_weight, bool bootstrap, Motion2D* out);
  void UpdateFeatures();
  void RateSupport(const cv::Mat& gray);
  bool ArmRegionChanged(const cv::Mat& gray) const;
  void LearnElbow();
  int CountPart(int part) const;
  int CountConfirmed(int part) const;
  void Seed(const cv::Mat& gray, int side, double reach);

  // anchored_sleeves.cpp: the sleeves.
  void LearnBars(const cv::Mat& bgr, int side);
  double RefineWithBar(const cv::Mat& bgr, int part, const cv::Point2d& joint_px, double deg,
                       double length_px, bool* used, double range_deg = 0);
  void UpdateReach(const cv::Mat& bgr, double upper_deg, double bend_deg);
  void LearnBarWidth(const cv::Mat& bgr, int part, const cv::Point2d& joint_px, double deg,
                     double length_px);
  void CalibrateBars(const cv::Mat& bgr, int side);
  void RefineShoulder();
  void LocateElbowOnBar(const cv::Mat& bgr, double fore_deg);

  // Small helpers used by all three.
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

}  // namespace armmimic::lk::anchored
