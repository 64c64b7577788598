// Private to src/engines: what the shared parts in common/ call in each engine's folder. The
// engine classes themselves stay hidden in their folder's engine.cpp; Engine::Create reaches
// them through the factories, and the analysis pipeline reaches the pose engine's steps before
// a run (choosing the side, detecting the joints) through the declarations below.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "armmimic/core/status.h"
#include "armmimic/core/video_source.h"
#include "armmimic/engines/engine.h"
#include "armmimic/engines/pose.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic::internal {

// The pose network the pose engine describes in an angle file's header (model=...).
inline constexpr const char* kPoseModelName = "movenet-lightning-v4";
inline constexpr const char* kBlazePoseModelName = "blazepose-full-ghum";  // --network blazepose

std::unique_ptr<Engine> CreateBgsubEngine(const BgsubOptions& options);
std::unique_ptr<Engine> CreateLkEngine(const LkOptions& options);
// The pose an lk engine's tracker withheld in its last row as undecided by its own evidence
// (lk/tracker.h, TrackerPose::undecided), as the ok row it would have been, and how far its
// rival lies at least; for a second measurement to decide.
struct UndecidedPose {
  ArmMeasurement row;
  double rival_apart_deg = 0;
};
// Null when the last row withheld none (or the gate would not have kept it on speed), or `lk` is
// not an lk engine.
const UndecidedPose* LkUndecidedPose(const Engine& lk);
// Whether an lk engine could not calibrate from the standstill (it then has no pose at all).
bool LkCalibrationRefused(const Engine& lk);
std::unique_ptr<Engine> CreateMarkerEngine(const MarkerOptions& options);
std::unique_ptr<Engine> CreatePoseEngine(const PoseOptions& options);  // either network
std::unique_ptr<Engine> CreateBlazePoseEngine(const PoseOptions& options);
std::unique_ptr<Engine> CreateHybridEngine(const HybridOptions& hybrid, const LkOptions& lk,
                                           const BgsubOptions& bgsub, const PoseOptions& pose);

// The arms the pose engine follows for `side` (pose/arms.h): {kLeft, kRight} for kBoth, {side}
// otherwise (kAuto is decided on the first frame). The analysis writes an angle file for each.
std::vector<PoseSide> FollowedSides(PoseSide side);

// The pose engine's steps before a run (pose/calibrate.cpp).
// Opens the analysed input for one pass (AnalysisOptions::open_source or its files).
using SourceOpener = std::function<std::unique_ptr<VideoSource>(Status*)>;

// DetectArmJoints (pose.h) on the input `open` gives.
Status DetectArmJointsFrom(const SourceOpener& open, int frame, PoseSide side,
                           const std::string& model_dir, const PoseOptions& options, PoseArm* arm,
                           PoseSide* chosen);

// The arm better seen over frames [start, start + one second): the scores summed over a few
// frames. *why says what was decided, for the shells to show.
Status ChoosePoseSide(const SourceOpener& open, int start, double fps, const std::string& model_dir,
                      PoseSide* side, std::string* why);

}  // namespace armmimic::internal
