#include "pose/movenet_track.h"

#include <algorithm>

#include "pose/arms.h"

namespace armmimic::internal {

PoseKeypoints MoveNetTracker::BodyLook(const cv::Mat& image, const std::vector<PoseSide>& sides) {
  const PoseCrop whole = WholeImageCrop(image.size());
  const bool cropped =
      tracking_ && (crop_.x != whole.x || crop_.y != whole.y || crop_.size != whole.size);
  used_ = cropped ? crop_ : whole;
  body_ = net_->Run(image, used_);
  const bool named = std::find(sides.begin(), sides.end(), PoseSide::kAuto) == sides.end();
  if (cropped && named && WeakestArmScore(body_, sides) < o_.min_score) {
    // The scores dropped inside the crop: search the whole image again.
    const PoseKeypoints again = net_->Run(image, whole);
    if (WeakestArmScore(again, sides) > WeakestArmScore(body_, sides)) {
      body_ = again;
      used_ = whole;
    }
  }
  crop_ = NextCrop(body_, image.size(), o_.crop_score);
  tracking_ = crop_.size > 0;
  return body_;
}

PoseLooks MoveNetTracker::Looks(const cv::Mat& image, const std::vector<PoseSide>& sides) {
  return TakeLooks(net_, image, body_, used_, sides, o_);
}

}  // namespace armmimic::internal
