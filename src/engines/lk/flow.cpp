#include "lk/flow.h"

#include <cmath>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace armmimic::lk {

std::vector<cv::Point2f> DetectCorners(const cv::Mat& gray, const cv::Mat& mask,
                                       const std::vector<cv::Point2f>& existing, int max_count,
                                       const LkOptions& options) {
  std::vector<cv::Point2f> corners;
  if (max_count <= 0 || gray.empty()) return corners;
  cv::Mat allowed;
  if (mask.empty()) {
    allowed = cv::Mat(gray.size(), CV_8U, cv::Scalar(255));
  } else {
    allowed = mask.clone();
  }
  const int radius = std::max(1, static_cast<int>(std::lround(options.min_distance_px)));
  for (const cv::Point2f& p : existing) {
    cv::circle(allowed, cv::Point(cvRound(p.x), cvRound(p.y)), radius, cv::Scalar(0), cv::FILLED);
  }
  // Only the allowed pixels' bounding box (plus a margin for the eigenvalue window and the 3x3
  // maximum) is searched: the strongest corner, the quality threshold and the maxima are all
  // taken over allowed pixels, so the corners are the same as over the whole image, for a
  // fraction of the work when the mask is the arm's band.
  const cv::Rect box = cv::boundingRect(allowed);
  if (box.area() == 0) return corners;
  const int margin = options.block_size + 2;
  const cv::Rect roi = (box + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin)) &
                       cv::Rect(0, 0, gray.cols, gray.rows);
  // Minimal eigenvalue (useHarrisDetector = false); the function keeps the local maxima of a
  // 3x3 dilation, drops those below quality_level * the strongest, then enforces min distance.
  cv::goodFeaturesToTrack(gray(roi), corners, max_count, options.quality_level,
                          options.min_distance_px, allowed(roi), options.block_size, false);
  for (cv::Point2f& c : corners)
    c += cv::Point2f(static_cast<float>(roi.x), static_cast<float>(roi.y));
  return corners;
}

PyramidFlow::PyramidFlow(const LkOptions& options)
    : window_(options.window_px, options.window_px),
      levels_(options.pyramid_levels),
      fb_max_px_(options.thesis_mode ? 0.0 : options.forward_backward_px),
      criteria_(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, options.max_iterations,
                options.epsilon) {}

void PyramidFlow::Build(const cv::Mat& gray, std::vector<cv::Mat>* pyramid) const {
  cv::buildOpticalFlowPyramid(gray, *pyramid, window_, levels_, true);
}

void PyramidFlow::Reset(const cv::Mat& gray) {
  prev_gray_ = gray.clone();
  Build(prev_gray_, &prev_pyramid_);
}

void PyramidFlow::Track(const cv::Mat& gray, const std::vector<cv::Point2f>& points,
                        std::vector<cv::Point2f>* tracked, std::vector<unsigned char>* found) {
  cv::Mat next = gray.clone();
  Build(next, &next_pyramid_);
  tracked->clear();
  found->clear();
  if (!points.empty() && !prev_pyramid_.empty()) {
    std::vector<float> err;
    cv::calcOpticalFlowPyrLK(prev_pyramid_, next_pyramid_, points, *tracked, *found, err, window_,
                             levels_, criteria_);
    if (fb_max_px_ > 0) {
      // Forward-backward check: a point tracked back must land where it started.
      std::vector<cv::Point2f> back = points;
      std::vector<unsigned char> back_found;
      cv::calcOpticalFlowPyrLK(next_pyramid_, prev_pyramid_, *tracked, back, back_found, err,
                               window_, levels_, criteria_, cv::OPTFLOW_USE_INITIAL_FLOW);
      for (std::size_t i = 0; i < back.size(); ++i) {
        const cv::Point2f d = back[i] - points[i];
        if (!back_found[i] || d.dot(d) > fb_max_px_ * fb_max_px_) (*found)[i] = 0;
      }
    }
    const float w = static_cast<float>(gray.cols - 1), h = static_cast<float>(gray.rows - 1);
    for (std::size_t i = 0; i < tracked->size(); ++i) {
      const cv::Point2f& p = (*tracked)[i];
      if (!(p.x >= 0 && p.y >= 0 && p.x <= w && p.y <= h)) (*found)[i] = 0;
    }
  }
  prev_gray_ = next;
  std::swap(prev_pyramid_, next_pyramid_);
}

}  // namespace armmimic::lk
