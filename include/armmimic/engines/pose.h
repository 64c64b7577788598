// The pose network (MoveNet SinglePose Lightning v4, run by OpenCV's DNN module): 17 body
// keypoints per frame. Used by the pose engine, by --auto-calibrate (the shoulder, elbow and
// wrist of a start frame for the tracking engines) and by the GUI's Auto-calibrate button.
// docs/pose.md describes the model, its files and where they are looked for.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic {

// MoveNet's keypoint order. Left/right are the person's own sides.
enum PoseKeypoint {
  kNose = 0,
  kLeftEye,
  kRightEye,
  kLeftEar,
  kRightEar,
  kLeftShoulder,
  kRightShoulder,
  kLeftElbow,
  kRightElbow,
  kLeftWrist,
  kRightWrist,
  kLeftHip,
  kRightHip,
  kLeftKnee,
  kRightKnee,
  kLeftAnkle,
  kRightAnkle,
};
inline constexpr int kPoseKeypointCount = 17;
// The skeleton's bones as keypoint pairs, for drawing.
extern const std::array<std::pair<int, int>, 16> kPoseBones;

struct PoseKeypoints {
  std::array<cv::Point2d, kPoseKeypointCount> px{};  // full-image pixels
  std::array<double, kPoseKeypointCount> score{};    // 0..1
};

// The square region of the image the network looks at, in pixels; it may reach past the image
// (the outside is black).
struct PoseCrop {
  double x = 0, y = 0, size = 0;
};

// The files of the pinned model.
inline constexpr const char* kPoseModelJson = "movenet-lightning.json";
inline constexpr const char* kPoseModelWeights = "movenet-lightning.bin";

// The package that installs the model, and where: <prefix>/share/armmimic/models beside the
// programs' <prefix>/bin, /usr/share/armmimic/models for the Debian package armmimic-models.
inline constexpr const char* kPoseModelPackage = "armmimic-models";
inline constexpr const char* kPoseModelInstallSubdir = "share/armmimic/models";
inline constexpr const char* kPackagedPoseModelDir = "/usr/share/armmimic/models";

// Where the model is looked for, in order: `flag_dir` (--model DIR) when given, and then only
// there; otherwise $ARMMIMIC_MODEL_DIR, the source tree's .cache/armmimic (where
// scripts/deps.sh --with-model puts it; only for a program run from the build folder),
// $XDG_CACHE_HOME/armmimic, ~/.cache/armmimic, the installed folder beside the running program
// (InstalledPoseModelDir) and /usr/share/armmimic/models. Each folder once.
std::vector<std::string> PoseModelSearchPath(const std::string& flag_dir);
// <prefix>/share/armmimic/models for the running program <prefix>/bin/NAME, its symbolic links
// resolved, so a relocated install finds its own models ("" if the program's file is unknown).
std::string InstalledPoseModelDir();
// The first folder of PoseModelSearchPath holding the JSON file `json` (MoveNet's by default);
// with none, "" and the folders tried (for the error message).
std::string FindPoseModelDir(const std::string& flag_dir, std::vector<std::string>* tried,
                             const std::string& json = kPoseModelJson);

class PoseNetwork {
 public:
  ~PoseNetwork();
  // Finds the model (FindPoseModelDir), checks the two files' sizes and SHA-256 against the
  // pinned version and builds the network. A missing, truncated or altered file is an error
  // naming it and saying how to get the model.
  static std::unique_ptr<PoseNetwork> Load(const std::string& flag_dir, Status* status);
  // Loads from a graph JSON without the checksum check (a test's own graph).
  static std::unique_ptr<PoseNetwork> LoadUnchecked(const std::string& json_path, Status* status);

  // The keypoints of the person in `crop` of `bgr` (CV_8UC3).
  PoseKeypoints Run(const cv::Mat& bgr, const PoseCrop& crop);
  // The same from the mirror image of the crop: the network's keypoints are mirrored back and
  // their left and right swapped, so they name the same joints as Run's. A second look whose
  // disagreement with the first says how sure the network is.
  PoseKeypoints RunMirrored(const cv::Mat& bgr, const PoseCrop& crop);
  // The same from the network's own 192x192 RGB input (parity checks against other runtimes).
  PoseKeypoints RunInput(const cv::Mat& rgb192);
  // The 192x192 RGB input the network sees for `crop`.
  static cv::Mat MakeInput(const cv::Mat& bgr, const PoseCrop& crop);
  static constexpr int kInputSize = 192;
  const std::string& dir() const;

 private:
  struct Impl;
  explicit PoseNetwork(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// The whole image padded to a square (the first frame, and after the person was lost).
PoseCrop WholeImageCrop(const cv::Size& image);
// MoveNet's demo rule: a square around the hips' centre that holds the torso (x1.9) and every
// keypoint scored above `min_score` (x1.2); the whole image when the torso is not seen.
PoseCrop NextCrop(const PoseKeypoints& k, const cv::Size& image, double min_score);

// The arm look's crop: a square around the upper body (shoulders, elbows, wrists and hips
// scored above `min_score`) of `factor` times its extent. False when fewer than four are seen.
bool ArmLookCrop(const PoseKeypoints& k, double factor, double min_score, PoseCrop* crop);

// One arm's joints from keypoints: shoulder, elbow, wrist of `side` (kLeft or kRight).
struct PoseArm {
  cv::Point2d shoulder, elbow, wrist;
  double score = 0;  // the lowest of the three scores
};
PoseArm ArmOf(const PoseKeypoints& k, PoseSide side);

// --auto-calibrate: the arm's three joints in frame `frame` of `inputs`, looked at as the pose
// engine does with `options` (its side is not used). With side kAuto, the better-seen arm.
// Fails (naming the frame) when the arm is not seen clearly (options.min_score).
Status DetectArmJoints(const std::vector<std::string>& inputs, int frame, PoseSide side,
                       const std::string& model_dir, const PoseOptions& options, PoseArm* arm,
                       PoseSide* chosen);

}  // namespace armmimic
