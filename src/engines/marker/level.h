// Private: a camera tilted up or down, levelled (docs/marker.md, "A tilted camera"). The joint's
// model assumes a level camera: the lower part's limbs are image columns. A camera pitched by p
// makes every vertical lean towards a vanishing point f / tan(p) above or below the principal
// point, so the two limbs lean apart in proportion to their distance. The reference's limb fits
// give the pitch; the reference and every view are then resampled as a level camera at the same
// place would see them.
#pragma once

#include <opencv2/core.hpp>

#include "marker/cylinder.h"
#include "marker/lower.h"

namespace armmimic::internal {

// The camera's pitch (radians, positive: the verticals meet below the image) from the two limbs
// as fitted in the reference (LowerCalibration::limb_x, limb_lean); nan when a limb did not fit.
double LevelPitch(const LowerCalibration& cal, const MarkerCamera& camera);

class LevelWarp {
 public:
  LevelWarp() = default;
  // Resampling of `size` images taken by `camera` pitched by `pitch` (radians).
  LevelWarp(const MarkerCamera& camera, cv::Size size, double pitch);

  bool active() const { return !map1_.empty(); }
  double pitch() const { return pitch_; }
  cv::Size level_size() const { return level_size_; }
  // The level camera: the same focal length, its principal point where the levelled rows put it.
  const MarkerCamera& camera() const { return camera_; }
  // The level camera's image of `image` (any type OpenCV remaps): bicubic (kSharp) for the
  // reference, whose limbs are fitted to a fraction of a pixel once; bilinear, three times
  // faster, for the views.
  enum class Resampling { kFast, kSharp };
  void Apply(const cv::Mat& image, cv::Mat* level, Resampling resampling = Resampling::kFast) const;
  // A point, or a box (the bounds of its corners), of the level image in the original one, and
  // back.
  cv::Point2d ToOriginal(cv::Point2d p) const;
  cv::Rect ToOriginal(const cv::Rect& r) const;
  cv::Point2d ToLevel(cv::Point2d p) const;
  cv::Rect ToLevel(const cv::Rect& r) const;

 private:
  double pitch_ = 0;
  cv::Size level_size_;
  MarkerCamera camera_;
  cv::Matx33d to_original_ = cv::Matx33d::eye(), to_level_ = cv::Matx33d::eye();
  cv::Mat map1_, map2_;
};

}  // namespace armmimic::internal
