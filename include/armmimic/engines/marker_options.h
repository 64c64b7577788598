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
  // true: the thesis path only (the three largest survivors, bounding-box centres, no geometry
  // check, no correction for the markers' depth on the cylinder).
  bool thesis_mode = false;
  // Beyond the thesis: a view is lost when the more turned lower marker faces the camera at more
  // than this angle (alpha + yaw, alpha measured in the reference): it is nearly edge-on
  // (thesis: hidden past about 35 degrees of yaw). 70 loses the views past about 30 degrees.
  double max_marker_turn_deg = 70;
  // ... or when it shows less than this share of its full-face area.
  double min_foreshortening = 0.2;
  // Geometry check: how far (relative to e) the upper marker may be from where the lower pair
  // puts it, and the accepted range of n / N.
  double geometry_tolerance = 0.15;
  // A view is lost when the yaw from the lower markers' areas and from their distance differ
  // by more than this (a blob standing in for a hidden marker).
  double max_yaw_disagreement_deg = 10;
  // ... or when the pair's area is off the model's 2 cos(alpha) cos(yaw) faces by more than
  // this share.
  double max_area_misfit = 0.2;
  // A view is lost when a second triple's misfit is within this margin of the best one's.
  double ambiguity_margin = 0.05;
  double min_width_ratio = 0.6;
  double max_width_ratio = 1.1;
  Status Check() const;  // messages name the flag (--low, --high, ...)
};

}  // namespace armmimic
