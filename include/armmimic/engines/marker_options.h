// Options of the marker-joint engine (thesis chapter 4), with thesis defaults. Areas are given
// for a 320x240 image and scale with the image area.
#pragma once

#include "armmimic/core/status.h"

namespace armmimic {

struct MarkerOptions {
  int median_size = 5;  // median filter window (4.2.1)
  int low = 20;         // two-level threshold: marker pixels are in [low, high] (4.2.2)
  int high = 80;
  int flood_range = 10;  // flood-fill value range (+/-), relative to the seed (4.2.3)
  int min_area = 10;     // elimination heuristics (4.2.4), pixels at 320x240
  int max_area = 200;
  double min_aspect = 0.2;  // bounding-box width / height
  double max_aspect = 3.0;
  double min_fill = 0.7;  // area / bounding-box area
  // Beyond the thesis: when [low, high] does not show the reference's three markers (other
  // illumination), the window of the same width that does, nearest to [low, high], is used.
  bool auto_window = true;
  // true: the thesis path only (the three largest survivors, bounding-box centres, yaw =
  // acos(n/N), no cylinder model and no sign).
  bool thesis_mode = false;
  // The cylinder model (docs/marker.md): the camera's horizontal field of view in degrees, which
  // sets the perspective; 0 = a distant camera (parallel projection).
  double fov_deg = 60;
  // A view is read only when a lower marker faces the camera within this angle (degrees):
  // one turned further is too foreshortened to read alone.
  double max_marker_turn_deg = 74;
  // The two lower markers' yaws must agree within this many expected spreads (plus 1 degree),
  // or the view is lost.
  double agreement_sigmas = 4;
  // The bend is measured while the upper marker faces the camera within this angle (degrees).
  double max_upper_turn_deg = 60;
  // How far (relative to e) the upper marker's centroid may lie from the model's.
  double upper_tolerance = 0.06;
  Status Check() const;  // the table's ranges and an odd median; errors carry "marker.KEY"
};

}  // namespace armmimic
