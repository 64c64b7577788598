#include "armmimic/robot/filter.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

namespace armmimic::robot {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Filter, PassesConstantsAndRampsUnchanged) {
  std::vector<double> c(100, -42.0), ramp(100);
  for (int i = 0; i < 100; ++i) ramp[i] = 3.0 * i - 50;
  const auto fc = ZeroPhaseLowPass(c, 30, 3);
  const auto fr = ZeroPhaseLowPass(ramp, 30, 3);
  for (int i = 0; i < 100; ++i) {
    EXPECT_NEAR(fc[i], -42.0, 1e-9);
    EXPECT_NEAR(fr[i], ramp[i], 1e-4) << i;
  }
}

TEST(Filter, RemovesNoiseWithoutDelayingTheMotion) {
  // A 0.5 Hz arm swing plus seeded measurement noise; the filtered series is closer to the
  // truth and shows no lag (zero phase): the error is not systematically ahead or behind.
  const double fs = 30;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 3);
  std::vector<double> truth(300), noisy(300);
  for (int i = 0; i < 300; ++i) {
    truth[i] = 40 * std::sin(2 * kPi * 0.5 * i / fs);
    noisy[i] = truth[i] + noise(rng);
  }
  const auto f = ZeroPhaseLowPass(noisy, fs, 3);
  double raw_rms = 0, filt_rms = 0, lag_corr = 0;
  for (int i = 0; i < 300; ++i) {
    raw_rms += (noisy[i] - truth[i]) * (noisy[i] - truth[i]);
    filt_rms += (f[i] - truth[i]) * (f[i] - truth[i]);
    // Correlation of the error with the truth's derivative: a lagging filter correlates.
    const double d = std::cos(2 * kPi * 0.5 * i / fs);
    lag_corr += (f[i] - truth[i]) * d;
  }
  raw_rms = std::sqrt(raw_rms / 300);
  filt_rms = std::sqrt(filt_rms / 300);
  EXPECT_LT(filt_rms, 0.5 * raw_rms);
  EXPECT_LT(std::abs(lag_corr / 300), 0.3);
}

TEST(Filter, AttenuatesAboveTheCutoff) {
  const double fs = 30;
  std::vector<double> x(600);
  for (int i = 0; i < 600; ++i) x[i] = std::sin(2 * kPi * 10 * i / fs);
  const auto f = ZeroPhaseLowPass(x, fs, 2);
  double peak = 0;
  for (int i = 100; i < 500; ++i) peak = std::max(peak, std::abs(f[i]));
  EXPECT_LT(peak, 0.05);
}

TEST(Filter, ZeroCutoffIsOffAndBadCutoffThrows) {
  const std::vector<double> x = {1, 5, 2};
  EXPECT_EQ(ZeroPhaseLowPass(x, 30, 0), x);
  EXPECT_THROW(ZeroPhaseLowPass(x, 30, 15), std::invalid_argument);
  EXPECT_EQ(ZeroPhaseLowPass({7.0}, 30, 3), std::vector<double>{7.0});
}

TEST(Filter, UnwrapMakesAnglesContinuous) {
  const auto u = UnwrapDeg({170, -175, -160, std::nan(""), 170, -90});
  EXPECT_DOUBLE_EQ(u[1], 185);
  EXPECT_DOUBLE_EQ(u[2], 200);
  EXPECT_TRUE(std::isnan(u[3]));
  EXPECT_DOUBLE_EQ(u[4], 170);
  EXPECT_DOUBLE_EQ(u[5], 270);
}

}  // namespace
}  // namespace armmimic::robot
