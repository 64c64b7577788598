#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/geometry.h"

namespace armmimic {
namespace {

TEST(MedianFilter, ThesisFigure38NeighbourhoodGives37) {
  cv::Mat img = (cv::Mat_<uint8_t>(3, 3) << 10, 25, 37, 42, 100, 33, 38, 55, 20);
  const cv::Mat out = MedianFilter(img, 3);
  EXPECT_EQ(out.at<uint8_t>(1, 1), 37);  // the noisy 100 in the centre is replaced
}

TEST(MedianFilter, AgreesWithOpenCvMedianBlur) {
  cv::RNG rng(21);
  cv::Mat img(97, 131, CV_8UC1);
  rng.fill(img, cv::RNG::UNIFORM, 0, 256);
  for (int k : {3, 5}) {
    SCOPED_TRACE(k);
    cv::Mat ref;
    cv::medianBlur(img, ref, k);
    cv::Mat out;
    MedianFilter(img, k, &out);
    ASSERT_EQ(out.size(), img.size());
    ASSERT_EQ(out.type(), CV_8UC1);
    const cv::Rect inner(k / 2, k / 2, img.cols - 2 * (k / 2), img.rows - 2 * (k / 2));
    EXPECT_EQ(cv::countNonZero(out(inner) != ref(inner)), 0);
  }
}

// Reference: sort each replicated-border neighbourhood.
cv::Mat SortedMedian(const cv::Mat& img, int k) {
  cv::Mat padded;
  cv::copyMakeBorder(img, padded, k / 2, k / 2, k / 2, k / 2,
                     cv::BORDER_REPLICATE | cv::BORDER_ISOLATED);
  cv::Mat out(img.size(), CV_8UC1);
  std::vector<uint8_t> v;
  for (int y = 0; y < img.rows; ++y) {
    for (int x = 0; x < img.cols; ++x) {
      v.clear();
      for (int dy = 0; dy < k; ++dy) {
        for (int dx = 0; dx < k; ++dx) v.push_back(padded.at<uint8_t>(y + dy, x + dx));
      }
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      out.at<uint8_t>(y, x) = v[v.size() / 2];
    }
  }
  return out;
}

TEST(MedianFilter, EveryPixelMatchesTheSortedNeighbourhood) {
  cv::RNG rng(4);
  for (const cv::Size size : {cv::Size(40, 30), cv::Size(7, 5), cv::Size(33, 3), cv::Size(1, 1)}) {
    cv::Mat img(size, CV_8UC1);
    rng.fill(img, cv::RNG::UNIFORM, 0, 256);
    for (int k : {3, 5, 7}) {
      SCOPED_TRACE(testing::Message() << size << " k=" << k);
      EXPECT_EQ(cv::countNonZero(MedianFilter(img, k) != SortedMedian(img, k)), 0);
    }
  }
}

TEST(MedianFilter, RoiReplicatesItsOwnEdge) {
  cv::Mat big(20, 20, CV_8UC1, cv::Scalar(200));
  cv::Mat inner = big(cv::Rect(5, 5, 10, 10));
  inner.setTo(10);
  // Outside the ROI everything is 200; inside 10. A standalone 10x10 image of 10s stays 10.
  const cv::Mat out = MedianFilter(inner, 5);
  EXPECT_EQ(cv::countNonZero(out != 10), 0);
}

TEST(MedianFilter, RejectsEvenWindowAndWrongType) {
  const cv::Mat img(8, 8, CV_8UC1, cv::Scalar(3));
  EXPECT_THROW(MedianFilter(img, 4), std::invalid_argument);
  EXPECT_THROW(MedianFilter(img, 0), std::invalid_argument);
  EXPECT_THROW(MedianFilter(cv::Mat(8, 8, CV_8UC3), 3), std::invalid_argument);
  EXPECT_EQ(cv::countNonZero(MedianFilter(img, 1) != img), 0);
}

}  // namespace
}  // namespace armmimic
