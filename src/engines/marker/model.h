// Private: the marker joint's cylinder model as a whole (docs/marker.md): what the reference
// gives, and one view measured with it.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/engines/marker_options.h"
#include "marker/detect.h"
#include "marker/lower.h"
#include "marker/upper.h"

namespace armmimic::internal {

struct MarkerCalibration {
  MarkerCamera camera;
  LowerCalibration lower;
  UpperCalibration upper;
  double radius_px = 0;  // the lower part's half-width in the reference
};

// From the reference (grey), taken by `camera`, and its three markers (their centroids refined).
bool CalibrateMarkerJoint(const cv::Mat& gray, const MarkerCamera& camera,
                          const MarkerTriple& markers, MarkerCalibration* cal,
                          std::string* message);

struct MarkerViewResult {
  bool ok = false;
  std::string note;  // why lost, or how the view was read
  double yaw = 0;    // radians, signed: positive turns the joint's right side to the camera
  // The sign of `yaw` rests on evidence (docs/marker.md, "The sign"); false: only |yaw| is known.
  bool sign_known = true;
  double bend = kNaN;  // radians, CCW on screen positive; nan when the upper marker is unsure
  cv::Point2d pivot_px{kNaN, kNaN};
  cv::Point2d upper_px{kNaN, kNaN}, left_px{kNaN, kNaN}, right_px{kNaN, kNaN};
  double left_edge_px = kNaN, right_edge_px = kNaN;  // the silhouette, from the pivot row down
  double axis_x_px = kNaN;
  int bottom_row = 0;                // lowest row of the lower part used
  std::vector<cv::Rect> candidates;  // dark patches across the lower part, spots weighed above
};

struct MarkerViewScratch {
  LowerScratch lower;
  LowerScan scan;
};

MarkerViewResult MeasureMarkerView(const cv::Mat& gray, const MarkerCalibration& cal,
                                   const MarkerOptions& options, MarkerViewScratch* scratch);

}  // namespace armmimic::internal
