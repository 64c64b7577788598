// Private: the steps of the marker-joint engine (docs/marker.md), as pure functions so tests
// and the benchmark can reach them through the engine only.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/core/geometry.h"
#include "armmimic/engines/marker_options.h"

namespace armmimic::internal {

// A candidate marker: one flood-fill component, or fragments of one merged.
struct MarkerBlob {
  cv::Rect box;
  int area_px = 0;
  cv::Point2d centre;      // bounding-box centre (thesis), then the refined centre
  double coverage_px = 0;  // refined: antialiasing-aware area (sum of coverage)
  double surround = 0;     // refined: background level at the centre
  double core = 0;         // refined: marker level at the centre (median image)
  bool refined = false;
};

// Per-image buffers reused from frame to frame.
struct MarkerScratch {
  cv::Mat gray, filtered, labels, tile;
  std::vector<Component> components;
};

// The single-channel image the cylinder model measures: the luma, or one colour channel alone,
// as a monochrome camera behind a colour filter would take it. Either is the surface's albedo
// times its shading, so everything the model assumes of grey holds for a channel too; a limb
// whose grey step vanishes against a wall of the same grey but another hue shows a step in the
// channel that tells the two hues apart (docs/marker.md, calibration step 7).
enum class MarkerChannel { kLuma, kBlue, kGreen, kRed };
void MonoImage(const cv::Mat& bgr, MarkerChannel channel, cv::Mat* out);
const char* ChannelName(MarkerChannel channel);

// The thesis' median filter (4.2.1), computed only where it can matter: a pixel whose window
// holds no value <= `high` has a median above `high` and gets 255, which thresholds the same.
void MedianWhereDark(const cv::Mat& gray, int ksize, int high, cv::Mat* out, cv::Mat* band);

// Thesis 4.2.1: the grey image and its median filter, into scratch->gray and ->filtered (what
// FindMarkerCandidates starts from, and RefineMarker measures in).
void MarkerImages(const cv::Mat& bgr, const MarkerOptions& options, MarkerScratch* scratch);

// Thesis 4.2.1-4.2.4: grey, median filter, flood-fill components in [low, high], fragments of
// one marker merged, then the area / aspect / fill heuristics (areas scaled to the image).
// Survivors are sorted by area, largest first.
std::vector<MarkerBlob> FindMarkerCandidates(const cv::Mat& bgr, const MarkerOptions& options,
                                             MarkerScratch* scratch);

// Sub-pixel centre and coverage area of a blob: a plane is fitted to the ring around it (the
// surface's shading), and every pixel of the window counts by how dark it is between the
// surround and the marker level. `core_ratio` is marker / surround level learnt from the
// reference (<= 0: take the darkest median-filtered value in the blob). False when the blob
// touches the image border (a window the border cuts is kept) or has no contrast (the blob keeps
// its bounding-box centre).
// `min_height`: the window spans at least this many rows (the reference marker's height).
bool RefineMarker(const cv::Mat& gray, const cv::Mat& filtered, double core_ratio, int min_height,
                  MarkerBlob* blob);

// The three markers, once chosen: upper, then the lower pair left to right.
struct MarkerTriple {
  MarkerBlob upper, left, right;
};

// The thesis path's calibration from the reference (4.3.1): N and e.
struct MarkerReference {
  double n_px = 0;  // N: lower markers' horizontal distance at zero yaw
  double e_px = 0;  // pivot distance: half the upper-to-lower-midpoint height
  MarkerTriple markers;
};

// The reference's markers: the most symmetric triple (two side by side, one centred above).
// In thesis mode: the three largest, the top-most as upper.
// `filtered` is the median image: the stretches between the markers must look like the joint's
// surface (even), not background.
bool ChooseReferenceTriple(const std::vector<MarkerBlob>& blobs, const cv::Mat& filtered,
                           bool thesis_mode, MarkerTriple* out);
// The `limit` most symmetric triples, best first (the cylinder model calibrates from the first
// one it can measure).
std::vector<MarkerTriple> RankReferenceTriples(const std::vector<MarkerBlob>& blobs,
                                               const cv::Mat& filtered, int limit);
// Thesis 4.2.5: the three largest survivors, the top-most as upper.
bool ThreeLargest(const std::vector<MarkerBlob>& blobs, MarkerTriple* out);

// The joint's surface along a stretch: the mean level of `image` between `a` and `b` (their
// ends left out) and the share of samples more than 15 % off a straight ramp.
struct SurfaceStretch {
  double level = 0;
  double uneven = 1;
};
SurfaceStretch SampleStretch(const cv::Mat& image, cv::Point2d a, cv::Point2d b);

// Eqs. 4-1..4-5 (the thesis path); see docs/marker.md.
struct MarkerAngles {
  double yaw_deg = 0;   // acos(n / N), >= 0
  double bend_deg = 0;  // CCW on screen positive, 0 = straight
  cv::Point2d pivot_px;
};
MarkerAngles ComputeThesisAngles(const MarkerTriple& t, const MarkerReference& ref);

}  // namespace armmimic::internal
