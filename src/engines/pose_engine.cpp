// The pose-network engine: MoveNet keypoints every frame, one arm's shoulder, elbow and wrist
// turned into the angle file's directions. Crop tracking as in MoveNet's demo: the first frame
// (and any frame after the person was lost) runs on the whole image padded to a square, later
// frames on a square around the previous keypoints; when the arm's scores drop in a crop, the
// whole image is searched again at once. A row is lost when a joint's score is low or a segment
// is much shorter than its usual length (pointing at the camera): never `ok` on a guess.
#include <algorithm>
#include <cmath>

#include "armmimic/core/angle_file.h"
#include "armmimic/engines/pose.h"
#include "engine_factories.h"
#include "pose_gate.h"

namespace armmimic {
namespace {

// The smallest in-plane segment lengths, in torso lengths (anthropometric tables put the upper
// arm near 0.6 and the forearm near 0.5 of the shoulder-to-hip distance).
constexpr double kUpperFloor = 0.45;
constexpr double kForeFloor = 0.4;

double TorsoPx(const PoseKeypoints& k, double min_score) {
  for (int j : {kLeftShoulder, kRightShoulder, kLeftHip, kRightHip}) {
    if (k.score[j] < min_score) return 0;
  }
  return cv::norm((k.px[kLeftShoulder] + k.px[kRightShoulder]) * 0.5 -
                  (k.px[kLeftHip] + k.px[kRightHip]) * 0.5);
}

class PoseEngine : public Engine {
 public:
  explicit PoseEngine(const PoseOptions& options)
      : o_(options), upper_gate_(kUpperFloor), fore_gate_(kForeFloor) {}

  EngineKind kind() const override { return EngineKind::kPose; }

  Status Begin(const EngineContext& context) override {
    if (context.frame_size.width <= 0 || context.frame_size.height <= 0) {
      return Status::Error("pose: the video has no frame size");
    }
    area_ = cv::Rect(cv::Point(0, 0), context.frame_size);
    if (context.roi) area_ = *context.roi & area_;
    Status st;
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
    PoseKeypoints k = net_->Run(image, cropped ? crop_ : whole);
    if (o_.side == PoseSide::kAuto) {  // without a first-second choice: the better arm now
      o_.side = ArmOf(k, PoseSide::kLeft).score >= ArmOf(k, PoseSide::kRight).score
                    ? PoseSide::kLeft
                    : PoseSide::kRight;
      m.estimate = std::string("arm: the person's ") + PoseSideName(o_.side) +
                   " (the better seen in the first frame)";
    }
    if (cropped && ArmOf(k, o_.side).score < o_.min_score) {
      // The scores dropped inside the crop: search the whole image again.
      const PoseKeypoints again = net_->Run(image, whole);
      if (ArmOf(again, o_.side).score > ArmOf(k, o_.side).score) k = again;
    }
    crop_ = NextCrop(k, image.size(), o_.crop_score);
    tracking_ = crop_.size > 0;
    for (cv::Point2d& p : k.px) p += cv::Point2d(area_.tl());
    Fill(k, &m);
    return m;
  }

  AngleMeta Describe() const override { return {{"model", "movenet-lightning-v4"}}; }

 private:
  void Fill(const PoseKeypoints& k, ArmMeasurement* m) {
    m->pose_keypoints.assign(k.px.begin(), k.px.end());
    m->pose_scores.assign(k.score.begin(), k.score.end());
    const PoseArm arm = ArmOf(k, o_.side);
    m->confidence = std::clamp(arm.score, 0.0, 1.0);
    m->shoulder_px = arm.shoulder;
    m->elbow_px = arm.elbow;
    m->wrist_px = arm.wrist;
    if (arm.score < o_.min_score) {
      m->phase = MeasurementPhase::kLost;
      m->note = "arm not seen (score " + FormatNumber(arm.score, 2) + ")";
      return;
    }
    const double torso = TorsoPx(k, o_.crop_score);
    const double upper = cv::norm(arm.elbow - arm.shoulder);
    const double fore = cv::norm(arm.wrist - arm.elbow);
    const bool upper_ok = upper_gate_.Accept(upper, torso, o_.min_length_ratio);
    const bool fore_ok = fore_gate_.Accept(fore, torso, o_.min_length_ratio);
    if (!upper_ok || !fore_ok) {
      m->phase = MeasurementPhase::kLost;
      const auto& gate = upper_ok ? fore_gate_ : upper_gate_;
      m->note = std::string(upper_ok ? "forearm" : "upper arm") + " points at the camera (" +
                FormatNumber(upper_ok ? fore : upper, 0) + " px of a usual " +
                FormatNumber(gate.usual_px(), 0) + ")";
      return;
    }
    m->phase = MeasurementPhase::kOk;
    m->upper_deg = DirectionDeg(arm.shoulder, arm.elbow);
    m->fore_deg = DirectionDeg(arm.elbow, arm.wrist);
    m->bend_deg = Wrap180(m->fore_deg - m->upper_deg);
    m->upper_com_px = (arm.shoulder + arm.elbow) * 0.5;
    m->fore_com_px = (arm.elbow + arm.wrist) * 0.5;
    m->bent = std::abs(m->bend_deg) > 20;
  }

  PoseOptions o_;
  cv::Rect area_;
  std::unique_ptr<PoseNetwork> net_;
  bool tracking_ = false;
  PoseCrop crop_;
  internal::PoseLengthGate upper_gate_;
  internal::PoseLengthGate fore_gate_;
};

}  // namespace

namespace internal {
std::unique_ptr<Engine> CreatePoseEngine(const PoseOptions& options) {
  return std::make_unique<PoseEngine>(options);
}
}  // namespace internal

}  // namespace armmimic
