// Where the upper arm turns (docs/pose.md, "The shoulder's pivot"). A pose network's shoulder
// keypoint is a point on the shoulder's surface as people annotate it, not the joint the upper
// arm turns about; when the arm is raised the two are several pixels apart, and on a short upper
// arm that turns its direction by 15 degrees or more. The elbow, as the arm moves, draws a circle
// about the true pivot. ShoulderPivot fits that circle in the torso's frame (so the person may
// move and turn in the image) to the elbows of the frames seen so far, and once the fit is sure
// (a wide arc, a round circle, a pivot near the keypoint) gives the pivot in its place.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace armmimic::internal {

class ShoulderPivot {
 public:
  // The fit is used when the elbows span at least this arc about the pivot (degrees)...
  static constexpr double kMinArcDeg = 90;
  // ...lie on its circle within this share of its radius (root mean square)...
  static constexpr double kMaxSpread = 0.08;
  // ...and the pivot is within this share of the radius from the keypoint.
  static constexpr double kMaxOffset = 0.5;
  static constexpr std::size_t kMinFrames = 20;
  static constexpr std::size_t kWindow = 600;

  // Adds a frame's shoulder keypoint and elbow (pixels), with the torso from the hips' centre to
  // the shoulders' centre (pixels), and returns the shoulder to measure the upper arm from: the
  // pivot when the fit is sure, else `shoulder`. A torso shorter than a pixel adds nothing.
  cv::Point2d Add(const cv::Point2d& shoulder, const cv::Point2d& elbow, const cv::Point2d& hips,
                  const cv::Point2d& shoulders);

 private:
  // Refits the circle to elbows_; sure_ says whether it passed the three tests.
  void Fit();

  std::vector<cv::Point2d> elbows_;  // elbow - shoulder in the torso's frame, torso lengths
  cv::Point2d centre_;               // the pivot - shoulder in the torso's frame
  bool sure_ = false;
};

}  // namespace armmimic::internal
