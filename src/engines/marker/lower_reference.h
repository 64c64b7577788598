// Private: the reference's lower markers measured for a given silhouette, and the ways the
// silhouette's edges are placed and checked against the markers and the rows beside them
// (docs/marker.md, "Calibration", steps 2 and 4).
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "marker/lower.h"

namespace armmimic::internal {

// Marker grey over surface grey at the two markers' centres, then the markers measured with it:
// their zero-yaw angles, angular radius and height (the silhouette in cal, scan). `surface` is
// the surface's grey level per column from image column x0. A marker the limb cuts is accepted
// when `allow_cut`. False with a message when two markers are not found.
bool MeasureReferenceMarkers(const cv::Mat& gray, const MarkerCamera& camera, int x0,
                             const std::vector<double>& surface, bool allow_cut,
                             LowerCalibration* cal, LowerScan* scan, std::string* message);

// True when the calibrated lower markers' mid-angle lies near the upper marker's angle (at zero
// yaw they flank the front); false with a message otherwise.
bool AboutTheUpper(const MarkerCamera& camera, cv::Point2d upper_px, const LowerCalibration& cal,
                   std::string* message);

// An edge no band shows (the limb as bright as the wall behind it), from the other edge and the
// reference's markers: at zero yaw the lower markers lie symmetrically about the front, where
// the upper marker is, so theta(left) + theta(right) = 2 theta(upper). Bisection over the hidden
// edge's column. NaN when no column satisfies it.
double HiddenEdge(const MarkerCamera& camera, double known, int hidden_side, cv::Point2d left_px,
                  cv::Point2d right_px, cv::Point2d upper_px);

// The silhouette's edges set to `left` and `right`, the marker ratio and angular radius reset,
// and the scan started afresh on that cylinder: ready for MeasureReferenceMarkers.
void StartAtEdges(const MarkerCamera& camera, double left, double right, LowerCalibration* cal,
                  LowerScan* scan);

// Moves the edge on side `weak` (0 left) to where the lower markers' angular radii agree best.
void EqualDiscs(const cv::Mat& gray, const MarkerCamera& camera, int x0,
                const std::vector<double>& surface, int weak, LowerCalibration* cal,
                LowerScan* scan);

// Fits each limb over `rows` (FitLimb) near the present edges; `plain` tells which side's step
// is plain. True when the silhouette is sure enough to size a single lower marker;
// `either_fitted` false when neither limb fits.
bool RefineLimbs(const cv::Mat& gray, const MarkerCamera& camera, int x0,
                 const std::vector<double>& surface, const std::vector<int>& rows, double y_ref,
                 const bool plain[2], LowerCalibration* cal, LowerScan* scan, bool* either_fitted);

// The steepest step beside a dark limb may be the far edge of the joint's own shadow on the
// wall: inside it (towards the markers) a flat dark band, and inside that the shading ramp of the
// lit surface, which ends at the limb. The ramp's end for the step at `step` on `side` (0 left,
// 1 right) of the column profile starting at `x0`, or NaN when the profile shows no such band
// between the step and the nearer lower marker's centre `marker_x`.
double ShadowedLimb(const std::vector<double>& profile, int x0, double step, int side,
                    double marker_x);

}  // namespace armmimic::internal
