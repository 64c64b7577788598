// Image geometry used by the engines (thesis chapter 3): moments and orientation, semi-axes,
// convex hull by Sklansky's scan, convexity defects, flood-fill connected components and
// median filtering. Pure functions over OpenCV matrices.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace armmimic {

// Spatial and central moments of a binary region (eqs. 3-1..3-8).
struct RegionMoments {
  double m00 = 0, m10 = 0, m01 = 0;     // area and first moments
  double cx = 0, cy = 0;                // centre of mass, pixels (x right, y down)
  double mu20 = 0, mu02 = 0, mu11 = 0;  // second central moments
};

// Moments of the non-zero pixels of an 8-bit single-channel mask (optionally only inside `roi`,
// which is clipped to the image). Every pixel counts 1; coordinates (and cx, cy) are full-image
// pixels even with a ROI. One pass, no allocation. An empty region gives m00 = 0 and all zeros.
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
// starting at the left-most (then top-most) point, in cv::convexHull's default order: positive
// signed area in raw (x, y), which is clockwise as seen on screen since y points down. Points
// on hull edges and repeated points are not vertices. Degenerate inputs (fewer than 3 distinct
// points, collinear points) return the distinct extreme points (0, 1 or 2).
std::vector<int> ConvexHullIndices(const std::vector<cv::Point>& points);
std::vector<cv::Point> ConvexHull(const std::vector<cv::Point>& points);

// A convexity defect: the stretch of `contour` between two consecutive hull points that lies
// inside the hull, and its deepest point.
struct ConvexityDefect {
  int start_index = 0;    // contour index of the hull point where the defect starts
  int end_index = 0;      // contour index of the hull point where it ends
  int deepest_index = 0;  // contour index of the point farthest from the hull edge
  double depth_px = 0;    // its distance to the hull edge
};
// `hull_indices` as returned by ConvexHullIndices(contour). Sorted deepest first.
std::vector<ConvexityDefect> ConvexityDefects(const std::vector<cv::Point>& contour,
                                              const std::vector<int>& hull_indices);

// One connected component found by flood fill.
struct Component {
  int label = 0;  // value in the label image (1-based)
  int area_px = 0;
  cv::Rect box;    // bounding box
  cv::Point seed;  // first pixel found (raster order)
};

// 4-connected flood-fill labelling of an 8-bit single-channel image. Scanning in raster order,
// each unlabelled pixel with value in [min_value, max_value] seeds a component, which grows over
// 4-neighbours whose value is also in [min_value, max_value] and differs from the SEED's value
// by at most `range` (relative to the seed, like cv::floodFill with FLOODFILL_FIXED_RANGE; not
// relative to each neighbour). `labels` (may be null) receives CV_32S labels (0 = background).
// Components are returned in label order.
std::vector<Component> FloodFillComponents(const cv::Mat& gray, int min_value, int max_value,
                                           int range, cv::Mat* labels);
// The same for a binary mask: every non-zero pixel is foreground, 4-connected.
std::vector<Component> MaskComponents(const cv::Mat& mask, cv::Mat* labels);

// Median filter of an 8-bit single-channel image with an odd square window (thesis Fig. 3-8);
// borders replicate. Throws std::invalid_argument for an even or non-positive ksize or a
// non-CV_8UC1 image. The second form writes into *out (reusing its buffer; out != &gray).
cv::Mat MedianFilter(const cv::Mat& gray, int ksize);
void MedianFilter(const cv::Mat& gray, int ksize, cv::Mat* out);

}  // namespace armmimic
