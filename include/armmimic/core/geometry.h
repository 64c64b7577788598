// Image geometry used by the engines (thesis chapter 3): moments and orientation, semi-axes,
// convex hull by Sklansky's scan, convexity defects, flood-fill connected components and
// median filtering. Pure functions over OpenCV matrices.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace armmimic {

// Spatial and central moments of a binary region (eqs. 3-1..3-8).
struct RegionMoments {
  double m00 = 0, m10 = 0, m01 = 0;        // area and first moments
  double cx = 0, cy = 0;                   // centre of mass, pixels (x right, y down)
  double mu20 = 0, mu02 = 0, mu11 = 0;     // second central moments
};

// Moments of the non-zero pixels of an 8-bit mask (optionally only inside `roi`).
RegionMoments ComputeMoments(const cv::Mat& mask);
RegionMoments ComputeMoments(const cv::Mat& mask, const cv::Rect& roi);

// Orientation of the axis of least inertia, by the nine sign cases of thesis Table 3-1
// (signs of mu20 - mu02 and mu11). Returned as an axis in the contract's convention:
// degrees CCW on screen from +x, in (-90, 90].
double OrientationDeg(const RegionMoments& m);

// Semi-major and semi-minor axis lengths of the equivalent ellipse (eq. 3-14), in pixels.
struct SemiAxes {
  double major = 0;
  double minor = 0;
};
SemiAxes ComputeSemiAxes(const RegionMoments& m);

// Convex hull by Sklansky's three-coins scan (section 3.6), returned as indices into `points`,
// counter-clockwise in image coordinates, starting at the left-most point. Degenerate inputs
// (fewer than 3 distinct points, collinear points) return the extreme points.
std::vector<int> ConvexHullIndices(const std::vector<cv::Point>& points);
std::vector<cv::Point> ConvexHull(const std::vector<cv::Point>& points);

// A convexity defect: the stretch of `contour` between two consecutive hull points that lies
// inside the hull, and its deepest point.
struct ConvexityDefect {
  int start_index = 0;     // contour index of the hull point where the defect starts
  int end_index = 0;       // contour index of the hull point where it ends
  int deepest_index = 0;   // contour index of the point farthest from the hull edge
  double depth_px = 0;     // its distance to the hull edge
};
// `hull_indices` as returned by ConvexHullIndices(contour). Sorted deepest first.
std::vector<ConvexityDefect> ConvexityDefects(const std::vector<cv::Point>& contour,
                                              const std::vector<int>& hull_indices);

// One connected component found by flood fill.
struct Component {
  int label = 0;           // value in the label image (1-based)
  int area_px = 0;
  cv::Rect box;            // bounding box
  cv::Point seed;          // first pixel found (raster order)
};

// 4-connected flood-fill labelling of an 8-bit single-channel image. Starting from each
// unlabelled pixel with value in [min_value, max_value], it grows over 4-neighbours whose value
// differs from the seed's by at most `range` (floating range, as cv::floodFill without
// FLOODFILL_FIXED_RANGE would be relative to neighbours; here it is relative to the seed).
// `labels` receives CV_32S labels (0 = background). Components are returned in label order.
std::vector<Component> FloodFillComponents(const cv::Mat& gray, int min_value, int max_value,
                                           int range, cv::Mat* labels);
// The same for a binary mask: every non-zero pixel is foreground, 4-connected.
std::vector<Component> MaskComponents(const cv::Mat& mask, cv::Mat* labels);

// Median filter with an odd square window (thesis Fig. 3-8); borders replicate.
cv::Mat MedianFilter(const cv::Mat& gray, int ksize);

}  // namespace armmimic
