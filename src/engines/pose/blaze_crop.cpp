// BlazePose's crop (MediaPipe's AlignmentPointsRectsCalculator with a target angle of 90 degrees
// and RectTransformationCalculator's 1.25 scale, square), its first placement from MoveNet, and
// BlazePose's landmarks in MoveNet's order.
#include <algorithm>
#include <cmath>

#include "pose/blazepose.h"

namespace armmimic::internal {
namespace {

// The crop's rotation for an up direction `from` -> `to` (image y down).
double RotationOf(const cv::Point2d& from, const cv::Point2d& to) {
  const double rotation = M_PI / 2 - std::atan2(-(to.y - from.y), to.x - from.x);
  return rotation - 2 * M_PI * std::floor((rotation + M_PI) / (2 * M_PI));  // to [-pi, pi)
}

}  // namespace

cv::Point2d CropToImage(const BlazeCrop& crop, double u, double v) {
  const double x = (u - 0.5) * crop.size, y = (v - 0.5) * crop.size;
  const double c = std::cos(crop.rotation), s = std::sin(crop.rotation);
  return crop.centre + cv::Point2d(c * x - s * y, s * x + c * y);
}

BlazeCrop CropFromAuxiliary(const cv::Point2d& centre, const cv::Point2d& top) {
  BlazeCrop crop;
  crop.centre = centre;
  crop.size = 2 * cv::norm(top - centre) * 1.25;
  crop.rotation = RotationOf(centre, top);
  return crop;
}

bool CropFromMoveNet(const PoseKeypoints& k, double min_score, BlazeCrop* crop) {
  for (int j : {kLeftShoulder, kRightShoulder, kLeftHip, kRightHip}) {
    if (k.score[j] < min_score) return false;
  }
  const cv::Point2d hips = (k.px[kLeftHip] + k.px[kRightHip]) * 0.5;
  const cv::Point2d shoulders = (k.px[kLeftShoulder] + k.px[kRightShoulder]) * 0.5;
  const double torso = cv::norm(shoulders - hips);
  if (!(torso > 0)) return false;
  // The auxiliary circle holds the whole body; the keypoints stop short of the top of the head
  // and the feet by about a tenth.
  double radius = 1.2 * torso;
  for (int j = 0; j < kPoseKeypointCount; ++j) {
    if (k.score[j] >= min_score) radius = std::max(radius, 1.1 * cv::norm(k.px[j] - hips));
  }
  const cv::Point2d up = (shoulders - hips) / torso;
  *crop = CropFromAuxiliary(hips, hips + up * radius);
  return true;
}

bool SeedCrop(PoseNetwork* movenet, BlazePoseNetwork* blaze, const cv::Mat& bgr, double min_score,
              BlazeCrop* crop) {
  const PoseKeypoints k = movenet->Run(bgr, WholeImageCrop(bgr.size()));
  if (!CropFromMoveNet(k, min_score, crop)) return false;
  const BlazeLandmarks first = blaze->Run(bgr, *crop);
  if (first.poseflag < kMinPoseFlag) return false;
  *crop = CropFromAuxiliary(first.px[kBlazeCentre], first.px[kBlazeTop]);
  return true;
}

PoseKeypoints AsMoveNetKeypoints(const BlazeLandmarks& b) {
  static constexpr int kFrom[kPoseKeypointCount] = {
      kBlazeNose,         kBlazeLeftEye,       kBlazeRightEye,  kBlazeLeftEar,    kBlazeRightEar,
      kBlazeLeftShoulder, kBlazeRightShoulder, kBlazeLeftElbow, kBlazeRightElbow, kBlazeLeftWrist,
      kBlazeRightWrist,   kBlazeLeftHip,       kBlazeRightHip,  kBlazeLeftKnee,   kBlazeRightKnee,
      kBlazeLeftAnkle,    kBlazeRightAnkle};
  PoseKeypoints k;
  for (int i = 0; i < kPoseKeypointCount; ++i) {
    k.px[i] = b.px[kFrom[i]];
    k.score[i] = b.visibility[kFrom[i]];
  }
  return k;
}

}  // namespace armmimic::internal
