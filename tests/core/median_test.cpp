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

TEST(MedianFilter, LargeWindowMatchesSortedNeighbourhood) {
  cv::RNG rng(4);
  cv::Mat img(30, 40, CV_8UC1);
  rng.fill(img, cv::RNG::UNIFORM, 0, 256);
  const int k = 7;
  const cv::Mat out = MedianFilter(img, k);
  cv::Mat padded;
  cv::copyMakeBorder(img, padded, k / 2, k / 2, k / 2, k / 2, cv::BORDER_REPLICATE);
  for (int y = 0; y < img.rows; ++y) {
    for (int x = 0; x < img.cols; ++x) {
      std::vector<uint8_t> v;
      for (int dy = 0; dy < k; ++dy) {
        for (int dx = 0; dx < k; ++dx) v.push_back(padded.at<uint8_t>(y + dy, x + dx));
      }
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      ASSERT_EQ(out.at<uint8_t>(y, x), v[v.size() / 2]) << "at " << x << "," << y;
    }
  }
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
