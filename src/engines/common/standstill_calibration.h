// The arm's joints in the standstill from the thesis protocol's three images, with no clicks
// (docs/accuracy.md, "Calibrating from the standstill"): the empty room, the standstill's mean
// (the arm hanging) and the arm-length image (the same arm straight and horizontal).
//  - the standing body: where the standstill differs from the empty room;
//  - the straight arm: the largest region of the arm-length image that differs from both and
//    lies outside the standing body; its side of the body is the moving arm's side, its
//    thickness the arm's width, its axis row the shoulder's height and its outer end the
//    fingertip;
//  - the shoulder: one arm radius inside the hanging arm's outer edge, below the straight arm's
//    inner end;
//  - the hanging arm's direction: a line through its axis (its outer edge one radius in) down
//    the standstill;
//  - the wrist: along that direction at the shoulder-to-wrist share of the shoulder-to-fingertip
//    reach (anthropometric segment proportions: upper arm 0.186, forearm 0.146 and hand 0.108 of
//    body height), the elbow at `upper_fraction` of the shoulder-to-wrist length.
// Every estimate is written to describe() for the log. Shared by the arm engines.
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/engines/lk_options.h"

namespace armmimic {

struct StandstillCalibration {
  bool ok = false;
  std::string note;  // why not, when !ok
  int side = 0;      // the moving arm on the image's right +1, left -1
  cv::Point2d shoulder{kNaN, kNaN}, elbow{kNaN, kNaN}, wrist{kNaN, kNaN};  // region pixels
  double reach_px = kNaN;       // shoulder to fingertip, the straight arm
  double half_width_px = kNaN;  // half the straight arm's thickness
  double hanging_deg = kNaN;    // the hanging arm's direction in the standstill
  int hanging_rows = 0;         // rows its direction was fitted on (0: straight down assumed)
  // One line for the log: every estimate above, in full-image pixels (`offset` is the region's
  // top-left corner).
  std::string Describe(const cv::Point2d& offset) const;
};

// The images are CV_8UC3 of one size (the analysed region). `threshold`: the largest channel
// difference that still counts as the same pixel. `side`: +1 or -1 when the operator named it,
// 0 to take it from the arm-length image. `upper_fraction`: upper arm / shoulder to wrist.
StandstillCalibration CalibrateFromStandstill(const cv::Mat& background, const cv::Mat& standstill,
                                              const cv::Mat& arm_length, int threshold, int side,
                                              double upper_fraction);

// The same with the lk engine's settings (lk.body_threshold, lk.side, lk.upper_fraction): what
// the lk and hybrid runs calibrate from, and what the shells show ahead of a run.
StandstillCalibration CalibrateFromStandstill(const cv::Mat& background, const cv::Mat& standstill,
                                              const cv::Mat& arm_length, const LkOptions& lk);

}  // namespace armmimic
