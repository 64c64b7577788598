// MoveNet's crop tracking (the demo's init_crop_region and determine_crop_region), in pixels,
// and the arm look's closer square around the upper body.
#include <algorithm>
#include <cmath>

#include "armmimic/engines/pose.h"

namespace armmimic {

const std::array<std::pair<int, int>, 16> kPoseBones = {{
    {kNose, kLeftEye},
    {kNose, kRightEye},
    {kLeftEye, kLeftEar},
    {kRightEye, kRightEar},
    {kLeftShoulder, kRightShoulder},
    {kLeftShoulder, kLeftElbow},
    {kLeftElbow, kLeftWrist},
    {kRightShoulder, kRightElbow},
    {kRightElbow, kRightWrist},
    {kLeftShoulder, kLeftHip},
    {kRightShoulder, kRightHip},
    {kLeftHip, kRightHip},
    {kLeftHip, kLeftKnee},
    {kLeftKnee, kLeftAnkle},
    {kRightHip, kRightKnee},
    {kRightKnee, kRightAnkle},
}};

PoseCrop WholeImageCrop(const cv::Size& image) {
  const double w = image.width, h = image.height;
  if (w > h) return {0, (h - w) / 2, w};
  return {(w - h) / 2, 0, h};
}

PoseCrop NextCrop(const PoseKeypoints& k, const cv::Size& image, double min_score) {
  auto seen = [&](int i) { return k.score[i] > min_score; };
  const bool torso =
      (seen(kLeftHip) || seen(kRightHip)) && (seen(kLeftShoulder) || seen(kRightShoulder));
  if (!torso) return WholeImageCrop(image);
  const cv::Point2d centre = (k.px[kLeftHip] + k.px[kRightHip]) * 0.5;
  double torso_x = 0, torso_y = 0, body_x = 0, body_y = 0;
  for (int j : {kLeftShoulder, kRightShoulder, kLeftHip, kRightHip}) {
    torso_x = std::max(torso_x, std::abs(centre.x - k.px[j].x));
    torso_y = std::max(torso_y, std::abs(centre.y - k.px[j].y));
  }
  for (int j = 0; j < kPoseKeypointCount; ++j) {
    if (k.score[j] < min_score) continue;
    body_x = std::max(body_x, std::abs(centre.x - k.px[j].x));
    body_y = std::max(body_y, std::abs(centre.y - k.px[j].y));
  }
  double half = std::max({torso_x * 1.9, torso_y * 1.9, body_x * 1.2, body_y * 1.2});
  const double w = image.width, h = image.height;
  half = std::min(half, std::max({centre.x, w - centre.x, centre.y, h - centre.y}));
  if (!(half > 0) || half > std::max(w, h) / 2) return WholeImageCrop(image);
  return {centre.x - half, centre.y - half, 2 * half};
}

bool ArmLookCrop(const PoseKeypoints& k, double factor, double min_score, PoseCrop* crop) {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int seen = 0;
  for (int j = kLeftShoulder; j <= kRightHip; ++j) {
    if (k.score[j] < min_score) continue;
    const cv::Point2d& p = k.px[j];
    x0 = seen ? std::min(x0, p.x) : p.x;
    x1 = seen ? std::max(x1, p.x) : p.x;
    y0 = seen ? std::min(y0, p.y) : p.y;
    y1 = seen ? std::max(y1, p.y) : p.y;
    ++seen;
  }
  const double half = factor * std::max(x1 - x0, y1 - y0) / 2;
  if (seen < 4 || !(half > 0)) return false;
  *crop = {(x0 + x1) / 2 - half, (y0 + y1) / 2 - half, 2 * half};
  return true;
}

PoseArm ArmOf(const PoseKeypoints& k, PoseSide side) {
  const bool left = side == PoseSide::kLeft;
  const int s = left ? kLeftShoulder : kRightShoulder;
  const int e = left ? kLeftElbow : kRightElbow;
  const int w = left ? kLeftWrist : kRightWrist;
  PoseArm arm;
  arm.shoulder = k.px[s];
  arm.elbow = k.px[e];
  arm.wrist = k.px[w];
  arm.score = std::min({k.score[s], k.score[e], k.score[w]});
  return arm;
}

}  // namespace armmimic
