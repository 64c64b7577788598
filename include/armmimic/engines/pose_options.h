// Options of the pose-network engine (MoveNet SinglePose Lightning, docs/pose.md).
#pragma once

#include <string>

#include "armmimic/core/status.h"

namespace armmimic {

// The person's own arm (their left arm is on the image's right when they face the camera).
enum class PoseSide { kAuto, kLeft, kRight };  // kAuto: the arm better seen over the first second

struct PoseOptions {
  PoseSide side = PoseSide::kAuto;
  // A shoulder, elbow or wrist scored below this is not seen: the row is lost.
  double min_score = 0.4;
  // A segment shorter than this share of its usual length over the clip points at the camera:
  // its 2-D direction means nothing, the row is lost.
  double min_length_ratio = 0.55;
  // Crop tracking (as in MoveNet's demo): torso keypoints above this score place the next crop;
  // below it, or when an arm keypoint drops below min_score, the next frame searches the whole
  // image again.
  double crop_score = 0.2;
  Status Check() const;
};

const char* PoseSideName(PoseSide side);  // "auto", "left", "right"
bool ParsePoseSide(const std::string& name, PoseSide* out);

}  // namespace armmimic
