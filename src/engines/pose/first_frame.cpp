#include "pose/first_frame.h"

namespace armmimic::internal {

Status PoseArea(const EngineContext& context, cv::Rect* area) {
  if (context.frame_size.width <= 0 || context.frame_size.height <= 0) {
    return Status::Error("pose: the video has no frame size");
  }
  *area = cv::Rect(cv::Point(0, 0), context.frame_size);
  if (context.roi) *area &= *context.roi;
  return Status::Ok();
}

PoseSide BetterSeenSide(const PoseKeypoints& k, std::string* estimate) {
  const PoseSide side = ArmOf(k, PoseSide::kLeft).score >= ArmOf(k, PoseSide::kRight).score
                            ? PoseSide::kLeft
                            : PoseSide::kRight;
  *estimate = std::string("arm: the person's ") + PoseSideName(side) +
              " (the better seen in the first frame)";
  return side;
}

}  // namespace armmimic::internal
