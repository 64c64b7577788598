#include "armmimic/core/video_source.h"

#include <cmath>
#include <cstdint>
#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "test_util.h"

namespace armmimic {
namespace {

constexpr double kFps = 25;
const cv::Size kSize(160, 120);

// Frame i shows a flat grey level that identifies it after lossy compression.
cv::Mat NumberedFrame(int i, cv::Size size = kSize) {
  return cv::Mat(size, CV_8UC3, cv::Scalar::all(10 + 8 * i));
}

int FrameNumber(const cv::Mat& bgr) {
  return static_cast<int>(std::lround((cv::mean(bgr)[1] - 10) / 8));
}

// Writes `n` numbered frames; false when this build has no encoder for `fourcc`.
bool WriteVideo(const std::string& path, int n, const char* fourcc = "MJPG") {
  cv::VideoWriter w(path, cv::VideoWriter::fourcc(fourcc[0], fourcc[1], fourcc[2], fourcc[3]), kFps,
                    kSize);
  if (!w.isOpened()) return false;
  for (int i = 0; i < n; ++i) w.write(NumberedFrame(i));
  return true;
}

std::unique_ptr<VideoSource> OpenOk(const std::vector<std::string>& inputs) {
  Status st;
  auto src = VideoSource::Open(inputs, &st);
  EXPECT_TRUE(st.ok()) << st.message();
  EXPECT_NE(src, nullptr);
  return src;
}

// Opening must fail with a message that names `named`.
std::string OpenError(const std::vector<std::string>& inputs, const std::string& named) {
  Status st;
  auto src = VideoSource::Open(inputs, &st);
  EXPECT_EQ(src, nullptr);
  EXPECT_FALSE(st.ok());
  EXPECT_NE(st.message().find(named), std::string::npos) << st.message();
  return st.message();
}

// Offsets of the frame chunks ("##dc") inside an AVI's movi list.
std::vector<size_t> AviFrameChunks(const std::string& bytes) {
  std::vector<size_t> chunks;
  size_t pos = bytes.find("movi");
  if (pos == std::string::npos) return chunks;
  pos += 4;
  while (pos + 8 <= bytes.size()) {
    const auto* p = reinterpret_cast<const uint8_t*>(bytes.data() + pos + 4);
    const uint32_t size = p[0] | p[1] << 8 | p[2] << 16 | uint32_t(p[3]) << 24;
    if (bytes.compare(pos + 2, 2, "dc") == 0) chunks.push_back(pos);
    if (bytes.compare(pos, 4, "idx1") == 0) break;
    pos += 8 + size + (size & 1);
  }
  return chunks;
}

void ExpectReadsAll(VideoSource* src, int n, double fps) {
  Frame f;
  Status st;
  for (int i = 0; i < n; ++i) {
    ASSERT_TRUE(src->Read(&f, &st)) << "frame " << i << ": " << st.message();
    EXPECT_EQ(f.index, i);
    EXPECT_EQ(FrameNumber(f.image), i);
    EXPECT_EQ(f.image.type(), CV_8UC3);
    EXPECT_EQ(f.image.size(), kSize);
    EXPECT_DOUBLE_EQ(f.time_s, fps > 0 ? i / fps : 0);
  }
  EXPECT_FALSE(src->Read(&f, &st));
  EXPECT_TRUE(st.ok()) << st.message();
}

TEST(VideoSource, MjpgAviReportsInfoAndReadsEveryFrameInOrder) {
  test::TempDir dir;
  const std::string path = dir.file("scene.avi");
  ASSERT_TRUE(WriteVideo(path, 20));
  auto src = OpenOk({path});
  ASSERT_TRUE(src);
  const VideoInfo& info = src->info();
  EXPECT_EQ(info.kind, SourceKind::kVideo);
  EXPECT_EQ(info.path, path);
  EXPECT_EQ(info.frame_count, 20);
  EXPECT_DOUBLE_EQ(info.fps, kFps);
  EXPECT_EQ(info.size, kSize);
  EXPECT_EQ(info.codec, "MJPG");
  ExpectReadsAll(src.get(), 20, kFps);
}

// Debian's OpenCV writes XVID through FFmpeg's MPEG-4 encoder, so the test never skips.
TEST(VideoSource, XvidAvi) {
  test::TempDir dir;
  const std::string path = dir.file("scene_xvid.avi");
  ASSERT_TRUE(WriteVideo(path, 12, "XVID")) << "no XVID encoder in this OpenCV build";
  auto src = OpenOk({path});
  ASSERT_TRUE(src);
  EXPECT_EQ(src->info().frame_count, 12);
  EXPECT_FALSE(src->info().codec.empty());
  ExpectReadsAll(src.get(), 12, kFps);
}

TEST(VideoSource, SeekForwardBackwardAndOutOfRange) {
  test::TempDir dir;
  const std::string path = dir.file("seek.avi");
  ASSERT_TRUE(WriteVideo(path, 25));
  auto src = OpenOk({path});
  ASSERT_TRUE(src);
  Frame f;
  Status st;
  for (int target : {0, 12, 13, 3, 24, 0, 20, 5}) {
    SCOPED_TRACE(target);
    ASSERT_TRUE(src->Seek(target).ok());
    ASSERT_TRUE(src->Read(&f, &st)) << st.message();
    EXPECT_EQ(f.index, target);
    EXPECT_EQ(FrameNumber(f.image), target);
    EXPECT_DOUBLE_EQ(f.time_s, target / kFps);
  }
  const Status bad = src->Seek(26);
  EXPECT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find(path), std::string::npos);
  EXPECT_FALSE(src->Seek(-1).ok());
}

TEST(VideoSource, MissingEmptyAndRandomFilesNameTheFile) {
  test::TempDir dir;
  OpenError({dir.file("nothere.avi")}, dir.file("nothere.avi"));
  test::WriteFile(dir.file("empty.avi"), "");
  EXPECT_NE(OpenError({dir.file("empty.avi")}, dir.file("empty.avi")).find("0 bytes"),
            std::string::npos);
  cv::RNG rng(1);
  std::string noise(20000, '\0');
  for (char& c : noise) c = static_cast<char>(rng.uniform(0, 256));
  test::WriteFile(dir.file("noise.avi"), noise);
  OpenError({dir.file("noise.avi")}, dir.file("noise.avi"));
  test::WriteFile(dir.file("notes.txt"), "hello");
  EXPECT_NE(OpenError({dir.file("notes.txt")}, dir.file("notes.txt")).find(".txt"),
            std::string::npos);
  OpenError({}, "no input");
}

TEST(VideoSource, AviWithZeroFramesIsAnError) {
  test::TempDir dir;
  const std::string path = dir.file("zero.avi");
  ASSERT_TRUE(WriteVideo(path, 0));
  ASSERT_TRUE(std::filesystem::exists(path));
  OpenError({path}, path);
}

TEST(VideoSource, TruncatedAvi) {
  test::TempDir dir;
  const std::string path = dir.file("full.avi");
  ASSERT_TRUE(WriteVideo(path, 20));
  const std::string bytes = test::ReadFile(path);
  const std::vector<size_t> chunks = AviFrameChunks(bytes);
  ASSERT_EQ(chunks.size(), 20u);

  // Cut inside frame 8: the header still announces 20, the stream ends early with an ok status.
  const std::string cut = dir.file("cut.avi");
  test::WriteFile(cut, bytes.substr(0, chunks[8] + 20));
  auto src = OpenOk({cut});
  ASSERT_TRUE(src);
  Frame f;
  Status st;
  int n = 0;
  while (src->Read(&f, &st)) {
    EXPECT_EQ(FrameNumber(f.image), n);
    ++n;
  }
  EXPECT_TRUE(st.ok()) << st.message();
  EXPECT_GE(n, 7);
  EXPECT_LE(n, 9);
  EXPECT_EQ(src->info().frame_count, n);  // corrected to what was decodable

  // Cut inside the header: nothing to decode.
  const std::string stub = dir.file("stub.avi");
  test::WriteFile(stub, bytes.substr(0, std::min<size_t>(200, chunks[0])));
  OpenError({stub}, stub);
}

TEST(VideoSource, DamagedFrameMidStreamNamesTheFrame) {
  test::TempDir dir;
  const std::string path = dir.file("damaged.avi");
  ASSERT_TRUE(WriteVideo(path, 20));
  std::string bytes = test::ReadFile(path);
  const std::vector<size_t> chunks = AviFrameChunks(bytes);
  ASSERT_EQ(chunks.size(), 20u);
  // Overwrite frame 11's JPEG data (its chunk header and size stay).
  const size_t data = chunks[11] + 8;
  for (size_t i = data; i < data + 300 && i < chunks[12]; ++i) bytes[i] = 0x55;
  test::WriteFile(path, bytes);

  auto src = OpenOk({path});
  ASSERT_TRUE(src);
  Frame f;
  Status st;
  for (int i = 0; i < 11; ++i) ASSERT_TRUE(src->Read(&f, &st)) << st.message();
  ASSERT_FALSE(src->Read(&f, &st));
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find(path), std::string::npos) << st.message();
  EXPECT_NE(st.message().find("frame 11"), std::string::npos) << st.message();
  // The caller may go on: the next frame is the one after the damage.
  ASSERT_TRUE(src->Read(&f, &st)) << st.message();
  EXPECT_EQ(f.index, 12);
  EXPECT_EQ(FrameNumber(f.image), 12);
}

TEST(VideoSource, FolderOfImagesSortedByNameWithGreyConverted) {
  test::TempDir dir;
  const std::string folder = dir.file("shots");
  std::filesystem::create_directory(folder);
  // Written out of order, mixed formats and case; a text file and a hidden file are ignored.
  ASSERT_TRUE(cv::imwrite(folder + "/img_02.JPG", NumberedFrame(2)));
  ASSERT_TRUE(cv::imwrite(folder + "/img_00.png", NumberedFrame(0)));
  cv::Mat grey(kSize, CV_8UC1, cv::Scalar(10 + 8 * 1));
  ASSERT_TRUE(cv::imwrite(folder + "/img_01.pgm", grey));
  ASSERT_TRUE(cv::imwrite(folder + "/img_03.bmp", NumberedFrame(3)));
  test::WriteFile(folder + "/readme.txt", "not an image");
  ASSERT_TRUE(cv::imwrite(folder + "/.hidden.png", NumberedFrame(9)));

  auto src = OpenOk({folder});
  ASSERT_TRUE(src);
  EXPECT_EQ(src->info().kind, SourceKind::kImages);
  EXPECT_EQ(src->info().frame_count, 4);
  EXPECT_EQ(src->info().fps, 0);
  EXPECT_EQ(src->info().size, kSize);
  const std::vector<std::string> names = {"img_00.png", "img_01.pgm", "img_02.JPG", "img_03.bmp"};
  Frame f;
  Status st;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(src->Read(&f, &st)) << st.message();
    EXPECT_EQ(f.name, names[i]);
    EXPECT_EQ(f.index, i);
    EXPECT_EQ(f.time_s, 0);
    EXPECT_EQ(f.image.type(), CV_8UC3);
    EXPECT_EQ(FrameNumber(f.image), i);
  }
  EXPECT_FALSE(src->Read(&f, &st));
  EXPECT_TRUE(st.ok());
  ASSERT_TRUE(src->Seek(1).ok());
  ASSERT_TRUE(src->Read(&f, &st));
  EXPECT_EQ(f.name, "img_01.pgm");
  ASSERT_TRUE(src->Seek(0).ok());
  ASSERT_TRUE(src->Read(&f, &st));
  EXPECT_EQ(f.name, "img_00.png");
  EXPECT_FALSE(src->Seek(5).ok());
}

TEST(VideoSource, ImageFilesKeepTheGivenOrder) {
  test::TempDir dir;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(cv::imwrite(dir.file("p" + std::to_string(i) + ".png"), NumberedFrame(i)));
  }
  auto src = OpenOk({dir.file("p2.png"), dir.file("p0.png"), dir.file("p1.png")});
  ASSERT_TRUE(src);
  EXPECT_EQ(src->info().frame_count, 3);
  Frame f;
  Status st;
  for (int expected : {2, 0, 1}) {
    ASSERT_TRUE(src->Read(&f, &st));
    EXPECT_EQ(FrameNumber(f.image), expected);
    EXPECT_EQ(f.name, "p" + std::to_string(expected) + ".png");
  }
  // A single image is a one-frame source.
  auto one = OpenOk({dir.file("p1.png")});
  ASSERT_TRUE(one);
  EXPECT_EQ(one->info().frame_count, 1);
}

TEST(VideoSource, BadImageInputsNameTheFile) {
  test::TempDir dir;
  const std::string folder = dir.file("empty_folder");
  std::filesystem::create_directory(folder);
  test::WriteFile(folder + "/notes.txt", "x");
  OpenError({folder}, folder);

  ASSERT_TRUE(cv::imwrite(dir.file("a.png"), NumberedFrame(0)));
  ASSERT_TRUE(cv::imwrite(dir.file("small.png"), NumberedFrame(1, {80, 60})));
  ASSERT_TRUE(cv::imwrite(dir.file("c.png"), NumberedFrame(2)));
  // Mixed sizes are found when opening, and the odd file is named.
  EXPECT_NE(OpenError({dir.file("a.png"), dir.file("small.png"), dir.file("c.png")},
                      dir.file("small.png"))
                .find("80x60"),
            std::string::npos);
  OpenError({dir.file("a.png"), dir.file("gone.png")}, dir.file("gone.png"));
  test::WriteFile(dir.file("zero.png"), "");
  OpenError({dir.file("a.png"), dir.file("zero.png")}, dir.file("zero.png"));
  ASSERT_TRUE(WriteVideo(dir.file("v.avi"), 2));
  OpenError({dir.file("a.png"), dir.file("v.avi")}, dir.file("v.avi"));
  test::WriteFile(dir.file("junk.png"), "this is not a png at all");
  OpenError({dir.file("junk.png")}, dir.file("junk.png"));

  // A broken image later in the sequence fails when it is read, naming it.
  auto src = OpenOk({dir.file("a.png"), dir.file("junk.png")});
  ASSERT_TRUE(src);
  Frame f;
  Status st;
  ASSERT_TRUE(src->Read(&f, &st));
  EXPECT_FALSE(src->Read(&f, &st));
  EXPECT_NE(st.message().find(dir.file("junk.png")), std::string::npos) << st.message();
  // A size that only decoding reveals (TIFF headers are not peeked) also names the file.
  ASSERT_TRUE(cv::imwrite(dir.file("odd.tif"), NumberedFrame(3, {100, 100})));
  auto mixed = OpenOk({dir.file("a.png"), dir.file("odd.tif")});
  ASSERT_TRUE(mixed);
  ASSERT_TRUE(mixed->Read(&f, &st));
  EXPECT_FALSE(mixed->Read(&f, &st));
  EXPECT_NE(st.message().find(dir.file("odd.tif")), std::string::npos) << st.message();
}

TEST(VideoSource, MixedSizesFoundFromEveryPeekedHeaderFormat) {
  test::TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir.file("first.png"), NumberedFrame(0)));
  for (const char* ext : {"jpg", "jpeg", "bmp", "pgm", "ppm", "png"}) {
    SCOPED_TRACE(ext);
    const std::string same = dir.file(std::string("same.") + ext);
    const std::string odd = dir.file(std::string("odd.") + ext);
    const bool grey = std::string(ext) == "pgm";  // PGM holds one channel only
    cv::Mat same_img = NumberedFrame(1);
    cv::Mat odd_img = NumberedFrame(1, {96, 72});
    if (grey) {
      cv::cvtColor(same_img, same_img, cv::COLOR_BGR2GRAY);
      cv::cvtColor(odd_img, odd_img, cv::COLOR_BGR2GRAY);
    }
    ASSERT_TRUE(cv::imwrite(same, same_img));
    ASSERT_TRUE(cv::imwrite(odd, odd_img));
    EXPECT_NE(OpenError({dir.file("first.png"), same, odd}, odd).find("96x72"), std::string::npos);
    EXPECT_TRUE(OpenOk({dir.file("first.png"), same}));
  }
}

TEST(VideoSource, CamerasAndStreamsThatCannotOpenAreNamed) {
  OpenError({"camera:x"}, "camera:x");
  OpenError({"camera:97"}, "camera:97");
  OpenError({"http://127.0.0.1:1/stream.mjpg"}, "http://127.0.0.1:1/stream.mjpg");
}

TEST(VideoSource, FramesInMemoryReadAndSeekLikeAVideo) {
  auto frames = std::make_shared<std::vector<cv::Mat>>();
  for (int i = 0; i < 5; ++i) frames->push_back(NumberedFrame(i));
  Status st;
  std::unique_ptr<VideoSource> src = VideoSource::FromFrames(frames, 25, "scene-7", &st);
  ASSERT_TRUE(src) << st.message();
  EXPECT_EQ(src->info().frame_count, 5);
  EXPECT_EQ(src->info().fps, 25);
  EXPECT_EQ(src->info().size, frames->front().size());
  EXPECT_EQ(src->info().path, "scene-7");
  ASSERT_TRUE(src->Seek(3).ok());
  Frame f;
  ASSERT_TRUE(src->Read(&f, &st));
  EXPECT_EQ(f.index, 3);
  EXPECT_DOUBLE_EQ(f.time_s, 3 / 25.0);
  EXPECT_EQ(cv::norm(f.image, (*frames)[3], cv::NORM_INF), 0);
  f.image.setTo(cv::Scalar::all(0));  // a reader's own copy: the held frame is untouched
  EXPECT_GT(cv::norm((*frames)[3], cv::NORM_INF), 0);
  ASSERT_TRUE(src->Read(&f, &st));
  EXPECT_FALSE(src->Read(&f, &st));
  EXPECT_TRUE(st.ok());
  EXPECT_NE(src->Seek(5).message().find("scene-7"), std::string::npos);
  EXPECT_FALSE(VideoSource::FromFrames(std::make_shared<std::vector<cv::Mat>>(), 25, "none", &st));
  EXPECT_NE(st.message().find("none"), std::string::npos);
}

}  // namespace
}  // namespace armmimic
