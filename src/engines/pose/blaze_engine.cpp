// The pose engine with BlazePose (--network blazepose): BlazePose's landmark network every frame
// in a crop placed by the previous frame's auxiliary landmarks, smoothed (MediaPipe's tracking).
// The first frame, and any frame after the person was lost, places the crop from MoveNet's
// keypoints on the whole image and refines it once with BlazePose's own auxiliary landmarks.
// pose/blaze_gate.h decides each row; with side both, each arm's from the same landmarks.
#include "armmimic/engines/pose.h"
#include "common/engine_internal.h"
#include "pose/arms.h"
#include "pose/blaze_gate.h"
#include "pose/blazepose.h"
#include "pose/first_frame.h"
#include "pose/movenet_track.h"
#include "pose/one_euro.h"

namespace armmimic {
namespace {

class BlazePoseEngine : public Engine {
 public:
  explicit BlazePoseEngine(const PoseOptions& options)
      : o_(options),
        sides_(internal::FollowedSides(options.side)),
        gates_(sides_.size(), internal::BlazeArmGate(options)) {}

  EngineKind kind() const override { return EngineKind::kPose; }

  Status Begin(const EngineContext& context) override {
    Status st = internal::PoseArea(context, &area_);
    if (!st) return st;
    blaze_ = internal::BlazePoseNetwork::Load(context.model_dir, &st);
    if (!blaze_) return st;
    movenet_ = PoseNetwork::Load(context.model_dir, &st);
    if (!movenet_) return st;
    movenet_track_ = std::make_unique<internal::MoveNetTracker>(movenet_.get(), o_);
    tracking_ = false;
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    ArmMeasurement m;
    m.frame = frame.index;
    m.time_s = frame.time_s;
    const cv::Mat image = frame.image(area_);
    if (!tracking_ && !Seed(image)) {
      m.note = "no person seen to place the crop";
      return internal::JoinArms(std::vector<ArmMeasurement>(sides_.size(), m));
    }
    internal::BlazeLandmarks b = blaze_->Run(image, crop_);
    tracking_ = b.poseflag >= internal::kMinPoseFlag;
    if (tracking_) {
      crop_ = internal::CropFromAuxiliary(SmoothAuxiliary(b.px[internal::kBlazeCentre], 0, frame),
                                          SmoothAuxiliary(b.px[internal::kBlazeTop], 2, frame));
    } else {
      for (internal::OneEuroFilter& f : auxiliary_) f.Reset();
    }
    if (sides_.front() == PoseSide::kAuto) {
      sides_.front() = internal::BetterSeenSide(internal::AsMoveNetKeypoints(b), &m.estimate);
    }
    movenet_track_->BodyLook(image, sides_);
    internal::PoseLooks movenet = movenet_track_->Looks(image, sides_);
    const cv::Point2d offset(area_.tl());
    for (cv::Point2d& p : b.px) p += offset;
    movenet.Shift(offset);
    return internal::DecideArms(gates_, sides_, m, b, movenet, frame.image.size());
  }

  AngleMeta Describe() const override { return {{"model", internal::kBlazePoseModelName}}; }

 private:
  // An auxiliary landmark smoothed as MediaPipe smooths them before placing the next crop: a
  // cut-off of 0.01 Hz for a still point that rises by 10 Hz per crop size per second of speed.
  cv::Point2d SmoothAuxiliary(const cv::Point2d& p, int first_filter, const Frame& frame) {
    const double per_size = 1 / crop_.size;
    return {auxiliary_[first_filter].Apply(frame.time_s, p.x, per_size),
            auxiliary_[first_filter + 1].Apply(frame.time_s, p.y, per_size)};
  }

  // The first crop (SeedCrop). False when nobody is seen.
  bool Seed(const cv::Mat& image) {
    return internal::SeedCrop(movenet_.get(), blaze_.get(), image, o_.crop_score, &crop_);
  }

  PoseOptions o_;
  std::vector<PoseSide> sides_;                // the arms followed (pose/arms.h)
  std::vector<internal::BlazeArmGate> gates_;  // one per side
  cv::Rect area_;
  std::unique_ptr<internal::BlazePoseNetwork> blaze_;
  std::unique_ptr<PoseNetwork> movenet_;
  std::unique_ptr<internal::MoveNetTracker> movenet_track_;  // the second opinion's looks
  bool tracking_ = false;
  internal::BlazeCrop crop_;
  // x and y of the centre, then of the top (SmoothAuxiliary).
  std::vector<internal::OneEuroFilter> auxiliary_ =
      std::vector<internal::OneEuroFilter>(4, internal::OneEuroFilter(0.01, 10, 1));
};

}  // namespace

namespace internal {
std::unique_ptr<Engine> CreateBlazePoseEngine(const PoseOptions& options) {
  return std::make_unique<BlazePoseEngine>(options);
}
}  // namespace internal

}  // namespace armmimic
