// The straight horizontal arm of the arm-length image (thesis 5.2.3), measured column by column
// once its region is found: shared by bgsub's calibration and the standstill calibration of the
// arm engines (common/standstill_calibration.h), which find the region each their own way.
#pragma once

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"

namespace armmimic {

// The standing body's box takes, beside its largest region, the sizeable regions above and below
// it, sharing some of its columns (legs that differ little from the floor, cut off from the
// torso where thin lines are taken out): true when `part` is one of those for `torso`.
bool InTheBodysColumns(const cv::Rect& torso, const cv::Rect& part);

// A standing person's shoulders are in the upper half of the body (at about four fifths of its
// height): a region centred lower in the body's box is no arm held out from the shoulder (the
// floor or the legs, where the images differ by their compression or light).
bool CentredHighEnoughForAShoulder(const cv::Rect& region, const cv::Rect& body_box);

// The rows of `box` that hold the horizontal arm in `arm` (CV_8UC1 0/255): around the fullest
// row, those at least 0.3 as full (what hangs off it, a strip of the torso's side, is left out).
cv::Rect HorizontalBand(const cv::Mat& arm, const cv::Rect& box);

struct StraightArmColumns {
  bool ok = false;  // false with fewer than four columns: too small to measure
  int inner_x = 0;  // the column nearest the body (the first with the arm, seen from it)
  int outer_x = 0;  // the fingertip's column
  // The arm's thickness: the 0.8 quantile of its columns' heights (a part hidden in front of
  // something of its own colour shows thinner, never thicker).
  double thick_px = kNaN;
  // The axis row: the median middle of the columns at least 0.75 of that thick.
  double axis_y = kNaN;
};

// The columns of `arm` within `band`; `side` +1 when the arm points to the image's right of the
// body, -1 to its left.
StraightArmColumns MeasureStraightArm(const cv::Mat& arm, const cv::Rect& band, int side);

// The straight arm's outer end where a fixed difference threshold lost it early: an arm held out
// over a wall of nearly its own colour differs from the room there by less than the threshold,
// though by more than the noise. Outwards from `cols`.outer_x, a column is the arm's while the
// arm-length image's middle rows of the arm there are nearer the arm's own colour (each row's
// mean over the last columns found) than the standstill's same pixels, relit by the light's
// change between the two images (each channel's median ratio just above and below the arm).
// Three columns in a row that are not end it. Both images CV_8UC3 of one size; returns the
// outer end's column (cols.outer_x when nothing continues the arm).
int ContinueStraightArm(const cv::Mat& arm_length, const cv::Mat& standstill,
                        const StraightArmColumns& cols, int side);

}  // namespace armmimic
