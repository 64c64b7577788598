// The bgsub engine's two-segment fit (bgsub/fit.h) searches the forearm only as far folded back
// onto the upper arm as an elbow bends (the option max_bend_deg, 150 by default). The trap: an
// arm bent by 60 whose forearm mostly hides (in the wall's colour), beside a region that shows
// arm (the torso, an object in the sleeve's colour) where a forearm folded back by 168 would lie.
// Searched to 160 (as before the limit) the fold wins; searched to 150 the arm's own forearm
// does.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "bgsub/fit.h"

namespace armmimic {
namespace {

constexpr double kUpperLen = 34, kForeLen = 30, kHalfWidth = 4;
constexpr double kUpperDeg = 20, kBendDeg = 60, kFoldDeg = 168;

// A weights window (CV_8SC1: 2 the arm now, -1 the empty room) around the shoulder at its
// centre. The upper arm is whole; the forearm shows as small spots every third pixel along it;
// the region a forearm folded back by kFoldDeg would cover shows arm throughout.
cv::Mat TrapWeights(cv::Point* origin) {
  cv::Mat w(161, 161, CV_8SC1, cv::Scalar(-1));
  *origin = cv::Point(80, 80);
  const cv::Point2d s(*origin);
  const cv::Point2d e = s + DirectionVector(kUpperDeg) * kUpperLen;
  const int thick = 2 * static_cast<int>(kHalfWidth) + 1;
  cv::line(w, s, e, cv::Scalar(2), thick);
  const cv::Point2d fold = e + DirectionVector(kUpperDeg + kFoldDeg) * kForeLen;
  cv::line(w, e, fold, cv::Scalar(2), thick);
  const cv::Point2d d = DirectionVector(kUpperDeg + kBendDeg);
  for (int t = 3; t <= static_cast<int>(kForeLen); t += 3) {
    cv::circle(w, e + d * t, 2, cv::Scalar(2), cv::FILLED);
  }
  return w;
}

bgsub::ArmFit FitWithin(int max_bend_deg) {
  cv::Point origin;
  const cv::Mat w = TrapWeights(&origin);
  bgsub::ArmFitter fitter;
  fitter.Begin(static_cast<int>(w.step1()), kUpperLen, kForeLen, kHalfWidth, max_bend_deg);
  return fitter.Fit(w, origin);
}

TEST(BgsubFit, AForearmIsNotFoldedBackFurtherThanAnElbowBends) {
  const bgsub::ArmFit fit = FitWithin(150);
  ASSERT_TRUE(fit.found);
  EXPECT_LT(std::abs(AngleDiff(fit.upper_deg, kUpperDeg)), 4.0);
  EXPECT_LT(std::abs(AngleDiff(fit.fore_deg, kUpperDeg + kBendDeg)), 6.0)
      << "forearm at " << fit.fore_deg;
}

TEST(BgsubFit, SearchedFurtherTheFoldWinsTheTrap) {
  // The scene is a trap: searched as far as before the limit, the folded forearm scores best.
  const bgsub::ArmFit fit = FitWithin(160);
  ASSERT_TRUE(fit.found);
  EXPECT_GT(std::abs(AngleDiff(fit.fore_deg, fit.upper_deg)), 150.0)
      << "forearm at " << fit.fore_deg << ", upper arm at " << fit.upper_deg;
}

}  // namespace
}  // namespace armmimic
