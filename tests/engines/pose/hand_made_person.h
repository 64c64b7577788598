// Keypoints of a hand-made person for the pose gates' tests (no network): Person() faces the
// camera with the left arm hanging and its forearm at a chosen direction; TurnForearm() turns it.
#pragma once

#include <cmath>

#include "armmimic/engines/pose.h"

namespace armmimic::internal {

// A person facing the camera, 100 px from shoulders to hips, the left arm (image right) hanging
// at -90 with its elbow bent so the forearm points at `fore_deg`. Every score 0.9.
inline PoseKeypoints Person(double fore_deg = -45) {
  PoseKeypoints k;
  k.score.fill(0.9);
  k.px[kLeftShoulder] = {230, 100};
  k.px[kRightShoulder] = {170, 100};
  k.px[kLeftHip] = {220, 200};
  k.px[kRightHip] = {180, 200};
  k.px[kRightElbow] = {165, 160};
  k.px[kRightWrist] = {165, 210};
  k.px[kLeftElbow] = {230, 160};
  const double a = fore_deg * M_PI / 180;
  k.px[kLeftWrist] = k.px[kLeftElbow] + 50.0 * cv::Point2d(std::cos(a), -std::sin(a));
  return k;
}

// `k` with its left forearm turned by `deg` about the elbow.
inline PoseKeypoints TurnForearm(PoseKeypoints k, double deg) {
  const cv::Point2d d = k.px[kLeftWrist] - k.px[kLeftElbow];
  const double a = -deg * M_PI / 180;  // image y points down
  k.px[kLeftWrist] = k.px[kLeftElbow] + cv::Point2d(d.x * std::cos(a) - d.y * std::sin(a),
                                                    d.x * std::sin(a) + d.y * std::cos(a));
  return k;
}

}  // namespace armmimic::internal
