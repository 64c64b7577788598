// Private: the lower part of the marker joint in one image (docs/marker.md, "The cylinder
// model"): its silhouette, and the lower markers measured across it as angles on its surface.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "marker/cylinder.h"

namespace armmimic::internal {

// A band of rows beside the lower markers that shows only the lower part's surface: its column
// profile gives the silhouette and the shading (which on an upright cylinder depends on the
// column only). Each band sees its own background, so each keeps its own edges.
struct EdgeBand {
  std::vector<int> rows;
  double edge_px[2] = {0, 0};  // left and right silhouette edge in the reference
  // Where the steepest step of this band's profile lies in the reference (what the views track:
  // the silhouette moves with it) and how steep it is; strength 0: too faint to track.
  double peak_px[2] = {0, 0};
  double strength[2] = {0, 0};
};

// What the reference taught about the lower part; fixed for the run.
// NOLINTNEXTLINE(bugprone-reserved-identifier): __i0 is clang's own loop in the implicit copy
struct LowerCalibration {
  EdgeBand bands[2];                           // above and below the markers
  double left_edge_px = 0, right_edge_px = 0;  // the reference's silhouette
  int search_px = 3;                           // how far an edge may move from the reference's
  int band_top = 0, band_bottom = 0;           // rows the lower markers can occupy (inclusive)
  double marker_ratio = 0.25;                  // marker grey / surface grey
  double marker_height_px = 0;                 // the lower markers' height in the reference
  double delta = 0;                            // the markers' angular radius (radians)
  double theta_left0 = 0, theta_right0 = 0;    // the lower markers' angles at zero yaw
  double alpha() const { return 0.5 * (theta_right0 - theta_left0); }  // their half-spacing
  // The steeper of the two bands' steps at one limb (0 = left; 0 when neither band tracks it).
  double steepest(int side) const {
    return std::max(std::abs(bands[0].strength[side]), std::abs(bands[1].strength[side]));
  }
  double height = 0;  // the lower markers' height in the camera frame (radii, y up)
  // Whether one lower marker alone can be sized: both reference markers whole and of equal
  // angular radius (within kEqualDiscs). A single marker's yaw rests on its reference angle
  // alone, which a silhouette edge misplaced in the reference shifts by degrees (most near a
  // limb, where a cut marker lies; unequal discs show an edge misplaced); two markers' yaws
  // check each other.
  bool single_sized = true;
  // Each limb as fitted over all its rows (calibration step 2; nan where it did not fit): its
  // column at the fit's reference row and its lean (columns per row). A tilted camera makes the
  // two limbs lean apart (LevelPitch).
  double limb_x[2] = {kNaN, kNaN}, limb_lean[2] = {kNaN, kNaN};
};

// One lower marker found across the cylinder.
struct LowerMarker {
  double theta = 0;       // angle of its centre on the surface (radians)
  double sigma = 0;       // expected spread of theta (radians)
  cv::Point2d centre_px;  // its centre in the image
  double radius = 0;      // its angular radius as measured (radians; nan when cut)
  bool cut = false;       // partly beyond the limb: measured from its inner edge
  int first_col = 0, last_col = 0;
  double coverage_px = 0;  // dark area, in pixels
};

struct LowerScan {
  CylinderView cylinder;  // this image's silhouette
  double left_edge_px = 0, right_edge_px = 0;
  std::vector<LowerMarker> markers;     // left to right
  std::vector<double> column_coverage;  // marker coverage summed down each column of the band
  int first_col = 0;                    // image column of column_coverage[0]
  std::string failure;                  // set when the lower part was not found
  // Marker coverage (area in pixels) in the image columns [x0, x1], those of `skip` left out.
  double CoverageBetween(double x0, double x1, const LowerMarker* skip = nullptr) const;
};

// Per-image buffers.
struct LowerScratch {
  std::vector<double> above, below, surface;
  std::vector<float> coverage;
};

// Finds the silhouette near the reference's and measures the dark patches between the edges in
// the marker band. False (with `failure` set) when the silhouette is not there.
bool ScanLowerPart(const cv::Mat& gray, const LowerCalibration& cal, const MarkerCamera& camera,
                   LowerScan* out, LowerScratch* scratch);

// The marker band's coverage and patches, given out->left/right_edge_px and out->cylinder, and
// the surface's grey level per column (`surface`, its first entry image column x0). In
// `calibrating` mode patches are kept without the size and height checks.
void MeasureLowerMarkers(const cv::Mat& gray, const LowerCalibration& cal, int x0,
                         const std::vector<double>& surface, bool calibrating, LowerScan* out,
                         LowerScratch* scratch);

// The same measurement on the reference: finds the silhouette from scratch around the lower pair
// (`left_px`, `right_px`, the pair's blob centres; `upper_px` the upper marker's) and fills the
// bands, edges and marker angles of `cal`. False with a message naming what is missing.
bool CalibrateLowerPart(const cv::Mat& gray, const MarkerCamera& camera, cv::Point2d left_px,
                        cv::Point2d right_px, cv::Point2d upper_px, double marker_height_px,
                        LowerCalibration* cal, LowerScan* scan, std::string* message);

}  // namespace armmimic::internal
