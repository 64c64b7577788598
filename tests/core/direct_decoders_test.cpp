// Videos and PNG images are decoded with FFmpeg and libpng directly (src/core/ffmpeg_reader.h,
// png_reader.h), not through OpenCV's capture and image reader. The pixels must be the ones
// OpenCV gives for the same files, to the byte: every engine's figures were measured on those.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>
#include <zlib.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include "armmimic/core/image_io.h"
#include "armmimic/core/video_source.h"
#include "test_util.h"

namespace armmimic {
namespace {

// A frame with smooth colour, sharp edges and noise: chroma subsampling and the colour
// conversion's rounding show on every kind of pixel.
cv::Mat TexturedFrame(cv::Size size, int i) {
  cv::Mat img(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      img.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uchar>((x * 3 + i * 7) % 256),
                                          static_cast<uchar>((y * 5 + x) % 256),
                                          static_cast<uchar>((x * y + i * 11) % 256));
    }
  }
  cv::rectangle(img, cv::Rect(10 + i, 12, size.width / 3, size.height / 4), {20, 200, 90}, -1);
  cv::Mat noise(size, CV_8UC3);
  cv::randu(noise, 0, 24);
  img += noise;
  return img;
}

void ExpectFramesAsOpenCvDecodesThem(const std::string& fourcc, cv::Size size) {
  SCOPED_TRACE(fourcc + " " + std::to_string(size.width) + "x" + std::to_string(size.height));
  test::TempDir dir;
  const std::string path = dir.file("clip.avi");
  const int n = 14;
  {
    cv::VideoWriter w(path, cv::CAP_FFMPEG,
                      cv::VideoWriter::fourcc(fourcc[0], fourcc[1], fourcc[2], fourcc[3]), 30,
                      size);
    ASSERT_TRUE(w.isOpened()) << "no " << fourcc << " encoder in this OpenCV build";
    for (int i = 0; i < n; ++i) w.write(TexturedFrame(size, i));
  }
  cv::VideoCapture cap(path, cv::CAP_FFMPEG);
  ASSERT_TRUE(cap.isOpened());
  Status st;
  auto src = VideoSource::Open(path, &st);
  ASSERT_TRUE(src) << st.message();
  EXPECT_EQ(src->info().frame_count, static_cast<int>(cap.get(cv::CAP_PROP_FRAME_COUNT)));
  EXPECT_DOUBLE_EQ(src->info().fps, cap.get(cv::CAP_PROP_FPS));
  EXPECT_EQ(src->info().size, cv::Size(static_cast<int>(cap.get(cv::CAP_PROP_FRAME_WIDTH)),
                                       static_cast<int>(cap.get(cv::CAP_PROP_FRAME_HEIGHT))));
  int read = 0;
  cv::Mat expected;
  Frame frame;
  while (cap.read(expected)) {
    ASSERT_TRUE(src->Read(&frame, &st)) << "frame " << read << ": " << st.message();
    ASSERT_EQ(frame.image.size(), expected.size()) << "frame " << read;
    EXPECT_EQ(cv::norm(frame.image, expected, cv::NORM_INF), 0) << "frame " << read;
    ++read;
  }
  EXPECT_EQ(read, n);
  EXPECT_FALSE(src->Read(&frame, &st));
  EXPECT_TRUE(st.ok()) << st.message();
  // A seek back lands on the same pixels.
  ASSERT_TRUE(src->Seek(5).ok());
  ASSERT_TRUE(src->Read(&frame, &st));
  cap.set(cv::CAP_PROP_POS_FRAMES, 5);
  ASSERT_TRUE(cap.read(expected));
  EXPECT_EQ(cv::norm(frame.image, expected, cv::NORM_INF), 0);
}

TEST(DirectDecoders, VideoFramesAreTheOnesOpenCvsCaptureDecodes) {
  ExpectFramesAsOpenCvDecodesThem("MJPG", {320, 240});
  // A size the codec pads to whole blocks (its coded size is larger than the picture).
  ExpectFramesAsOpenCvDecodesThem("MJPG", {170, 122});
  ExpectFramesAsOpenCvDecodesThem("XVID", {160, 120});
}

// A relative name with a colon is a file, not one of FFmpeg's protocols ("take" is none, and
// FFmpeg would have refused it as such).
TEST(DirectDecoders, AVideoNamedWithAColonIsReadAsAFile) {
  test::TempDir dir;
  {
    cv::VideoWriter w(dir.file("take:2.avi"), cv::CAP_FFMPEG,
                      cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25, {64, 48});
    ASSERT_TRUE(w.isOpened());
    for (int i = 0; i < 5; ++i) w.write(TexturedFrame({64, 48}, i));
  }
  char here[4096];
  ASSERT_NE(getcwd(here, sizeof here), nullptr);
  ASSERT_EQ(chdir(dir.path().c_str()), 0);
  Status st;
  auto src = VideoSource::Open("take:2.avi", &st);
  Frame frame;
  int read = 0;
  while (src && src->Read(&frame, &st)) ++read;
  ASSERT_EQ(chdir(here), 0);
  ASSERT_TRUE(src) << st.message();
  EXPECT_EQ(read, 5) << st.message();
}

// Writes `n` textured frames as MPEG-4 with B-frames into an AVI, with FFmpeg's libraries (OpenCV's
// writer makes none): a container without presentation times holding frames decoded out of order.
bool WriteAviWithBFrames(const std::string& path, int n, cv::Size size) {
  AVFormatContext* out = nullptr;
  if (avformat_alloc_output_context2(&out, nullptr, "avi", path.c_str()) < 0) return false;
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_MPEG4);
  AVStream* st = avformat_new_stream(out, nullptr);
  AVCodecContext* enc = avcodec_alloc_context3(codec);
  enc->width = size.width;
  enc->height = size.height;
  enc->pix_fmt = AV_PIX_FMT_YUV420P;
  enc->time_base = {1, 25};
  enc->gop_size = 12;
  enc->max_b_frames = 2;
  bool ok = avcodec_open2(enc, codec, nullptr) >= 0 &&
            avcodec_parameters_from_context(st->codecpar, enc) >= 0;
  st->time_base = enc->time_base;
  ok = ok && avio_open(&out->pb, path.c_str(), AVIO_FLAG_WRITE) >= 0 &&
       avformat_write_header(out, nullptr) >= 0;
  SwsContext* sws =
      sws_getContext(size.width, size.height, AV_PIX_FMT_BGR24, size.width, size.height,
                     AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
  AVFrame* frame = av_frame_alloc();
  frame->format = enc->pix_fmt;
  frame->width = size.width;
  frame->height = size.height;
  ok = ok && av_frame_get_buffer(frame, 0) >= 0;
  AVPacket* pkt = av_packet_alloc();
  auto drain = [&] {
    while (avcodec_receive_packet(enc, pkt) == 0) {
      av_packet_rescale_ts(pkt, enc->time_base, st->time_base);
      pkt->stream_index = st->index;
      ok = ok && av_interleaved_write_frame(out, pkt) >= 0;
    }
  };
  for (int i = 0; ok && i <= n; ++i) {
    if (i == n) {
      avcodec_send_frame(enc, nullptr);  // flush the B-frames held back
    } else {
      const cv::Mat bgr = TexturedFrame(size, i);
      const uint8_t* src[1] = {bgr.data};
      const int stride[1] = {static_cast<int>(bgr.step[0])};
      ok = av_frame_make_writable(frame) >= 0;
      sws_scale(sws, src, stride, 0, size.height, frame->data, frame->linesize);
      frame->pts = i;
      ok = ok && avcodec_send_frame(enc, frame) >= 0;
    }
    drain();
  }
  ok = ok && av_write_trailer(out) >= 0;
  av_packet_free(&pkt);
  av_frame_free(&frame);
  sws_freeContext(sws);
  avcodec_free_context(&enc);
  avio_closep(&out->pb);
  avformat_free_context(out);
  return ok;
}

TEST(DirectDecoders, SeeksLandOnTheFrameReadInOrderWithBFramesInAnAvi) {
  test::TempDir dir;
  const std::string path = dir.file("bframes.avi");
  const int n = 60;
  ASSERT_TRUE(WriteAviWithBFrames(path, n, {96, 64}));
  Status st;
  auto src = VideoSource::Open(path, &st);
  ASSERT_TRUE(src) << st.message();
  std::vector<cv::Mat> in_order;
  Frame frame;
  while (src->Read(&frame, &st)) in_order.push_back(frame.image.clone());
  ASSERT_EQ(static_cast<int>(in_order.size()), n) << st.message();
  // Backwards and forwards, on and between keyframes; each seek then reads on.
  for (int index : {37, 5, 50, 12, 0, 59, 24, 23}) {
    SCOPED_TRACE("seek to " + std::to_string(index));
    ASSERT_TRUE(src->Seek(index).ok());
    for (int k = index; k < std::min(n, index + 3); ++k) {
      ASSERT_TRUE(src->Read(&frame, &st)) << st.message();
      EXPECT_EQ(frame.index, k);
      EXPECT_EQ(cv::norm(frame.image, in_order[static_cast<std::size_t>(k)], cv::NORM_INF), 0)
          << "frame " << k;
    }
  }
}

// OpenCV's reading as ReadImage documents it: IMREAD_UNCHANGED, then 16-bit scaled by 1/257,
// grey spread and alpha dropped.
cv::Mat OpenCvBgr(const std::string& path) {
  cv::Mat img = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (img.depth() == CV_16U) img.convertTo(img, CV_MAKETYPE(CV_8U, img.channels()), 1 / 257.0);
  if (img.channels() == 1) cv::cvtColor(img, img, cv::COLOR_GRAY2BGR);
  if (img.channels() == 4) cv::cvtColor(img, img, cv::COLOR_BGRA2BGR);
  return img;
}

// A PNG written with libpng, for the kinds OpenCV cannot write (palettes, interlacing): `rows`
// holds each row's packed samples; `palette` and `alpha`, when not empty, its PLTE and tRNS.
void WriteRawPng(const std::string& path, int width, int depth, int colour, int interlace,
                 std::vector<std::vector<png_byte>> rows,
                 const std::vector<png_color>& palette = {},
                 const std::vector<png_byte>& alpha = {}) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, f);
  png_set_IHDR(png, info, width, static_cast<png_uint_32>(rows.size()), depth, colour, interlace,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!palette.empty()) png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
  if (!alpha.empty())
    png_set_tRNS(png, info, alpha.data(), static_cast<int>(alpha.size()), nullptr);
  png_write_info(png, info);
  std::vector<png_bytep> pointers;
  for (std::vector<png_byte>& row : rows) pointers.push_back(row.data());
  png_write_image(png, pointers.data());  // all passes of an interlaced image
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

// A 4-bit palette PNG with a transparent entry.
void WritePalettePng(const std::string& path, int width, int height) {
  std::vector<png_color> palette(16);
  for (int i = 0; i < 16; ++i) {
    palette[i] = {static_cast<png_byte>(i * 16), static_cast<png_byte>(255 - i * 9),
                  static_cast<png_byte>(i * i)};
  }
  std::vector<std::vector<png_byte>> rows(height, std::vector<png_byte>((width + 1) / 2));
  for (int y = 0; y < height; ++y) {
    for (size_t x = 0; x < rows[y].size(); ++x) rows[y][x] = static_cast<png_byte>((x + y) * 0x13);
  }
  WriteRawPng(path, width, 4, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, rows, palette, {0, 128});
}

// An interlaced (Adam7) RGB PNG of the samples of `image` (CV_8UC3).
void WriteInterlacedPng(const std::string& path, const cv::Mat& image) {
  std::vector<std::vector<png_byte>> rows;
  for (int y = 0; y < image.rows; ++y)
    rows.emplace_back(image.ptr(y), image.ptr(y) + 3 * image.cols);
  WriteRawPng(path, image.cols, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_ADAM7, rows);
}

TEST(DirectDecoders, PngPixelsAreTheOnesOpenCvsReaderDecodes) {
  test::TempDir dir;
  const cv::Size size(37, 23);
  std::vector<std::string> paths;
  for (int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4}) {
    cv::Mat img(size, type);
    cv::randu(img, 0, CV_MAT_DEPTH(type) == CV_16U ? 65536 : 256);
    paths.push_back(dir.file("t" + std::to_string(type) + ".png"));
    ASSERT_TRUE(cv::imwrite(paths.back(), img));
  }
  cv::Mat bilevel(size, CV_8UC1);
  cv::randu(bilevel, 0, 2);
  bilevel *= 255;
  paths.push_back(dir.file("bilevel.png"));
  ASSERT_TRUE(cv::imwrite(paths.back(), bilevel, {cv::IMWRITE_PNG_BILEVEL, 1}));
  paths.push_back(dir.file("palette.png"));
  WritePalettePng(paths.back(), size.width, size.height);
  cv::Mat colour(size, CV_8UC3);
  cv::randu(colour, 0, 256);
  paths.push_back(dir.file("interlaced.png"));
  WriteInterlacedPng(paths.back(), colour);
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    cv::Mat ours;
    const Status st = ReadImage(path, &ours);
    ASSERT_TRUE(st.ok()) << st.message();
    const cv::Mat theirs = OpenCvBgr(path);
    ASSERT_EQ(ours.type(), CV_8UC3);
    ASSERT_EQ(ours.size(), theirs.size());
    EXPECT_EQ(cv::norm(ours, theirs, cv::NORM_INF), 0);
  }
}

TEST(DirectDecoders, APngWhoseHeaderAsksForGigabytesIsRefused) {
  test::TempDir dir;
  cv::Mat img(4, 4, CV_8UC3, cv::Scalar(9, 8, 7));
  std::vector<uchar> bytes;
  ASSERT_TRUE(cv::imencode(".png", img, bytes));
  // Width and height (bytes 16..23, big-endian) set to 30000 x 30000, 900 million pixels, with
  // the header's checksum made right again: a valid header, refused before any pixel is
  // allocated.
  for (int i : {16, 20}) {
    bytes[i] = 0;
    bytes[i + 1] = 0;
    bytes[i + 2] = 0x75;
    bytes[i + 3] = 0x30;
  }
  const uLong crc = crc32(0, bytes.data() + 12, 17);  // "IHDR" and its 13 bytes
  for (int k = 0; k < 4; ++k) bytes[29 + k] = static_cast<uchar>(crc >> (24 - 8 * k));
  const std::string path = dir.file("huge.png");
  test::WriteFile(path, std::string(bytes.begin(), bytes.end()));
  cv::Mat out;
  const Status st = ReadImage(path, &out);
  EXPECT_FALSE(st.ok());
  EXPECT_NE(st.message().find(path), std::string::npos) << st.message();
  EXPECT_NE(st.message().find("too large"), std::string::npos) << st.message();
  EXPECT_TRUE(out.empty());
}

TEST(DirectDecoders, ADamagedPngNamesTheFile) {
  test::TempDir dir;
  cv::Mat img(40, 40, CV_8UC3, cv::Scalar(1, 2, 3));
  std::vector<uchar> bytes;
  ASSERT_TRUE(cv::imencode(".png", img, bytes));
  bytes.resize(bytes.size() / 2);  // cut in the middle of the image data
  const std::string path = dir.file("cut.png");
  test::WriteFile(path, std::string(bytes.begin(), bytes.end()));
  cv::Mat out;
  const Status st = ReadImage(path, &out);
  EXPECT_FALSE(st.ok());
  EXPECT_NE(st.message().find(path), std::string::npos) << st.message();
  EXPECT_NE(st.message().find("corrupt PNG data"), std::string::npos) << st.message();
}

}  // namespace
}  // namespace armmimic
