// The row kernels against the plain per-value expressions they replace: every length up to a few
// vector steps (the tails), random bytes and gains (quotients on the .5 boundaries, gains so
// small the quotient overflows an int), and backgrounds on both sides of each value.
#include "common/pixel_rows.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace armmimic::arm {
namespace {

TEST(PixelRowsTest, DivideRowEqualsSaturateCastOfTheQuotient) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_real_distribution<float> gain(0.4f, 2.5f);
  for (int n = 0; n <= 70; ++n) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<std::uint8_t> in(n), out(n, 7);
      std::vector<float> g(n);
      for (int i = 0; i < n; ++i) {
        in[i] = static_cast<std::uint8_t>(byte(rng));
        switch (i % 5) {
          case 0:
            g[i] = gain(rng);
            break;
          case 1:
            g[i] = in[i] / (byte(rng) + 0.5f);
            break;  // a quotient of x.5
          case 2:
            g[i] = 1e-30f;
            break;  // beyond any int
          case 3:
            g[i] = 0.5f;
            break;  // above 255
          default:
            g[i] = 1.f;
            break;
        }
        if (g[i] == 0.f) g[i] = 1.f;
      }
      DivideRow(in.data(), g.data(), out.data(), n);
      for (int i = 0; i < n; ++i) {
        ASSERT_EQ(out[i], cv::saturate_cast<uchar>(in[i] / g[i]))
            << "n " << n << " i " << i << " in " << int(in[i]) << " gain " << g[i];
      }
    }
  }
}

TEST(PixelRowsTest, SquaredOutsideRowEqualsTheBranchingDistance) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_real_distribution<float> level(-5.f, 260.f), width(0.f, 30.f);
  for (int n = 0; n <= 70; ++n) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<std::uint8_t> in(n);
      std::vector<float> lo(n), hi(n), out(n, -1.f);
      for (int i = 0; i < n; ++i) {
        in[i] = static_cast<std::uint8_t>(byte(rng));
        lo[i] = i % 7 == 0 ? static_cast<float>(in[i]) : level(rng);
        hi[i] = i % 11 == 0 ? static_cast<float>(in[i]) : lo[i] + width(rng);
        hi[i] = std::max(hi[i], lo[i]);
      }
      SquaredOutsideRow(in.data(), lo.data(), hi.data(), out.data(), n);
      for (int i = 0; i < n; ++i) {
        const float v = in[i];
        const float e = v < lo[i] ? lo[i] - v : (v > hi[i] ? v - hi[i] : 0.f);
        const float want = e * e;
        ASSERT_EQ(std::memcmp(&out[i], &want, sizeof want), 0)
            << "n " << n << " i " << i << " got " << out[i] << " want " << want;
      }
    }
  }
}

TEST(PixelRowsTest, EvidenceRowEqualsTheBranchingExpression) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> change(-1.f, 60.f), prob(0.f, 1.f);
  const float low = 9.5f, inv = 1.f / 12.f, share = 0.6f;
  for (int n = 0; n <= 40; ++n) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<float> d(n), p(n);
      for (int i = 0; i < n; ++i) {
        d[i] = i % 5 == 0 ? -1.f : (i % 7 == 0 ? low : change(rng));  // unknown; on the bound
        p[i] = prob(rng);
      }
      std::vector<float> out = p;
      EvidenceRow(d.data(), out.data(), n, low, inv, share);
      for (int i = 0; i < n; ++i) {
        const float want =
            d[i] < 0 ? share * p[i] : p[i] * std::clamp((d[i] - low) * inv, 0.f, 1.f);
        ASSERT_EQ(std::memcmp(&out[i], &want, sizeof want), 0)
            << "n " << n << " i " << i << " got " << out[i] << " want " << want;
      }
    }
  }
}

}  // namespace
}  // namespace armmimic::arm
