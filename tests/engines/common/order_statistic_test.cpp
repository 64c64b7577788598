// KthSmallest against std::nth_element: every rank of arrays of many sizes, with ties, runs of
// one value and sorted input.
#include "common/order_statistic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace armmimic::arm {
namespace {

float Reference(std::vector<float> v, std::size_t k) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

void ExpectEveryRank(const std::vector<float>& v) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    std::vector<float> w = v;
    ASSERT_EQ(KthSmallest(w.data(), w.size(), k), Reference(v, k))
        << "n " << v.size() << " k " << k;
  }
}

TEST(KthSmallestTest, EqualsNthElementOnNoisyRatios) {
  std::mt19937 rng(11);
  std::normal_distribution<float> ratio(1.0f, 0.08f);
  for (std::size_t n : {1, 2, 3, 23, 24, 25, 26, 60, 100, 144, 145, 500}) {
    std::vector<float> v(n);
    for (float& x : v) x = ratio(rng);
    ExpectEveryRank(v);
  }
}

TEST(KthSmallestTest, EqualsNthElementWithTiesAndOrder) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> level(0, 6);
  for (std::size_t n : {30, 100, 144}) {
    std::vector<float> ties(n);
    for (float& x : ties) x = static_cast<float>(level(rng)) / 4;  // a few values, many times
    ExpectEveryRank(ties);
    ExpectEveryRank(std::vector<float>(n, 1.25f));  // one value
    std::vector<float> sorted = ties;
    std::sort(sorted.begin(), sorted.end());
    ExpectEveryRank(sorted);
    std::reverse(sorted.begin(), sorted.end());
    ExpectEveryRank(sorted);
  }
}

// Unspecified but finite work: a NaN pivot used to leave every partition empty, for ever.
TEST(KthSmallestTest, ReturnsOneOfTheValuesWithANaNAmongThem) {
  std::vector<float> v(100, std::numeric_limits<float>::quiet_NaN());
  for (std::size_t i = 0; i < v.size(); i += 3) v[i] = static_cast<float>(i);
  auto numbers = [](std::vector<float> x) {
    x.erase(std::remove_if(x.begin(), x.end(), [](float f) { return std::isnan(f); }), x.end());
    std::sort(x.begin(), x.end());
    return x;
  };
  for (std::size_t k : {0, 50, 99}) {
    std::vector<float> w = v;
    const float r = KthSmallest(w.data(), w.size(), k);
    EXPECT_TRUE(std::isnan(r) || std::find(v.begin(), v.end(), r) != v.end()) << r;
    EXPECT_EQ(numbers(w), numbers(v));  // reordered, nothing lost
  }
}

// The calibrations' quantile: the value at rank round(q (n - 1)), whatever the order given.
TEST(NearestRankQuantileTest, TakesTheNearestRank) {
  const std::vector<double> v = {7, 1, 9, 3, 5};  // sorted: 1 3 5 7 9
  EXPECT_EQ(NearestRankQuantile(v, 0.0), 1);
  EXPECT_EQ(NearestRankQuantile(v, 0.5), 5);
  EXPECT_EQ(NearestRankQuantile(v, 0.8), 7);  // rank round(3.2) = 3
  EXPECT_EQ(NearestRankQuantile(v, 1.0), 9);
  EXPECT_EQ(NearestRankQuantile({4, 2, 8, 6}, 0.5), 6);  // rank round(1.5) = 2
  EXPECT_TRUE(std::isnan(NearestRankQuantile({}, 0.5)));
}

}  // namespace
}  // namespace armmimic::arm
