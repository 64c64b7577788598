#include <map>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/geometry.h"

namespace armmimic {
namespace {

cv::Mat FromRows(const std::vector<std::vector<int>>& rows) {
  cv::Mat m(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()), CV_8UC1);
  for (int y = 0; y < m.rows; ++y) {
    for (int x = 0; x < m.cols; ++x) m.at<uint8_t>(y, x) = static_cast<uint8_t>(rows[y][x]);
  }
  return m;
}

std::vector<std::vector<int>> ToRows(const cv::Mat& labels) {
  std::vector<std::vector<int>> rows(labels.rows, std::vector<int>(labels.cols));
  for (int y = 0; y < labels.rows; ++y) {
    for (int x = 0; x < labels.cols; ++x) rows[y][x] = labels.at<int32_t>(y, x);
  }
  return rows;
}

TEST(MaskComponents, FourConnectedNotEight) {
  const cv::Mat mask = FromRows({
      {1, 1, 0, 0, 0},
      {1, 0, 0, 1, 0},
      {0, 1, 0, 1, 1},
      {0, 0, 1, 0, 0},
  });
  cv::Mat labels;
  const std::vector<Component> comps = MaskComponents(mask, &labels);
  // 8-connectivity would join the diagonal chain (0,1)-(1,2)-(2,3) and the top-left L.
  ASSERT_EQ(comps.size(), 4u);
  EXPECT_EQ(ToRows(labels), (std::vector<std::vector<int>>{
                                {1, 1, 0, 0, 0},
                                {1, 0, 0, 2, 0},
                                {0, 3, 0, 2, 2},
                                {0, 0, 4, 0, 0},
                            }));
  EXPECT_EQ(comps[0].label, 1);
  EXPECT_EQ(comps[0].area_px, 3);
  EXPECT_EQ(comps[0].box, cv::Rect(0, 0, 2, 2));
  EXPECT_EQ(comps[0].seed, cv::Point(0, 0));
  EXPECT_EQ(comps[1].area_px, 3);
  EXPECT_EQ(comps[1].box, cv::Rect(3, 1, 2, 2));
  EXPECT_EQ(comps[1].seed, cv::Point(3, 1));
  EXPECT_EQ(comps[2].seed, cv::Point(1, 2));
  EXPECT_EQ(comps[3].box, cv::Rect(2, 3, 1, 1));
}

TEST(MaskComponents, AgreesWithOpenCvFourConnectivity) {
  cv::RNG rng(3);
  cv::Mat noise(120, 160, CV_8UC1);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::Mat mask = noise > 140;
  cv::Mat labels;
  const std::vector<Component> comps = MaskComponents(mask, &labels);
  cv::Mat ref_labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, ref_labels, stats, centroids, 4, CV_32S);
  ASSERT_EQ(static_cast<int>(comps.size()), n - 1);
  // The two labellings are the same partition: a one-to-one map between labels.
  std::map<int, int> mine_to_ref, ref_to_mine;
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      const int a = labels.at<int32_t>(y, x);
      const int b = ref_labels.at<int32_t>(y, x);
      ASSERT_EQ(a == 0, b == 0);
      if (a == 0) continue;
      ASSERT_EQ(mine_to_ref.emplace(a, b).first->second, b);
      ASSERT_EQ(ref_to_mine.emplace(b, a).first->second, a);
    }
  }
  for (const Component& c : comps) {
    const int r = mine_to_ref.at(c.label);
    EXPECT_EQ(c.area_px, stats.at<int>(r, cv::CC_STAT_AREA));
    EXPECT_EQ(c.box,
              cv::Rect(stats.at<int>(r, cv::CC_STAT_LEFT), stats.at<int>(r, cv::CC_STAT_TOP),
                       stats.at<int>(r, cv::CC_STAT_WIDTH), stats.at<int>(r, cv::CC_STAT_HEIGHT)));
  }
}

TEST(FloodFillComponents, RangeIsRelativeToTheSeed) {
  // A ramp: each step is within 10 of its neighbour, but the range counts from the seed.
  const cv::Mat ramp = FromRows({{10, 20, 30, 40, 50, 60}});
  cv::Mat labels;
  const std::vector<Component> comps = FloodFillComponents(ramp, 0, 255, 15, &labels);
  EXPECT_EQ(ToRows(labels), (std::vector<std::vector<int>>{{1, 1, 2, 2, 3, 3}}));
  ASSERT_EQ(comps.size(), 3u);
  EXPECT_EQ(comps[1].seed, cv::Point(2, 0));
  EXPECT_EQ(comps[1].area_px, 2);
  // Range 0: only equal values join.
  EXPECT_EQ(FloodFillComponents(FromRows({{7, 7, 8, 7}}), 0, 255, 0, &labels).size(), 3u);
}

TEST(FloodFillComponents, ValueWindowBoundsSeedsAndGrowth) {
  const cv::Mat img = FromRows({
      {100, 105, 250, 100},
      {0, 110, 250, 95},
      {100, 100, 100, 100},
  });
  cv::Mat labels;
  const std::vector<Component> comps = FloodFillComponents(img, 90, 200, 20, &labels);
  // 250 and 0 are outside [90, 200]: never labelled, and they do not conduct.
  EXPECT_EQ(ToRows(labels), (std::vector<std::vector<int>>{
                                {1, 1, 0, 1},
                                {0, 1, 0, 1},
                                {1, 1, 1, 1},
                            }));
  ASSERT_EQ(comps.size(), 1u);
  EXPECT_EQ(comps[0].area_px, 9);
  EXPECT_EQ(comps[0].box, cv::Rect(0, 0, 4, 3));
  // Null labels are allowed; an empty image gives nothing.
  EXPECT_EQ(FloodFillComponents(img, 240, 255, 0, nullptr).size(), 1u);
  EXPECT_TRUE(MaskComponents(cv::Mat(), &labels).empty());
  EXPECT_THROW(MaskComponents(cv::Mat(3, 3, CV_32F), &labels), std::invalid_argument);
}

}  // namespace
}  // namespace armmimic
