// The 1-euro filter (pose/one_euro.h) that smooths BlazePose's world landmarks and the crop's
// auxiliary landmarks: a still, noisy signal is steadied; a fast move is followed closely, where
// a filter of the still cut-off alone would lag far behind; a track placed afresh starts anew.
#include "pose/one_euro.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace armmimic::internal {
namespace {

TEST(OneEuroFilter, SteadiesAStillNoisySignal) {
  OneEuroFilter f(0.1, 40, 1);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 0.005);  // 5 mm of jitter on a joint at 0.3 m
  double raw = 0, filtered = 0;
  for (int i = 0; i < 300; ++i) {
    const double x = 0.3 + noise(rng);
    const double y = f.Apply(i / 30.0, x);
    if (i < 30) continue;
    raw += (x - 0.3) * (x - 0.3);
    filtered += (y - 0.3) * (y - 0.3);
  }
  std::printf("1-euro filter on a still joint: rms %.2f mm raw, %.2f mm filtered\n",
              1000 * std::sqrt(raw / 270), 1000 * std::sqrt(filtered / 270));
  EXPECT_LT(filtered, 0.5 * raw);
}

TEST(OneEuroFilter, FollowsAFastMoveWithoutTheStillCutoffsLag) {
  OneEuroFilter adaptive(0.1, 40, 1);
  OneEuroFilter still_only(0.1, 0, 1);
  double adaptive_y = 0, still_y = 0;
  // A joint moving at 1 m/s for half a second, seen at 30 frames per second.
  for (int i = 0; i <= 15; ++i) {
    adaptive_y = adaptive.Apply(i / 30.0, i / 30.0);
    still_y = still_only.Apply(i / 30.0, i / 30.0);
  }
  EXPECT_NEAR(adaptive_y, 0.5, 0.05);
  EXPECT_LT(still_y, 0.1);
}

TEST(OneEuroFilter, PassesTheFirstValueAndStartsAnewAfterAReset) {
  OneEuroFilter f(0.1, 40, 1);
  EXPECT_EQ(f.Apply(0, 2.0), 2.0);
  f.Apply(0.2, 2.0);
  f.Reset();
  EXPECT_EQ(f.Apply(0.4, -1.0), -1.0);
  // A time that does not move forward (a repeated frame) restarts rather than divide by zero.
  EXPECT_EQ(f.Apply(0.4, 5.0), 5.0);
}

}  // namespace
}  // namespace armmimic::internal
