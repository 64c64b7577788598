// The searches give up poses that can no longer matter, and must still return, to the bit, what
// scoring every pose returns. The local search (FitNear) gives up cells that can no longer beat
// the best so far: the reference below scores every cell with ScorePose and refines the best as
// FitNear does, on a painted arm over a textured wall, from predictions on the arm, beside it and
// far from it. The search over every pose (FitAnywhere), given the last frame's floor, gives up
// coarse poses below it: over frames of a moving arm among specks of its colour, one without it
// and a jump, with the map over the whole frame and over a region that cuts the arm, it returns
// what it returns without that memory. (evidence_bound_test checks the bound it gives up by.)
#include "common/arm_model_fit.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "painted_arm.h"

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

using painted::DrawnShape;
using painted::Specked;
using painted::TiledWall;

cv::Mat Painted(const cv::Mat& wall, const ArmPose& pose) {
  return painted::Painted(wall, JointsOf(pose, DrawnShape()));
}

ArmPose Truth() {
  ArmPose truth;
  truth.shoulder = {60.3, 40.7};
  truth.upper_deg = -60;
  truth.fore_deg = 10;
  return truth;
}

TEST(ArmModelFit, FitNearEqualsScoringEveryCell) {
  const cv::Size size(160, 120);
  const cv::Mat wall = TiledWall(size);
  const ArmPose truth = Truth();
  const cv::Mat frame = Painted(wall, truth);
  const LearntArm learnt = LearnArm(frame, JointsOf(truth, DrawnShape()), 80);
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

TEST(ArmModelFit, FitAnywhereWithTheLastFloorEqualsScoringEveryPose) {
  const cv::Size size(160, 120);
  const cv::Mat wall = TiledWall(size);
  const ArmPose truth = Truth();
  const LearntArm learnt = LearnArm(Painted(wall, truth), JointsOf(truth, DrawnShape()), 80);
  LearntBackground background;
  background.Reset(wall, cv::Mat::zeros(size, CV_8U));
  // The arm turning a few degrees a frame, then gone (every peak sinks below the last floor: the
  // given-up poses are scored in full), back, and at once elsewhere.
  // Specks of the arm's colour and of a near colour, all over: many poses explain part of a
  // frame, and score near the floor.
  std::mt19937 rng(5);
  auto specked = [&](const cv::Mat& frame) { return Specked(frame, 60, &rng); };
  std::vector<cv::Mat> frames;
  for (int f = 0; f < 4; ++f) {
    ArmPose p = truth;
    p.upper_deg += 3 * f;
    p.fore_deg -= 4 * f;
    frames.push_back(specked(Painted(wall, p)));
  }
  frames.push_back(wall.clone());
  frames.push_back(specked(Painted(wall, truth)));
  ArmPose far = truth;
  far.upper_deg = -150;
  far.fore_deg = -100;
  frames.push_back(specked(Painted(wall, far)));
  // The evidence over the whole frame, and over a region off its corner that cuts the far arm
  // (samples off the map).
  for (const cv::Rect& region : {cv::Rect(cv::Point(), size), cv::Rect(9, 6, 131, 97)}) {
    for (int count : {4, 12}) {
      WideSearchMemory memory;
      for (std::size_t f = 0; f < frames.size(); ++f) {
        EvidenceMap evidence;
        evidence.Compute(frames[f], background, learnt.colour, region, cv::Mat::zeros(size, CV_8U));
        const std::vector<FitResult> want =
            FitAnywhere(evidence, learnt.shape, truth.shoulder, count);
        const std::vector<FitResult> got =
            FitAnywhere(evidence, learnt.shape, truth.shoulder, count, &memory);
        ASSERT_EQ(got.size(), want.size()) << region << " frame " << f;
        for (std::size_t i = 0; i < got.size(); ++i) {
          EXPECT_EQ(got[i].pose.upper_deg, want[i].pose.upper_deg) << region << " frame " << f;
          EXPECT_EQ(got[i].pose.fore_deg, want[i].pose.fore_deg) << region << " frame " << f;
          EXPECT_EQ(got[i].score.total, want[i].score.total) << region << " frame " << f;
        }
        // A frame with the arm leaves the next one a floor, so each such next frame gives poses
        // up; the empty wall, one plateau and so fewer than four poses, leaves none.
        EXPECT_EQ(std::isfinite(memory.last_floor), f != 4) << region << " frame " << f;
      }
    }
  }
  // The arm is found anywhere on the last frame: the scenes are ones the search can read.
  EvidenceMap evidence;
  evidence.Compute(frames.back(), background, learnt.colour, cv::Rect(cv::Point(), size),
                   cv::Mat::zeros(size, CV_8U));
  const std::vector<FitResult> found = FitAnywhere(evidence, learnt.shape, truth.shoulder, 4);
  EXPECT_LT(PoseDistanceDeg(found.front().pose, far), 4.0);
}

}  // namespace
}  // namespace armmimic::arm
