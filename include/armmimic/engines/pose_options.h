// Options of the pose-network engine (MoveNet SinglePose Lightning, docs/pose.md).
#pragma once

#include <string>

#include "armmimic/core/status.h"

namespace armmimic {

// The person's own arm (their left arm is on the image's right when they face the camera).
// kAuto: the arm better seen over the first second. kBoth (the pose engine only): both arms from
// the same inferences, each into its own angle file (ArmOutputPaths, analysis.h).
enum class PoseSide { kAuto, kLeft, kRight, kBoth };

// The network: MoveNet SinglePose Lightning (2-D keypoints), or BlazePose GHUM full (2-D and
// 3-D world landmarks, in a crop placed by its own auxiliary points; docs/pose.md).
enum class PoseNetworkKind { kMoveNet, kBlazePose };

struct PoseOptions {
  PoseNetworkKind network = PoseNetworkKind::kMoveNet;
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
  // The arm look: a second look at every frame through a square around the upper body
  // (shoulders, elbows, wrists, hips) this many times its extent, where the arm is seen about
  // twice as large as in the whole-person crop. Its keypoints give the directions. 0: one look.
  double arm_crop = 1.5;
  // A segment whose direction differs by more than this between the looks (degrees) is lost:
  // the network itself is unsure where it points.
  double max_disagreement_deg = 15;
  // BlazePose only: a row is lost where MoveNet's looks, the second opinion, place the arm's
  // joints or segments farther from BlazePose's than a turn of this many degrees would, or where
  // BlazePose's 3-D direction turns this far from MoveNet's segment in the image plane
  // (pose/second_opinion.h). Wider than the looks' bound: the two networks were trained on
  // different joint conventions and differ by several degrees on real people.
  double max_network_disagreement_deg = 25;
  // Also look at the mirror image of the closer look's crop: the two are averaged, and their
  // disagreement counts like the others'. One more inference per frame.
  bool flip = false;
  Status Check() const;  // the table's ranges, arm_crop 0 or >= 1; errors carry "pose.KEY"
};

const char* PoseSideName(PoseSide side);  // "auto", "left", "right", "both"
bool ParsePoseSide(const std::string& name, PoseSide* out);

}  // namespace armmimic
