// The LK features as one cue of the model tracker (lk/model_tracker.cpp): corners on the upper
// arm, on the forearm and on the body around the shoulder, tracked frame to frame (thesis 6.2).
// Each arm feature tells how far its part turned about its joint since the last frame; the body's
// features tell how far the shoulder moved (a swaying body). The medians of these are the
// features' prediction of the new pose, which the two-segment model then measures around.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/engines/lk_options.h"
#include "common/arm_model_fit.h"
#include "lk/flow.h"

namespace armmimic::lk {

// What the features say about the motion since the last frame. Turns are nan when no feature
// of that part tells.
struct FlowCue {
  cv::Point2d shoulder_shift{0, 0};
  int body_count = 0;
  double upper_turn_deg = kNaN, fore_turn_deg = kNaN;  // fore: the forearm's direction change
  int upper_count = 0, fore_count = 0;
};

class ArmFlow {
 public:
  explicit ArmFlow(const LkOptions& options) : o_(options), flow_(options) {}
  void Reset(const cv::Mat& gray);
  // Tracks the features into `gray`; `pose` is the arm's pose in the previous frame.
  FlowCue Track(const cv::Mat& gray, const arm::ArmPose& pose, const arm::ArmShape& shape);
  // Keeps the arm's features that lie on `pose`'s segments (relabelled by the nearer one) and
  // the body's features off the arm; then, every few frames or when a part runs short, seeds new
  // corners in `gray` along the arm and on the body around the shoulder.
  void Refresh(const cv::Mat& gray, const arm::ArmPose& pose, const arm::ArmShape& shape);
  // Drops every arm feature (the pose they were seeded on is in doubt); the body's stay.
  void ForgetArm();
  std::vector<cv::Point2f> Points(int part) const;  // 0 body, 1 upper arm, 2 forearm

 private:
  struct Feature {
    cv::Point2f p, prev;
    int part = 0;  // 0 body, 1 upper arm, 2 forearm
  };
  void Seed(const cv::Mat& gray, const arm::ArmPose& pose, const arm::ArmShape& shape);

  LkOptions o_;
  PyramidFlow flow_;
  std::vector<Feature> feats_;
  int since_seed_ = 0;
};

}  // namespace armmimic::lk
