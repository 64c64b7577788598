#include "armmimic/core/image_io.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "test_util.h"

namespace armmimic {
namespace {

void ExpectErrorNames(const Status& st, const std::string& named) {
  EXPECT_FALSE(st.ok());
  EXPECT_NE(st.message().find(named), std::string::npos) << st.message();
}

TEST(ImageIo, WriteThenReadRoundTripsLosslessFormats) {
  test::TempDir dir;
  cv::Mat img(30, 40, CV_8UC3);
  cv::randu(img, 0, 256);
  for (const char* name : {"a.png", "b.bmp", "c.ppm", "d.tiff"}) {
    SCOPED_TRACE(name);
    const std::string path = dir.file(name);
    ASSERT_TRUE(WriteImageAtomically(path, img).ok());
    cv::Mat back;
    ASSERT_TRUE(ReadImage(path, &back).ok());
    EXPECT_EQ(cv::norm(back, img, cv::NORM_INF), 0);
  }
  // Nothing but the four images is left behind (no temporaries).
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 4);
}

TEST(ImageIo, ReadConvertsGreyToBgr) {
  test::TempDir dir;
  cv::Mat grey(10, 12, CV_8UC1, cv::Scalar(77));
  ASSERT_TRUE(cv::imwrite(dir.file("g.png"), grey));
  cv::Mat bgr;
  ASSERT_TRUE(ReadImage(dir.file("g.png"), &bgr).ok());
  EXPECT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.at<cv::Vec3b>(5, 5), cv::Vec3b(77, 77, 77));
  cv::Mat wide(10, 12, CV_16UC1, cv::Scalar(65535));
  ASSERT_TRUE(cv::imwrite(dir.file("w.png"), wide));
  ASSERT_TRUE(ReadImage(dir.file("w.png"), &bgr).ok());
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(255, 255, 255));
}

TEST(ImageIo, ReadErrorsNameTheFile) {
  test::TempDir dir;
  cv::Mat out;
  ExpectErrorNames(ReadImage(dir.file("missing.png"), &out), dir.file("missing.png"));
  test::WriteFile(dir.file("zero.png"), "");
  ExpectErrorNames(ReadImage(dir.file("zero.png"), &out), dir.file("zero.png"));
  test::WriteFile(dir.file("text.png"), "plain text, not pixels");
  ExpectErrorNames(ReadImage(dir.file("text.png"), &out), dir.file("text.png"));
  ExpectErrorNames(ReadImage(dir.path(), &out), dir.path());
  EXPECT_TRUE(out.empty());
}

TEST(ImageIo, WriteErrorsNameTheDirectoryOrExtension) {
  test::TempDir dir;
  const cv::Mat img(4, 4, CV_8UC3, cv::Scalar::all(1));
  const std::string nodir = dir.file("no/such/dir");
  ExpectErrorNames(WriteImageAtomically(nodir + "/x.png", img), nodir);
  ExpectErrorNames(WriteImageAtomically(dir.file("x.xyz"), img), ".xyz");
  ExpectErrorNames(WriteImageAtomically(dir.file("noext"), img), dir.file("noext"));
  ExpectErrorNames(WriteImageAtomically(dir.file("e.png"), cv::Mat()), dir.file("e.png"));
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.xyz")));
}

TEST(ImageIo, ImageExtensionsAreCaseInsensitive) {
  for (const char* p :
       {"a.png", "b.JPG", "c.jpeg", "d.Bmp", "e.tif", "f.TIFF", "g.pgm", "h.ppm", "dir.v/i.png"}) {
    EXPECT_TRUE(HasImageExtension(p)) << p;
  }
  for (const char* p : {"a.avi", "png", "a.png.txt", "dir.png/file", ""}) {
    EXPECT_FALSE(HasImageExtension(p)) << p;
  }
}

}  // namespace
}  // namespace armmimic
