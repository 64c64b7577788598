// The local search (FitNear) gives up cells that can no longer beat the best so far: it must
// still return, to the bit, what scoring every cell of its grid returns. The reference below
// scores every cell with ScorePose and refines the best as FitNear does, on a painted arm over a
// textured wall, from predictions on the arm, beside it and far from it.
#include "common/arm_model_fit.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"

namespace armmimic::arm {
namespace {

double ParabolaPeak(double a, double b, double c) {
  const double den = a - 2 * b + c;
  return den < 0 ? std::clamp(0.5 * (a - c) / den, -0.5, 0.5) : 0.0;
}

// FitNear without giving up any cell.
FitResult EveryCell(const EvidenceMap& evidence, const ArmShape& shape, const ArmPose& predicted,
                    int range) {
  const int n = 2 * range + 1;
  const double bend0 = AngleDiff(predicted.fore_deg, predicted.upper_deg);
  std::vector<double> total(static_cast<std::size_t>(n * n), -4.0);
  int best = -1;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double up = predicted.upper_deg + (i - range), bend = bend0 + (j - range);
      if (std::abs(bend) > kMaxBendDeg) continue;
      ArmPose p;
      p.shoulder = predicted.shoulder;
      p.upper_deg = up;
      p.fore_deg = up + bend;
      const int k = i * n + j;
      total[k] = ScorePose(evidence, p, shape).total;
      if (best < 0 || total[k] > total[best]) best = k;
    }
  }
  FitResult r;
  r.pose = predicted;
  if (best < 0) {
    r.score = ScorePose(evidence, predicted, shape);  // no bend the elbow allows
    return r;
  }
  const int bi = best / n, bj = best % n;
  double di = bi - range, dj = bj - range;
  auto at = [&](int i, int j) { return total[static_cast<std::size_t>(i * n + j)]; };
  if (bi > 0 && bi < n - 1 && at(bi - 1, bj) > -4 && at(bi + 1, bj) > -4) {
    di += ParabolaPeak(at(bi - 1, bj), at(bi, bj), at(bi + 1, bj));
  }
  if (bj > 0 && bj < n - 1 && at(bi, bj - 1) > -4 && at(bi, bj + 1) > -4) {
    dj += ParabolaPeak(at(bi, bj - 1), at(bi, bj), at(bi, bj + 1));
  }
  r.pose.upper_deg = Wrap180(predicted.upper_deg + di);
  r.pose.fore_deg = Wrap180(r.pose.upper_deg + bend0 + dj);
  r.score = ScorePose(evidence, r.pose, shape);
  return r;
}

TEST(ArmModelFit, FitNearEqualsScoringEveryCell) {
  const cv::Size size(160, 120);
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
  ArmPose truth;
  truth.shoulder = {60.3, 40.7};
  truth.upper_deg = -60;
  truth.fore_deg = 10;
  ArmShape drawn;
  drawn.upper_px = 38;
  drawn.fore_px = 32;
  drawn.hand_px = 10;
  drawn.upper_hw = 4;
  drawn.fore_hw = 3.5;
  const ArmJoints joints = JointsOf(truth, drawn);
  cv::Mat frame = wall.clone();
  cv::Mat arm = cv::Mat::zeros(size, CV_8U);
  DrawArm(arm, joints, drawn, 0);
  frame.setTo(cv::Scalar(40, 60, 200), arm);
  const LearntArm learnt = LearnArm(frame, joints, 80);
  LearntBackground background;
  background.Reset(wall, cv::Mat::zeros(size, CV_8U));
  EvidenceMap evidence;
  evidence.Compute(frame, background, learnt.colour, cv::Rect(cv::Point(), size),
                   cv::Mat::zeros(size, CV_8U));
  const ArmShape& shape = learnt.shape;
  int predictions = 0;
  for (double du : {0.0, 3.4, -7.9, 40.2}) {
    for (double df : {0.0, -5.3, 12.6, 155.0}) {
      ArmPose predicted = truth;
      predicted.upper_deg = Wrap180(truth.upper_deg + du);
      predicted.fore_deg = Wrap180(truth.fore_deg + df);
      for (int range : {4, 15}) {
        LocalSearch search;
        search.upper_range_deg = search.bend_range_deg = range;
        const FitResult got = FitNear(evidence, shape, predicted, search);
        const FitResult want = EveryCell(evidence, shape, predicted, range);
        EXPECT_EQ(got.pose.upper_deg, want.pose.upper_deg) << du << " " << df << " " << range;
        EXPECT_EQ(got.pose.fore_deg, want.pose.fore_deg) << du << " " << df << " " << range;
        EXPECT_EQ(got.score.total, want.score.total) << du << " " << df << " " << range;
        ++predictions;
      }
    }
  }
  // The arm is found from a prediction on it: the scene is one the search can read.
  const FitResult on = FitNear(evidence, shape, truth, LocalSearch());
  EXPECT_LT(PoseDistanceDeg(on.pose, truth), 3.0);
  EXPECT_EQ(predictions, 32);
}

}  // namespace
}  // namespace armmimic::arm
