// Corner detection and pyramidal LK tracking for the LK engine (thesis 6.2): Shi-Tomasi
// minimal-eigenvalue corners with 3x3 non-maximum suppression, a quality threshold and a
// minimum distance (cv::goodFeaturesToTrack), and cv::calcOpticalFlowPyrLK on pyramids that are
// built once per frame and reused as the previous pyramid of the next frame.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/engines/lk_options.h"

namespace armmimic::lk {

// Corners of `gray` inside `mask` (CV_8U, non-zero = allowed; empty = everywhere), at most
// `max_count`, at least options.min_distance_px away from each other and from `existing`.
std::vector<cv::Point2f> DetectCorners(const cv::Mat& gray, const cv::Mat& mask,
                                       const std::vector<cv::Point2f>& existing, int max_count,
                                       const LkOptions& options);

class PyramidFlow {
 public:
  explicit PyramidFlow(const LkOptions& options);
  // Makes `gray` the previous frame.
  void Reset(const cv::Mat& gray);
  // Tracks `points` from the previous frame into `gray`, which then becomes the previous frame.
  // `found[i]` is false when LK lost point i or it left the image.
  void Track(const cv::Mat& gray, const std::vector<cv::Point2f>& points,
             std::vector<cv::Point2f>* tracked, std::vector<unsigned char>* found);
  const cv::Mat& previous() const { return prev_gray_; }

 private:
  void Build(const cv::Mat& gray, std::vector<cv::Mat>* pyramid) const;
  cv::Size window_;
  int levels_;
  double fb_max_px_;
  cv::TermCriteria criteria_;
  cv::Mat prev_gray_;
  std::vector<cv::Mat> prev_pyramid_;
  std::vector<cv::Mat> next_pyramid_;
};

// Tracks every feature of `feats` from the previous frame into `gray` with `flow`, in place and in
// order: a feature LK lost is dropped; the others keep their last position in `prev` and move `p`
// to where they were tracked. `F` has cv::Point2f members `p` and `prev`.
template <class F>
void TrackFeatures(PyramidFlow* flow, const cv::Mat& gray, std::vector<F>* feats) {
  std::vector<cv::Point2f> pts, next;
  std::vector<unsigned char> found;
  pts.reserve(feats->size());
  for (const F& f : *feats) pts.push_back(f.p);
  flow->Track(gray, pts, &next, &found);
  std::size_t w = 0;
  for (std::size_t i = 0; i < feats->size(); ++i) {
    if (!found[i]) continue;
    F& f = (*feats)[i];
    f.prev = f.p;
    f.p = next[i];
    if (w != i) (*feats)[w] = f;
    ++w;
  }
  feats->resize(w);
}

}  // namespace armmimic::lk
