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
  cv::Vec3f colour;          // median BGR along the part's axis at the start
  double half_width_px = 4;  // half the part's width
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
// (stops after `max_px`).
double MeasureBarLength(const cv::Mat& bgr, const ArmBar& bar, const cv::Point2d& joint_px,
                        double deg, double max_px);

}  // namespace armmimic::lk
