#include <algorithm>
#include <set>
#include <utility>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/geometry.h"

namespace armmimic {
namespace {

std::set<std::pair<int, int>> AsSet(const std::vector<cv::Point>& pts) {
  std::set<std::pair<int, int>> s;
  for (const auto& p : pts) s.insert({p.x, p.y});
  return s;
}

double SignedArea(const std::vector<cv::Point>& poly) {
  double a = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const cv::Point& p = poly[i];
    const cv::Point& q = poly[(i + 1) % poly.size()];
    a += double(p.x) * q.y - double(q.x) * p.y;
  }
  return a / 2;
}

// Checks that `hull` is strictly convex, keeps every point inside, and starts left-most.
void ExpectValidHull(const std::vector<cv::Point>& points, const std::vector<cv::Point>& hull) {
  ASSERT_GE(hull.size(), 3u);
  const size_t n = hull.size();
  for (size_t i = 0; i < n; ++i) {
    const cv::Point& a = hull[i];
    const cv::Point& b = hull[(i + 1) % n];
    const cv::Point& c = hull[(i + 2) % n];
    EXPECT_GT(double(b.x - a.x) * (c.y - a.y) - double(b.y - a.y) * (c.x - a.x), 0)
        << "hull turns the wrong way or has a collinear vertex at " << b;
  }
  std::vector<cv::Point> poly(hull);
  for (const auto& p : points) {
    EXPECT_GE(cv::pointPolygonTest(poly, cv::Point2f(p), false), 0) << p << " outside the hull";
  }
  for (const auto& p : hull) {
    EXPECT_TRUE(hull[0].x < p.x || (hull[0].x == p.x && hull[0].y <= p.y));
  }
}

TEST(ConvexHull, SameVertexSetAsOpenCvOnRandomPointSets) {
  cv::RNG rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = rng.uniform(3, 250);
    const int span = trial % 3 == 0 ? 12 : 400;  // small spans force duplicates and collinearity
    std::vector<cv::Point> pts(n);
    for (auto& p : pts) p = {rng.uniform(0, span), rng.uniform(0, span)};
    std::vector<cv::Point> ref;
    cv::convexHull(pts, ref, /*clockwise=*/false, /*returnPoints=*/true);
    const std::vector<cv::Point> mine = ConvexHull(pts);
    SCOPED_TRACE(trial);
    EXPECT_EQ(AsSet(mine), AsSet(ref));
    EXPECT_EQ(mine.size(), AsSet(mine).size()) << "a vertex repeats";
    if (AsSet(ref).size() >= 3) {
      ExpectValidHull(pts, mine);
      // Same orientation as OpenCV's default (clockwise=false).
      EXPECT_EQ(SignedArea(mine) > 0, SignedArea(ref) > 0);
    }
  }
}

TEST(ConvexHull, IndicesPointIntoTheInput) {
  const std::vector<cv::Point> pts = {{5, 5}, {0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 7}};
  const std::vector<int> idx = ConvexHullIndices(pts);
  ASSERT_EQ(idx.size(), 4u);
  EXPECT_EQ(idx[0], 1);  // left-most, then top-most
  std::set<int> s(idx.begin(), idx.end());
  EXPECT_EQ(s, (std::set<int>{1, 2, 3, 4}));
}

TEST(ConvexHull, DegenerateInputs) {
  EXPECT_TRUE(ConvexHullIndices({}).empty());
  EXPECT_EQ(ConvexHull({{3, 4}}), (std::vector<cv::Point>{{3, 4}}));
  // Duplicates only: one point.
  EXPECT_EQ(ConvexHull({{3, 4}, {3, 4}, {3, 4}}), (std::vector<cv::Point>{{3, 4}}));
  // Two distinct points.
  EXPECT_EQ(AsSet(ConvexHull({{9, 1}, {2, 2}, {9, 1}})), AsSet({{2, 2}, {9, 1}}));
  // Collinear: the two extremes, whatever the order and repeats.
  EXPECT_EQ(AsSet(ConvexHull({{4, 4}, {0, 0}, {2, 2}, {8, 8}, {6, 6}, {2, 2}})),
            AsSet({{0, 0}, {8, 8}}));
  EXPECT_EQ(AsSet(ConvexHull({{5, 9}, {5, 1}, {5, 3}})), AsSet({{5, 1}, {5, 9}}));
  // Points on the hull's edges are not vertices.
  EXPECT_EQ(AsSet(ConvexHull({{0, 0}, {5, 0}, {10, 0}, {10, 5}, {10, 10}, {5, 10}, {0, 10}})),
            AsSet({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
}

// The outer contour of the largest blob of a random union of discs and bars.
std::vector<cv::Point> RandomBlobContour(cv::RNG& rng) {
  cv::Mat mask(240, 320, CV_8UC1, cv::Scalar(0));
  const cv::Point c(160, 120);
  cv::circle(mask, c, rng.uniform(15, 40), cv::Scalar(255), cv::FILLED);
  const int arms = rng.uniform(2, 6);
  for (int i = 0; i < arms; ++i) {
    const double a = rng.uniform(0.0, 2 * CV_PI);
    const double len = rng.uniform(40.0, 110.0);
    const cv::Point tip(c.x + int(len * std::cos(a)), c.y + int(len * std::sin(a)));
    cv::line(mask, c, tip, cv::Scalar(255), rng.uniform(6, 20));
    cv::circle(mask, tip, rng.uniform(4, 15), cv::Scalar(255), cv::FILLED);
  }
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  return *std::max_element(contours.begin(), contours.end(),
                           [](const auto& a, const auto& b) { return a.size() < b.size(); });
}

TEST(ConvexityDefects, SameAsOpenCvForTheSameHull) {
  cv::RNG rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(trial);
    const std::vector<cv::Point> contour = RandomBlobContour(rng);
    std::vector<int> cv_hull;
    cv::convexHull(contour, cv_hull, false, false);
    std::vector<cv::Vec4i> ref;
    cv::convexityDefects(contour, cv_hull, ref);
    const std::vector<ConvexityDefect> mine = ConvexityDefects(contour, cv_hull);
    ASSERT_EQ(mine.size(), ref.size());
    std::sort(ref.begin(), ref.end(),
              [](const cv::Vec4i& a, const cv::Vec4i& b) { return a[3] > b[3]; });
    for (size_t i = 0; i < ref.size(); ++i) {
      EXPECT_NEAR(mine[i].depth_px, ref[i][3] / 256.0, 1.0 / 256 + 1e-9);
    }
  }
}

TEST(ConvexityDefects, OwnHullGivesOpenCvDepthsWithinOnePixel) {
  cv::RNG rng(9);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(trial);
    const std::vector<cv::Point> contour = RandomBlobContour(rng);
    std::vector<int> cv_hull;
    cv::convexHull(contour, cv_hull, false, false);
    std::vector<cv::Vec4i> ref;
    cv::convexityDefects(contour, cv_hull, ref);
    std::vector<double> ref_depths;
    for (const auto& d : ref) {
      if (d[3] / 256.0 >= 2.0) ref_depths.push_back(d[3] / 256.0);
    }
    std::sort(ref_depths.rbegin(), ref_depths.rend());

    const std::vector<ConvexityDefect> mine = ConvexityDefects(contour, ConvexHullIndices(contour));
    std::vector<double> depths;
    for (const auto& d : mine) {
      EXPECT_LT(d.start_index, static_cast<int>(contour.size()));
      EXPECT_GE(d.depth_px, 0);
      if (d.depth_px >= 2.0) depths.push_back(d.depth_px);
    }
    ASSERT_EQ(depths.size(), ref_depths.size());
    for (size_t i = 0; i < depths.size(); ++i) EXPECT_NEAR(depths[i], ref_depths[i], 1.0);
    for (size_t i = 1; i < mine.size(); ++i) EXPECT_GE(mine[i - 1].depth_px, mine[i].depth_px);
  }
}

TEST(ConvexityDefects, NotchOfKnownDepth) {
  // A 40x40 square with a V notch 15 px deep cut into its top edge.
  const std::vector<cv::Point> contour = {{0, 0},  {15, 0},  {20, 15}, {25, 0},
                                          {40, 0}, {40, 40}, {0, 40}};
  const std::vector<ConvexityDefect> d = ConvexityDefects(contour, ConvexHullIndices(contour));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(contour[d[0].deepest_index], cv::Point(20, 15));
  EXPECT_DOUBLE_EQ(d[0].depth_px, 15);
  EXPECT_TRUE(ConvexityDefects({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {0, 1, 2, 3}).empty());
  EXPECT_TRUE(ConvexityDefects({}, {}).empty());
}

}  // namespace
}  // namespace armmimic
