#include "pose/movenet_track.h"

namespace armmimic::internal {

PoseKeypoints MoveNetTracker::BodyLook(const cv::Mat& image, PoseSide side) {
  const PoseCrop whole = WholeImageCrop(image.size());
  const bool cropped =
      tracking_ && (crop_.x != whole.x || crop_.y != whole.y || crop_.size != whole.size);
  used_ = cropped ? crop_ : whole;
  body_ = net_->Run(image, used_);
  if (cropped && side != PoseSide::kAuto && ArmOf(body_, side).score < o_.min_score) {
    // The scores dropped inside the crop: search the whole image again.
    const PoseKeypoints again = net_->Run(image, whole);
    if (ArmOf(again, side).score > ArmOf(body_, side).score) {
      body_ = again;
      used_ = whole;
    }
  }
  crop_ = NextCrop(body_, image.size(), o_.crop_score);
  tracking_ = crop_.size > 0;
  return body_;
}

PoseLooks MoveNetTracker::Looks(const cv::Mat& image, PoseSide side) {
  return TakeLooks(net_, image, body_, used_, side, o_);
}

}  // namespace armmimic::internal
