// Background-subtraction engine, step 2 (thesis 5.2.5-5.2.7): from the arm's mask to the arm's
// segments. Contour, hull, deepest convexity defect (elbow), the 30 % straight/bent rule, the
// split through the elbow, the moment orientation of each part and the segment directions.
// All coordinates are those of the mask (the engine adds the ROI offset). Private to src/engines.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/core/geometry.h"
#include "armmimic/engines/bgsub_options.h"

namespace armmimic::bgsub {

// Moments of a set of pixels, accumulated one by one.
class MomentAccumulator {
 public:
  void Add(int x, int y) {
    ++n_;
    sx_ += x;
    sy_ += y;
    sxx_ += static_cast<double>(x) * x;
    syy_ += static_cast<double>(y) * y;
    sxy_ += static_cast<double>(x) * y;
  }
  double count() const { return n_; }
  RegionMoments Moments() const;

 private:
  double n_ = 0, sx_ = 0, sy_ = 0, sxx_ = 0, syy_ = 0, sxy_ = 0;
};

struct ArmGeometry {
  bool found = false;
  std::string note;  // why not found, or which rule decided
  std::vector<cv::Point> contour;
  std::vector<cv::Point> hull;
  RegionMoments whole;
  SemiAxes axes;               // of the whole arm region
  double axis_deg = 0;         // orientation of the whole region, (-90, 90]
  double defect_depth_px = 0;  // deepest convexity defect (0 when none)
  bool bent = false;
  cv::Point2d elbow_px;
  cv::Point2d wrist_px;
  cv::Point2d upper_com_px;
  cv::Point2d fore_com_px;
  double upper_deg = 0;  // shoulder -> elbow
  double fore_deg = 0;   // elbow -> wrist
  double reach_px = 0;   // farthest arm pixel from the shoulder along the arm's axis
};

// Analyses the arm region `mask` (CV_8UC1, 0/255, one region inside `box`): the thesis' 30 %
// rule decides straight or bent. Straight arms get one direction for both segments.
ArmGeometry AnalyzeArm(const cv::Mat& mask, const cv::Rect& box, const cv::Point2d& shoulder_px,
                       const BgsubOptions& options);

}  // namespace armmimic::bgsub
