// The pose-network engine: MoveNet keypoints every frame, one arm's shoulder, elbow and wrist
// turned into the angle file's directions. MoveNet's looks at each frame (pose/movenet_track.h):
// the body look, tracked as in MoveNet's demo, then a closer look at the upper body
// (pose/looks.h), which places the joints. A row is lost when a joint's score is low,
// a segment is much shorter than its usual length (pointing at the camera) or the looks disagree
// on its direction (pose/gate.h): never `ok` on a guess. With side both, the same looks give
// both arms (pose/arms.h): the crop is searched again when either arm drops in it.
#include "armmimic/engines/pose.h"
#include "common/engine_internal.h"
#include "pose/arms.h"
#include "pose/first_frame.h"
#include "pose/gate.h"
#include "pose/looks.h"
#include "pose/movenet_track.h"

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
    track_ = std::make_unique<internal::MoveNetTracker>(net_.get(), o_);
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    ArmMeasurement m;
    m.frame = frame.index;
    m.time_s = frame.time_s;
    const cv::Mat image = frame.image(area_);
    const PoseKeypoints body = track_->BodyLook(image, sides_);
    if (sides_.front() == PoseSide::kAuto) {
      sides_.front() = internal::BetterSeenSide(body, &m.estimate);
    }
    internal::PoseLooks looks = track_->Looks(image, sides_);
    looks.Shift(cv::Point2d(area_.tl()));
    return internal::DecideArms(gates_, sides_, m, looks);
  }

  AngleMeta Describe() const override { return {{"model", internal::kPoseModelName}}; }

 private:
  PoseOptions o_;
  std::vector<PoseSide> sides_;               // the arms followed (pose/arms.h)
  std::vector<internal::PoseArmGate> gates_;  // one per side
  cv::Rect area_;
  std::unique_ptr<PoseNetwork> net_;
  std::unique_ptr<internal::MoveNetTracker> track_;
};

}  // namespace

namespace internal {
std::unique_ptr<Engine> CreatePoseEngine(const PoseOptions& options) {
  if (options.network == PoseNetworkKind::kBlazePose) return CreateBlazePoseEngine(options);
  return std::make_unique<PoseEngine>(options);
}
}  // namespace internal

}  // namespace armmimic
