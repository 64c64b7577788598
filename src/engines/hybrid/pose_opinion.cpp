#include "hybrid/pose_opinion.h"

#include <cmath>
#include <limits>
#include <utility>

#include "armmimic/engines/pose.h"
#include "common/arm_gate.h"
#include "common/engine_internal.h"

namespace armmimic::internal {
namespace {

double Distance(const std::optional<cv::Point2d>& p, const cv::Point2d& q) {
  return p ? std::hypot(p->x - q.x, p->y - q.y) : std::numeric_limits<double>::infinity();
}

}  // namespace

std::unique_ptr<PoseOpinion> PoseOpinion::Start(const EngineContext& context,
                                                const PoseOptions& options, std::string* why) {
  if (!context.shoulder_px || !context.elbow_px) {
    *why = "no joints were given, so the pose network's arm cannot be told";
    return nullptr;
  }
  PoseOptions both = options;
  both.side = PoseSide::kBoth;
  std::unique_ptr<Engine> pose = CreatePoseEngine(both);
  EngineContext own = context;
  own.shoulder_px.reset();
  own.elbow_px.reset();
  own.wrist_px.reset();
  if (const Status st = pose->Begin(own); !st) {
    *why = st.message();
    return nullptr;
  }
  const cv::Point2d s = *context.shoulder_px, e = *context.elbow_px;
  return std::unique_ptr<PoseOpinion>(
      new PoseOpinion(std::move(pose), s, std::hypot(e.x - s.x, e.y - s.y)));
}

ArmMeasurement PoseOpinion::Process(const Frame& frame) {
  ArmMeasurement left = pose_->Process(frame);
  if (!left.right_arm) return left;  // cannot happen with both arms followed
  const ArmMeasurement right = *left.right_arm;
  left.right_arm.reset();
  if (!right_) {
    // The arm whose shoulder lies nearest the clicked one, and within half an upper arm of it
    // (the other shoulder is a torso's width away).
    const double dl = Distance(left.shoulder_px, shoulder_);
    const double dr = Distance(right.shoulder_px, shoulder_);
    if (std::min(dl, dr) > upper_px_ / 2) {
      LoseRow(&left, "the pose network sees no shoulder where the shoulder was clicked");
      return left;
    }
    right_ = dr < dl;
    ArmMeasurement m = *right_ ? right : left;
    m.estimate = std::string("the pose network's second opinion follows the person's ") +
                 (*right_ ? "right" : "left") + " arm, its shoulder " +
                 std::to_string(static_cast<int>(std::lround(std::min(dl, dr)))) +
                 " px from the shoulder the tracker starts from";
    return m;
  }
  return *right_ ? right : left;
}

}  // namespace armmimic::internal
