// Scenes for the tests of the arm model's searches (arm_model_fit_test, evidence_bound_test): a
// tiled wall with noise, an arm of a known shape painted over it in the sleeve's colour, and
// specks of that colour and of a near one.
#pragma once

#include <random>

#include <opencv2/imgproc.hpp>

#include "common/arm_model_fit.h"

namespace armmimic::arm::painted {

inline const cv::Scalar kSleeve(40, 60, 200), kNearSleeve(70, 90, 170);

inline cv::Mat TiledWall(const cv::Size& size) {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> noise(-25, 25);
  cv::Mat wall(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const int t = ((x / 8 + y / 8) % 2) * 40;  // tiles
      wall.at<cv::Vec3b>(y, x) = cv::Vec3b(cv::saturate_cast<uchar>(90 + t + noise(rng)),
                                           cv::saturate_cast<uchar>(140 + noise(rng)),
                                           cv::saturate_cast<uchar>(150 - t + noise(rng)));
    }
  }
  return wall;
}

inline ArmShape DrawnShape() {
  ArmShape drawn;
  drawn.upper_px = 38;
  drawn.fore_px = 32;
  drawn.hand_px = 10;
  drawn.upper_hw = 4;
  drawn.fore_hw = 3.5;
  return drawn;
}

inline cv::Mat Painted(const cv::Mat& wall, const ArmJoints& joints) {
  cv::Mat frame = wall.clone();
  cv::Mat arm = cv::Mat::zeros(wall.size(), CV_8U);
  DrawArm(arm, joints, DrawnShape(), 0);
  frame.setTo(kSleeve, arm);
  return frame;
}

// `count` specks of 1-3 pixels' radius anywhere on the frame, every other one in the sleeve's
// colour and the rest in a near colour.
inline cv::Mat Specked(const cv::Mat& clean, int count, std::mt19937* rng) {
  cv::Mat frame = clean.clone();
  std::uniform_real_distribution<double> at(0, 1);
  for (int i = 0; i < count; ++i) {
    const cv::Point c(static_cast<int>(at(*rng) * frame.cols),
                      static_cast<int>(at(*rng) * frame.rows));
    cv::circle(frame, c, 1 + static_cast<int>(at(*rng) * 3), i % 2 ? kSleeve : kNearSleeve,
               cv::FILLED);
  }
  return frame;
}

}  // namespace armmimic::arm::painted
