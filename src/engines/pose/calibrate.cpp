// Uses of the pose network outside the pose engine: the arm's joints in one frame
// (--auto-calibrate for the tracking engines, looked at as the engine does) and the choice of arm
// over the first second.
#include <algorithm>

#include "armmimic/core/video_source.h"
#include "armmimic/engines/pose.h"
#include "common/engine_internal.h"
#include "pose/looks.h"

namespace armmimic {
namespace {

// Frames sampled over the first second to choose the arm.
constexpr int kSideSamples = 5;

Status ReadFrame(VideoSource* source, int index, Frame* frame) {
  Status st;
  if (index > 0 && source->info().kind != SourceKind::kCamera) {
    st = source->Seek(index);
    if (!st) return st;
  }
  if (!source->Read(frame, &st)) {
    if (!st) return st;
    return Status::Error(source->info().path + " has no frame " + std::to_string(index));
  }
  return Status::Ok();
}

}  // namespace

Status DetectArmJoints(const std::vector<std::string>& inputs, int frame, PoseSide side,
                       const std::string& model_dir, const PoseOptions& options, PoseArm* arm,
                       PoseSide* chosen) {
  return internal::DetectArmJointsFrom(
      [&inputs](Status* st) { return VideoSource::Open(inputs, st); }, frame, side, model_dir,
      options, arm, chosen);
}

namespace internal {

Status DetectArmJointsFrom(const SourceOpener& open, int frame, PoseSide side,
                           const std::string& model_dir, const PoseOptions& options, PoseArm* arm,
                           PoseSide* chosen) {
  Status st;
  std::unique_ptr<PoseNetwork> net = PoseNetwork::Load(model_dir, &st);
  if (!net) return st;
  std::unique_ptr<VideoSource> source = open(&st);
  if (!source) return st;
  Frame f;
  st = ReadFrame(source.get(), frame, &f);
  if (!st) return st;
  // The body look as the engine's crop tracking would take it (the whole image, then a crop
  // around what it found, where the person is seen larger), then the engine's closer looks.
  const PoseCrop whole = WholeImageCrop(f.image.size());
  PoseKeypoints k = net->Run(f.image, whole);
  const PoseCrop near = NextCrop(k, f.image.size(), options.crop_score);
  const PoseKeypoints closer = net->Run(f.image, near);
  auto best = [&](const PoseKeypoints& kp) {
    return std::max(ArmOf(kp, PoseSide::kLeft).score, ArmOf(kp, PoseSide::kRight).score);
  };
  const bool take_closer = (side == PoseSide::kAuto ? best(closer) : ArmOf(closer, side).score) >=
                           (side == PoseSide::kAuto ? best(k) : ArmOf(k, side).score);
  if (take_closer) k = closer;
  if (side == PoseSide::kAuto) {
    side = ArmOf(k, PoseSide::kLeft).score >= ArmOf(k, PoseSide::kRight).score ? PoseSide::kLeft
                                                                               : PoseSide::kRight;
  }
  const internal::PoseLooks looks =
      internal::TakeLooks(net.get(), f.image, k, take_closer ? near : whole, {side}, options);
  *arm = ArmOf(looks.Combined(), side);
  *chosen = side;
  if (arm->score < options.min_score) {
    return Status::Error("the person's " + std::string(PoseSideName(side)) +
                         " arm is not seen clearly in frame " + std::to_string(f.index) + " of " +
                         source->info().path + " (keypoint score " +
                         std::to_string(arm->score).substr(0, 4) + ", at least " +
                         std::to_string(options.min_score).substr(0, 4) +
                         " needed); choose another start frame or give the joints");
  }
  return Status::Ok();
}

Status ChoosePoseSide(const SourceOpener& open, int start, double fps, const std::string& model_dir,
                      PoseSide* side, std::string* why) {
  Status st;
  std::unique_ptr<PoseNetwork> net = PoseNetwork::Load(model_dir, &st);
  if (!net) return st;
  std::unique_ptr<VideoSource> source = open(&st);
  if (!source) return st;
  const int count = source->info().frame_count;
  const int second = std::max(1, static_cast<int>(fps > 0 ? fps + 0.5 : 1));
  double left = 0, right = 0;
  int used = 0;
  for (int i = 0; i < kSideSamples; ++i) {
    const int index = start + i * second / kSideSamples;
    if (i > 0 && index == start + (i - 1) * second / kSideSamples) continue;
    if (count >= 0 && index >= count) break;
    Frame f;
    if (!ReadFrame(source.get(), index, &f)) break;
    const PoseKeypoints k = net->Run(f.image, WholeImageCrop(f.image.size()));
    left += ArmOf(k, PoseSide::kLeft).score;
    right += ArmOf(k, PoseSide::kRight).score;
    ++used;
  }
  *side = left >= right ? PoseSide::kLeft : PoseSide::kRight;
  if (used > 0) {
    *why = std::string("arm: the person's ") + PoseSideName(*side) +
           " (better seen over the first second: mean score " +
           std::to_string(std::max(left, right) / used).substr(0, 4) + " against " +
           std::to_string(std::min(left, right) / used).substr(0, 4) + ")";
  }
  return Status::Ok();
}

}  // namespace internal
}  // namespace armmimic
