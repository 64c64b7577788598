// Arm scenes with ground truth (thesis protocol, chapters 5 and 6): K frames of the empty
// background, M standstill frames of a person with both arms hanging, then one arm moving with
// known upper-arm and forearm directions. Rendered in memory, so tests can run the engines
// without writing a video; WriteArmScene() also writes the scene to a folder.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"
#include "armmimic/synth/truth_file.h"

namespace armmimic::synth {

// How the moving arm moves after the standstill.
enum class ArmMotion {
  kSwing,  // straight arm from hanging to raised and back (upper = fore)
  kBend,   // upper arm slowly moving, elbow flexing 0..150 degrees
  kYaw,    // straight horizontal arm turning out of the image plane, yaw 0..~70 degrees
  kMixed,  // smooth random poses: upper arm hanging..raised combined with elbow flexion
};

// Which side of the image the moving arm is on (as seen on screen, not the person's side).
enum class ArmSide { kRight, kLeft };

const char* ArmMotionName(ArmMotion m);  // "swing", "bend", "yaw", "mixed"
bool ParseArmMotion(const std::string& name, ArmMotion* out);
const char* ArmSideName(ArmSide s);  // "right", "left"
bool ParseArmSide(const std::string& name, ArmSide* out);

struct ArmSceneOptions {
  uint64_t seed = 1;
  cv::Size size{320, 240};
  double fps = 30;
  int background_frames = 45;  // K: the empty scene (thesis 5.2.1)
  int standstill_frames = 60;  // M: person standing, arms hanging (thesis 5.2.2)
  int motion_frames = 150;     // frames of arm motion after the standstill
  double noise_sigma = 3;      // Gaussian sensor noise, grey levels
  std::string codec = "MJPG";  // for WriteArmScene: MJPG, XVID or H264
  // MJPG quality 1..100 with OpenCV's own encoder; 0 = FFmpeg's MJPEG encoder at its default
  // quality (about half the size at the same fidelity).
  int jpeg_quality = 0;
  // 1 = shirt far from the background colour; 0 = shirt the colour of the wall behind it.
  double clothing_contrast = 1.0;
  // Global gain change over the video: the gain ramps linearly from 1 to 1 + lighting_drift.
  double lighting_drift = 0;
  bool shadow = false;       // a soft shadow moving over the wall during the motion
  bool head_motion = false;  // the head sways and nods during the motion
  ArmMotion motion = ArmMotion::kMixed;
  ArmSide side = ArmSide::kRight;

  int frame_count() const { return background_frames + standstill_frames + motion_frames; }
  int first_motion_frame() const { return background_frames + standstill_frames; }
  // Checks ranges; the message names the option ("size 10x10 is too small (at least 160x120)").
  Status Check() const;
};

// The truth of one frame. Background frames have nan angles and positions.
struct ArmTruth {
  int frame = 0;
  double time_s = 0;
  bool person = false;  // false on the empty-background frames
  double upper_deg = kNaN;
  double fore_deg = kNaN;
  double yaw_deg = kNaN;   // 0 for in-plane motion, the out-of-plane angle in yaw mode
  double bend_deg = kNaN;  // fore - upper wrapped to (-180, 180]
  cv::Point2d shoulder_px{kNaN, kNaN};
  cv::Point2d elbow_px{kNaN, kNaN};  // projected (image) positions
  cv::Point2d wrist_px{kNaN, kNaN};
  TruthRow ToRow() const;
};

class ArmSceneRenderer {
 public:
  // Throws std::invalid_argument when options.Check() fails.
  explicit ArmSceneRenderer(const ArmSceneOptions& options);
  ~ArmSceneRenderer();
  ArmSceneRenderer(const ArmSceneRenderer&) = delete;
  ArmSceneRenderer& operator=(const ArmSceneRenderer&) = delete;

  const ArmSceneOptions& options() const;
  int frame_count() const;
  // The truth of `frame` without rendering it.
  ArmTruth Truth(int frame) const;
  // Frame `frame` (CV_8UC3 BGR, options().size), identical for a given seed and frame whatever
  // the order of calls. `truth` may be null.
  cv::Mat Render(int frame, ArmTruth* truth = nullptr) const;
  // Thesis 5.2.3: the same person and scene with the moving arm straight and horizontal
  // (pointing away from the body) at zero yaw. `truth` may be null.
  cv::Mat ArmLengthImage(ArmTruth* truth = nullptr) const;
  // The empty scene without noise, lighting drift or shadow.
  cv::Mat EmptyBackground() const;
  // Shoulder joint of the moving arm in pixels (fixed for the whole scene).
  cv::Point2d shoulder_px() const;
  // Projected lengths of the upper arm and forearm at zero yaw, pixels (joint to joint).
  double upper_length_px() const;
  double fore_length_px() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Writes scene.avi, armlength.png, background.png (the empty scene) and truth.tsv into `outdir`
// (created if missing). Every file appears complete or not at all. `progress(done, total)` is
// called after each video frame (may be empty). When `cancel` becomes true the video is
// dropped and nothing in `outdir` changes (the result is an error saying so).
Status WriteArmScene(const ArmSceneOptions& options, const std::string& outdir,
                     const std::function<void(int, int)>& progress,
                     const std::atomic<bool>* cancel = nullptr);

}  // namespace armmimic::synth
