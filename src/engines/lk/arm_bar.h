// The arm as a bar of its own colour (an improvement over thesis 6.4, no background needed):
// at the known starting posture the sleeve's colour is read along each part; in later frames the
// part's direction about its joint is searched for the angle whose axis strip has that colour
// while the strips on both sides do not. This absolute measurement in the current frame anchors
// the LK estimate, so its error does not grow with the sequence length.
#pragma once

#include <opencv2/core.hpp>

namespace armmimic::lk {

struct ArmBar {
  bool valid = false;
  cv::Vec3f colour;             // median BGR along the part's axis at the start
  double half_width_px = 4;     // half the part's width
  bool width_measured = false;  // half_width_px was measured with the sleeve clear on both sides
};

// Reads the colour along the axis from `joint_px` in direction `deg` over [0.2, 0.8] x length.
// Also measures the half-width where the colour stops on the narrower side (the other side may be
// the body in the same cloth).
ArmBar LearnArmBar(const cv::Mat& bgr, const cv::Point2d& joint_px, double deg, double length_px,
                   double max_half_width_px);

// How bar-like the strip from `joint_px` along `deg` is: colour likeness on the axis minus that on
// the two flanks, in [-1, 1].
double ArmBarScore(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px, double deg,
                   double length_px);

struct BarSearch {
  bool found = false;
  double deg = 0;    // best direction (parabolic refinement between 1-degree steps)
  double score = 0;  // its score
};

// Searches directions within `range_deg` of `predicted_deg`, skipping those within
// `avoid_half_deg` of `avoid_deg` (e.g. the forearm folded back onto the upper arm's sleeve).
BarSearch SearchArmBar(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px,
                       double predicted_deg, double length_px, double range_deg, double min_score,
                       double avoid_deg = 0, double avoid_half_deg = 0);

// Length of the sleeve from `joint_px` along `deg`: where the axis stops having the bar's colour
// (stops after `max_px`). `beyond`, when given, receives the share of the axis past that end (up
// to `max_px`) that has the bar's colour again: near 0 for a sleeve that really ends there.
double MeasureBarLength(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px,
                        double deg, double max_px, double* beyond = nullptr);

// The sleeve's own axis near `deg`: across the strip from `joint_px` along `deg`, at samples over
// [0.2, 0.8] x length, the centre of the run of the bar's colour around the axis (from both ends
// where the sleeve stands clear; with `one_sided`, also from one end and the measured half-width
// where the other side runs into the same colour). The line through these centres is the sleeve's
// axis, whatever the joint's position. Not found when too few samples tell or the axis turns more
// than 10 degrees.
struct BarAxis {
  bool found = false;
  double deg = 0;        // direction of the axis
  cv::Point2d point_px;  // a point on it
};
BarAxis CentreArmBar(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px, double deg,
                     double length_px, double max_half_width_px, bool one_sided);

// Share of the pixels within `radius_px` of `centre_px` that have the bar's colour, in [0, 1].
double BarShareAround(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& centre_px,
                      double radius_px);

// Half the sleeve's width measured across the strip from `joint_px` along `deg`: at samples over
// [0.2, 0.8] x length, the run of the bar's colour around the axis, where it ends on both sides
// within `max_half_width_px` (the part stands clear of anything in the same colour). Returns the
// median half-width, or -1 when fewer than half the samples end on both sides.
double MeasureBarHalfWidth(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px,
                           double deg, double length_px, double max_half_width_px);

}  // namespace armmimic::lk
