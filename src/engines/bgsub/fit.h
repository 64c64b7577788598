// Background-subtraction engine, default path: the arm as two segments of calibrated length fitted
// to per-pixel evidence; both segments may be foreshortened alike (an arm turned out of the image
// plane by a yaw: each seen at cos(yaw) of its length), and the yaw that fits best is measured.
// Every pixel the arm can reach from the shoulder gets a weight: the person where the standstill
// was not (the arm now there) counts for it, the empty room against it, the standstill's own arm
// unchanged for it, the unchanged body neither way. The upper arm is the ray from the shoulder, the
// forearm (with the hand) the ray from the elbow at the upper arm's length, and the pair with the
// most weight along both wins. Where along the arm the elbow lies differs from person to person,
// and the calibration measures only the whole reach (a straight arm shows no elbow): the upper
// arm is also tried a tenth shorter and longer (kElbowSplits), the forearm taking the rest of the
// reach, about the upper arm the calibrated lengths found. A bent arm whose elbow lies well off
// the calibrated share fits another split clearly better (by kSplitMargin), and that split is
// taken: the forearm is then measured from an elbow nearer the true one, not from a share the
// tracker's calibration makes too. Within a tenth of the share the scores hardly tell the splits
// apart, and the calibrated one stays. Private to src/engines.
#pragma once

#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "bgsub/calib.h"

namespace armmimic::bgsub {

// The weights of the window around the shoulder that the arm can reach.
class ArmEvidence {
 public:
  // `region` is the analysed region's size; the rest arm hangs from the shoulder along rest_deg.
  void Begin(const ArmCalibration& cal, const cv::Size& region, double rest_deg);
  // The window's part inside the region (region coordinates): the masks Update takes.
  const cv::Rect& rect() const { return rect_; }
  // From the person and moved masks of rect() (CV_8UC1 0/255).
  void Update(const cv::Mat& person, const cv::Mat& moved);
  const cv::Mat& weights() const { return weights_; }  // CV_8SC1, the whole window
  cv::Point origin() const { return origin_; }         // the shoulder, window coordinates
  cv::Point window_tl() const { return window_tl_; }   // window (0,0) in region coordinates

 private:
  cv::Rect rect_;
  cv::Point origin_, window_tl_;
  cv::Mat static_code_;  // CV_8UC1 of rect(): body and rest-arm bits
  cv::Mat code_, bits_;
  cv::Mat weights_;
};

// The upper arm's and the forearm's lengths when the upper arm is `split` of its calibrated
// length `upper` and the forearm takes the rest of the reach `upper` + `fore`.
struct SplitLengths {
  SplitLengths(double upper, double fore, double split)
      : upper(split * upper), fore(upper + fore - split * upper) {}
  double upper, fore;
};

struct ArmFit {
  bool found = false;
  double upper_deg = kNaN, fore_deg = kNaN;
  cv::Point2d elbow_px, wrist_px;  // window coordinates
  double upper_support = 0;        // share of the upper arm's samples with weight for the arm
  double fore_support = 0;         // the same for the forearm and hand
  double against = 0;              // share of all samples with weight against the arm
  // The flanks of a segment (lines beside it, outside its width) with weight for an arm: the
  // clearer side's share, of the worse segment. A folded arm covers one flank of each segment;
  // a mask flooded by light or texture covers both.
  double clutter = 0;
  // Both segments seen at this share of their calibrated lengths (cos of the yaw, 0..1].
  double scale = 1;
  // The upper arm at this share of its calibrated length, the forearm the rest of the reach.
  double split = 1;
};

class ArmFitter {
 public:
  // `stride` is the weights' row step; lengths in pixels. Forearms are searched within
  // `max_bend_deg` of the upper arm's direction (an elbow bends so far and no further).
  void Begin(int stride, double upper_len, double fore_len, double half_width, int max_bend_deg);
  ArmFit Fit(const cv::Mat& weights, const cv::Point& origin) const;

 private:
  struct Ray {
    std::vector<int> offsets;  // sample offsets from the ray's origin, in weights' elements
  };
  // The rays of one pair of segment lengths (the calibrated ones foreshortened by one yaw, or
  // split at another elbow).
  struct Lengths {
    double scale = 1, split = 1;  // MakeLengths'
    double upper = 0, fore = 0;
    std::vector<Ray> upper_rays, fore_rays;  // one per degree, 0..359 (DirectionVector)
    std::vector<Ray> upper_flank[2], fore_flank[2];
    // Every upper ray is the first samples of the longest upper arm's ray of its degree (the
    // same start, a shorter end): its scores are partial sums of those.
    bool upper_prefix = false;
  };
  // The segments foreshortened by `scale`, the upper arm at `split` of its calibrated length and
  // the forearm the rest of the reach.
  Lengths MakeLengths(double scale, double split = 1) const;
  // The upper arm's score at every degree (0..359) for each of lengths_.
  void ScoreUppers(const cv::Mat& weights, int from) const;
  // The best pose with the segments of `l`, whose upper scores are `up`; its score in *score.
  // With `near_deg`, only the upper arm best within kSplitNearDeg of it.
  ArmFit FitLengths(const cv::Mat& weights, const cv::Point& origin, const Lengths& l,
                    const std::vector<int>& up, int* score,
                    std::optional<int> near_deg = std::nullopt) const;
  // The yaw, to a degree, that fits `fit`'s directions and split best: its lengths and joints.
  void RefineScale(const cv::Mat& weights, const cv::Point& origin, ArmFit* fit) const;
  static Ray MakeRay(int stride, int deg, double t0, double t1, double half_width);
  static std::vector<Ray> MakeRays(int stride, double t0, double t1, double half_width);
  // Lines beside a segment on one side (+1 left of its direction, -1 right), outside its width,
  // over its middle part.
  static std::vector<Ray> MakeFlanks(int stride, double len, double half_width, int side);
  double Clutter(const cv::Mat& weights, int from, int deg,
                 const std::vector<Ray> (&flanks)[2]) const;
  int Score(const cv::Mat& weights, int from, int deg, const std::vector<Ray>& rays) const;
  void Count(const cv::Mat& weights, int from, int deg, const std::vector<Ray>& rays, int* pos,
             int* neg, int* n) const;

  // `weights` with an upper arm of `len` at `deg` cleared: the forearm is scored on what the
  // upper arm does not already explain (a forearm folded back over it would count its pixels
  // twice).
  const cv::Mat& WithoutUpper(const cv::Mat& weights, const cv::Point& origin, int deg,
                              double len) const;

  int stride_ = 0;
  int max_bend_deg_ = 0;
  double upper_len_ = 0, fore_len_ = 0, half_width_ = 0;
  mutable cv::Mat without_upper_;  // WithoutUpper's buffer: Fit's weights but for `cleared_`
  mutable cv::Rect cleared_;       // around the line WithoutUpper cleared last
  mutable cv::Point cleared_from_, cleared_to_;         // that line's ends
  mutable std::vector<std::vector<int>> upper_scores_;  // ScoreUppers' result, per lengths_
  // The calibrated lengths first, then foreshortened ones, then the other splits.
  std::vector<Lengths> lengths_;
  std::size_t longest_upper_ = 0;  // the lengths_ whose upper arm is longest
  int split_margin_ = 0;           // kSplitMargin in score
};

}  // namespace armmimic::bgsub
