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
#include "armmimic/synth/arm_scene_source.h"
#include "armmimic/synth/truth_file.h"

namespace armmimic::synth {

// How the moving arm moves after the standstill.
enum class ArmMotion {
  kSwing,  // straight arm from hanging to raised and back (upper = fore)
  kBend,   // upper arm slowly moving, elbow flexing 0..150 degrees
  kYaw,    // straight horizontal arm turning out of the image plane, yaw 0..~70 degrees
  kMixed,  // smooth random poses: upper arm hanging..raised combined with elbow flexion
};

const char* ArmMotionName(ArmMotion m);  // "swing", "bend", "yaw", "mixed"
bool ParseArmMotion(const std::string& name, ArmMotion* out);

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

class ArmSceneRenderer : public ArmSceneSource {
 public:
  // Throws std::invalid_argument when options.Check() fails.
  explicit ArmSceneRenderer(const ArmSceneOptions& options);
  ~ArmSceneRenderer() override;
  ArmSceneRenderer(const ArmSceneRenderer&) = delete;
  ArmSceneRenderer& operator=(const ArmSceneRenderer&) = delete;

  const ArmSceneOptions& options() const;
  cv::Size size() const override;
  double fps() const override;
  int background_frames() const override;
  int standstill_frames() const override;
  int motion_frames() const override;
  ArmTruth Truth(int frame) const override;
  cv::Mat Render(int frame, ArmTruth* truth = nullptr) const override;
  cv::Mat ArmLengthImage(ArmTruth* truth = nullptr) const override;
  cv::Mat EmptyBackground() const override;
  double upper_length_px() const override;
  double fore_length_px() const override;
  // Shoulder joint of the moving arm in pixels (fixed for the whole scene).
  cv::Point2d shoulder_px() const;

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
