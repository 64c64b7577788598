// A video file decoded with FFmpeg's libraries directly (libavformat, libavcodec, libswscale):
// the frames, frame rate, frame count and FOURCC that OpenCV's FFmpeg capture gives for the same
// file, without loading OpenCV's videoio and its image codecs (see docs/architecture.md, "Start
// of a process"). Private to src/core; VideoSource wraps it.
#pragma once

#include <string>

#include <opencv2/core.hpp>

struct AVCodecContext;
struct AVFormatContext;
struct AVFrame;
struct AVPacket;
struct SwsContext;

namespace armmimic::internal {

class FfmpegReader {
 public:
  FfmpegReader() = default;
  FfmpegReader(const FfmpegReader&) = delete;
  FfmpegReader& operator=(const FfmpegReader&) = delete;
  ~FfmpegReader() { Close(); }

  // Opens `path` and its first video stream; false with *error in FFmpeg's words otherwise.
  bool Open(const std::string& path, std::string* error);
  void Close();

  // Decodes the next frame into 8-bit BGR. False at the end of the stream, or for a frame whose
  // data does not decode (the next call goes on with the frame after it).
  bool Read(cv::Mat* bgr);
  // As Read, without the colour conversion.
  bool Grab();
  // Places the reader so that the next Read returns frame `index`. False when the demuxer cannot
  // place it exactly (no timestamps, reordered frames in AVI, or it lands past the frame); the
  // reader must then be opened again.
  bool SeekTo(int index);

  double fps() const { return fps_; }
  // The container's frame count, or from its duration; 0 when unknown.
  int frame_count() const { return frame_count_; }
  // The stream's four-character code, e.g. "MJPG".
  const std::string& fourcc() const { return fourcc_; }

 private:
  bool DecodeNext();

  AVFormatContext* format_ = nullptr;
  AVCodecContext* codec_ = nullptr;
  AVFrame* frame_ = nullptr;
  AVPacket* packet_ = nullptr;
  SwsContext* sws_ = nullptr;
  cv::Mat buffer_;  // the conversion's output, rows padded for swscale
  int stream_ = -1;
  bool flushing_ = false;     // the demuxer has ended; the decoder gives back what it holds
  bool held_ = false;         // frame_ holds the frame the next Read returns (after SeekTo)
  bool seek_by_time_ = true;  // the frames' timestamps place them exactly
  double fps_ = 0;
  int frame_count_ = 0;
  std::string fourcc_;
};

}  // namespace armmimic::internal
