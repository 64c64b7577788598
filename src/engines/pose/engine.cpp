// The pose-network engine: MoveNet keypoints every frame, one arm's shoulder, elbow and wrist
// turned into the angle file's directions. Crop tracking as in MoveNet's demo: the first frame
// (and any frame after the person was lost) runs on the whole image padded to a square, later
// frames on a square around the previous keypoints; when the arm's scores drop in a crop, the
// whole image is searched again at once. That body look is followed by a closer look at the
// upper body (pose/looks.h), which places the joints. A row is lost when a joint's score is low,
// a segment is much shorter than its usual length (pointing at the camera) or the looks disagree
// on its direction (pose/gate.h): never `ok` on a guess. With side both, the same looks give
// both arms (pose/arms.h): the crop is searched again when either arm drops in it.
#include "armmimic/engines/pose.h"
#include "common/engine_internal.h"
#include "pose/arms.h"
#include "pose/first_frame.h"
#include "pose/gate.h"
#include "pose/looks.h"

namespace armmimic {
namespace {

class PoseEngine : public Engine {
 public:
  explicit PoseEngine(const PoseOptions& options)
      : o_(options),
        sides_(internal::FollowedSides(options.side)),
        gates_(sides_.size(), internal::PoseArmGate(options)) {}

  EngineKind kind() const override { return EngineKind::kPose; }

  Status Begin(const EngineContext& context) override {
    Status st = internal::PoseArea(context, &area_);
    if (!st) return st;
    net_ = PoseNetwork::Load(context.model_dir, &st);
    if (!net_) return st;
    tracking_ = false;
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    ArmMeasurement m;
    m.frame = frame.index;
    m.time_s = frame.time_s;
    const cv::Mat image = frame.image(area_);
    const PoseCrop whole = WholeImageCrop(image.size());
    const bool cropped =
        tracking_ && (crop_.x != whole.x || crop_.y != whole.y || crop_.size != whole.size);
    PoseCrop used = cropped ? crop_ : whole;
    PoseKeypoints k = net_->Run(image, used);
    if (sides_.front() == PoseSide::kAuto) {
      sides_.front() = internal::BetterSeenSide(k, &m.estimate);
    }
    if (cropped && internal::WeakestArmScore(k, sides_) < o_.min_score) {
      // The scores dropped inside the crop: search the whole image again.
      const PoseKeypoints again = net_->Run(image, whole);
      if (internal::WeakestArmScore(again, sides_) > internal::WeakestArmScore(k, sides_)) {
        k = again;
        used = whole;
      }
    }
    crop_ = NextCrop(k, image.size(), o_.crop_score);
    tracking_ = crop_.size > 0;
    internal::PoseLooks looks = internal::TakeLooks(net_.get(), image, k, used, sides_, o_);
    looks.Shift(cv::Point2d(area_.tl()));
    return internal::DecideArms(gates_, sides_, looks, m);
  }

  AngleMeta Describe() const override { return {{"model", internal::kPoseModelName}}; }

 private:
  PoseOptions o_;
  std::vector<PoseSide> sides_;               // the arms followed (pose/arms.h)
  std::vector<internal::PoseArmGate> gates_;  // one per side
  cv::Rect area_;
  std::unique_ptr<PoseNetwork> net_;
  bool tracking_ = false;
  PoseCrop crop_;
};

}  // namespace

namespace internal {
std::unique_ptr<Engine> CreatePoseEngine(const PoseOptions& options) {
  if (options.network == PoseNetworkKind::kBlazePose) return CreateBlazePoseEngine(options);
  return std::make_unique<PoseEngine>(options);
}
}  // namespace internal

}  // namespace armmimic
