// ArmSceneSource: what every arm scene with ground truth offers, whoever draws it (the fixed
// room of ArmSceneRenderer, the randomised scenes of RandomArmScene). Tests, benchmarks and the
// scene writer run on either through this interface.
//
// Every scene follows the thesis protocol: frames [0, K) show the empty room, frames [K, K+M)
// the person standing with both arms hanging, and the N frames after that one arm moving.
#pragma once

#include <atomic>

#include <functional>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "armmimic/core/status.h"
#include "armmimic/synth/truth_file.h"

namespace armmimic::synth {

// Which side of the image the moving arm is on (as seen on screen, not the person's side).
enum class ArmSide { kRight, kLeft };

const char* ArmSideName(ArmSide s);  // "right", "left"
bool ParseArmSide(const std::string& name, ArmSide* out);

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

class ArmSceneSource {
 public:
  virtual ~ArmSceneSource() = default;

  virtual cv::Size size() const = 0;
  virtual double fps() const = 0;
  virtual int background_frames() const = 0;  // K
  virtual int standstill_frames() const = 0;  // M
  virtual int motion_frames() const = 0;      // N
  int frame_count() const { return background_frames() + standstill_frames() + motion_frames(); }
  int first_motion_frame() const { return background_frames() + standstill_frames(); }

  // The truth of `frame` without rendering it.
  virtual ArmTruth Truth(int frame) const = 0;
  // Frame `frame` (CV_8UC3 BGR, size()), identical for a given scene and frame whatever the
  // order of calls. `truth` may be null. Throws std::out_of_range outside [0, frame_count()).
  virtual cv::Mat Render(int frame, ArmTruth* truth = nullptr) const = 0;
  // Thesis 5.2.3: the same person and scene with the moving arm straight and horizontal
  // (pointing away from the body) at zero yaw. `truth` may be null.
  virtual cv::Mat ArmLengthImage(ArmTruth* truth = nullptr) const = 0;
  // The empty scene without noise, lighting drift or shadow.
  virtual cv::Mat EmptyBackground() const = 0;
  // Projected lengths of the upper arm and forearm at zero yaw, pixels (joint to joint).
  virtual double upper_length_px() const = 0;
  virtual double fore_length_px() const = 0;
};

// How WriteSceneFolder encodes scene.avi.
struct SceneVideo {
  std::string codec = "MJPG";  // MJPG, XVID or H264
  // MJPG quality 1..100 with OpenCV's own encoder; 0 = FFmpeg's MJPEG encoder at its default.
  int jpeg_quality = 0;
};

// Writes scene.avi, armlength.png, background.png (the empty scene) and truth.tsv (with `meta`
// as its meta line) into `outdir` (created if missing). Every file appears complete or not at
// all; the video is renamed into place last. `progress(done, total)` is called after each video
// frame (may be empty). When `cancel` becomes true the video is dropped and nothing in `outdir`
// changes (the result is an error saying so).
Status WriteSceneFolder(const ArmSceneSource& scene, const SceneVideo& video, const AngleMeta& meta,
                        const std::string& outdir, const std::function<void(int, int)>& progress,
                        const std::atomic<bool>* cancel = nullptr);
// The same with the whole truth file given (a scene whose truth has extra columns).
Status WriteSceneFolder(const ArmSceneSource& scene, const SceneVideo& video,
                        const TruthFile& truth, const std::string& outdir,
                        const std::function<void(int, int)>& progress,
                        const std::atomic<bool>* cancel = nullptr);

}  // namespace armmimic::synth
