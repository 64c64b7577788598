// Private: the upper marker and the bend (docs/marker.md, "Bend"), in the camera frame the lower
// part's silhouette gives (radii; x right, y up, z depth).
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "marker/cylinder.h"

namespace armmimic::internal {

struct UpperCalibration {
  double theta0 = 0;           // the upper marker's angle about the axis at zero yaw (radians)
  double pivot_height = 0;     // the pivot's height in the camera frame (radii, y up)
  double e = 0;                // pivot to each marker centre along the axes (radii)
  double k = 1;                // the marker's centroid factor (DiscCentroidFactor)
  double marker_ratio = 0.25;  // marker grey / surface grey
  int marker_height_px = 0;    // the upper marker's height in the reference
  double face_area_px = 0;     // its dark area there, facing the camera
  double support = 0;          // UpperSilhouetteSupport of the straight reference
  double darkness = 0;         // UpperMarkerDarkness of its upper marker
  double stretch_level = 0;    // grey level between the pivot and the upper marker (reference)
  // The darkest the reference's lower part is shaded (a column's mean grey, limbs aside), over
  // stretch_level: turned away from the light, the upper part may be as dark.
  double darkest_level = 0.5;
};

// Bends beyond this would fold the upper part down past the pivot's height onto the lower one.
inline constexpr double kMaxBendDeg = 120;

// The upper marker's centroid in the camera frame (radii; x right, y up, z depth) for yaw `yaw`
// and bend `bend` (radians), with the lower part at `cyl`.
cv::Vec3d UpperMarkerPoint(const CylinderView& cyl, const UpperCalibration& cal, double yaw,
                           double bend);
// ... and in the image.
cv::Point2d ProjectUpperMarker(const CylinderView& cyl, const UpperCalibration& cal, double yaw,
                               double bend);
// The pivot's image position.
cv::Point2d ProjectPivot(const CylinderView& cyl, const UpperCalibration& cal);

struct UpperMeasurement {
  bool found = false;
  bool ambiguous = false;  // a second dark spot on the joint fits as well
  double bend = 0;         // radians, counter-clockwise on screen positive
  double residual_px = 0;  // distance of the centroid from the model at that bend
  double support = 0;      // UpperSilhouetteSupport at that bend
  double quality = 0;      // UpperSpotQuality of the spot found
  cv::Point2d centre_px;
  std::vector<cv::Rect> spots;  // the dark spots along the model's curve that were weighed
  std::string note;
};

// How much a dark spot looks like the upper marker on the upper part: the upper part's silhouette
// where the spot puts it (`support`) as plain as the reference's, and the spot as dark
// (`darkness`, UpperMarkerDarkness) as the reference's marker. Of two spots, the one whose quality
// is kClearQuality higher wins; closer, neither does.
double UpperSpotQuality(const UpperCalibration& cal, double support, double darkness);
inline constexpr double kClearQuality = 0.15;

// Looks for the upper marker along the curve the model allows for `yaw` (every bend), refines
// the best dark spot's centroid and solves the bend from it. `tolerance` (relative to e) bounds
// the centroid's distance from the model.
UpperMeasurement MeasureUpperMarker(const cv::Mat& gray, const CylinderView& cyl,
                                    const UpperCalibration& cal, double yaw, double tolerance);

// How plainly the image shows the upper part's silhouette where the model puts it for `yaw` and
// `bend`: the mean grey step across its two edges at four places along it.
double UpperSilhouetteSupport(const cv::Mat& gray, const CylinderView& cyl,
                              const UpperCalibration& cal, double yaw, double bend);

// The upper marker's coverage-weighted centroid near `centre` (updated), with the surface's grey
// level at each offset across the upper part's axis (for `bend`) taken from strips beyond the
// marker along the axis. False when the window leaves the image.
bool UpperCentroid(const cv::Mat& gray, const CylinderView& cyl, const UpperCalibration& cal,
                   double yaw, double bend, cv::Point2d* centre);

// How dark a spot is against its surroundings: the mean of the 3x3 pixels at `centre` over the
// level of a ring about a marker's size round it (0 when the ring leaves the image).
double UpperMarkerDarkness(const cv::Mat& gray, cv::Point2d centre, int marker_height_px);

// The bend that puts the model's upper marker nearest to `centroid_px`.
double SolveBend(const CylinderView& cyl, const UpperCalibration& cal, double yaw,
                 cv::Point2d centroid_px, double* residual_px);

}  // namespace armmimic::internal
