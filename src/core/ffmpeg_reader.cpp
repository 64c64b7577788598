#include "ffmpeg_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <mutex>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/avutil.h>
#include <libswscale/swscale.h>
}

namespace armmimic::internal {
namespace {

// FFmpeg's own warnings ("overread 8", "No JPEG data found") would interleave with our messages,
// which name the file and frame. OPENCV_FFMPEG_DEBUG, the switch OpenCV's capture has for the
// same log, turns them back on.
void QuietFfmpegLogOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (!std::getenv("OPENCV_FFMPEG_DEBUG")) av_log_set_level(AV_LOG_QUIET);
  });
}

std::string AvError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

double ToDouble(AVRational r) { return r.den != 0 ? av_q2d(r) : 0.0; }

std::string FourccOf(const AVCodecParameters& par) {
  unsigned tag = par.codec_tag;
  std::string s;
  if (tag == 0) {
    // No tag in the container: the codec's name, as OpenCV's capture reports it.
    const char* name = avcodec_get_name(par.codec_id);
    for (int i = 0; name && name[i] && i < 4; ++i) s += name[i];
    return s;
  }
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((tag >> (8 * i)) & 0xFF);
    if (c >= 32 && c < 127) s += c;
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace

bool FfmpegReader::Open(const std::string& path, std::string* error) {
  Close();
  QuietFfmpegLogOnce();
  // Through FFmpeg's file protocol: a name with a colon ("take:2.avi") is a file, not a protocol.
  const std::string url = "file:" + path;
  int r = avformat_open_input(&format_, url.c_str(), nullptr, nullptr);
  if (r < 0) {
    *error = AvError(r);
    return false;
  }
  r = avformat_find_stream_info(format_, nullptr);
  if (r < 0) {
    *error = AvError(r);
    Close();
    return false;
  }
  for (unsigned i = 0; i < format_->nb_streams; ++i) {
    // The first video stream that is not a cover picture.
    const AVStream* candidate = format_->streams[i];
    if (candidate->codecpar->codec_type == AVMEDIA_TYPE_VIDEO &&
        (candidate->disposition & AV_DISPOSITION_ATTACHED_PIC) == 0) {
      stream_ = static_cast<int>(i);
      break;
    }
  }
  if (stream_ < 0) {
    *error = "no video stream";
    Close();
    return false;
  }
  AVStream* st = format_->streams[stream_];
  const AVCodec* decoder = avcodec_find_decoder(st->codecpar->codec_id);
  if (!decoder) {
    *error = std::string("no decoder for ") + avcodec_get_name(st->codecpar->codec_id);
    Close();
    return false;
  }
  codec_ = avcodec_alloc_context3(decoder);
  frame_ = av_frame_alloc();
  packet_ = av_packet_alloc();
  if (!codec_ || !frame_ || !packet_) {
    *error = "out of memory";
    Close();
    return false;
  }
  r = avcodec_parameters_to_context(codec_, st->codecpar);
  if (r >= 0) {
    codec_->thread_count = 0;  // as many as FFmpeg finds useful for the codec
    r = avcodec_open2(codec_, decoder, nullptr);
  }
  if (r < 0) {
    *error = AvError(r);
    Close();
    return false;
  }
  // Frame rate and count as OpenCV's capture computes them.
  fps_ = ToDouble(st->avg_frame_rate);
  if (fps_ <= 0) fps_ = ToDouble(av_guess_frame_rate(format_, st, nullptr));
  if (fps_ <= 0) fps_ = ToDouble(st->time_base) > 0 ? 1.0 / ToDouble(st->time_base) : 0;
  int64_t count = st->nb_frames;
  if (count <= 0) {
    double seconds =
        format_->duration > 0 ? static_cast<double>(format_->duration) / AV_TIME_BASE : 0.0;
    if (seconds <= 0 && st->duration > 0) {
      seconds = static_cast<double>(st->duration) * ToDouble(st->time_base);
    }
    count = std::llround(seconds * fps_);
  }
  frame_count_ = count > 0 && count < (1LL << 30) ? static_cast<int>(count) : 0;
  fourcc_ = FourccOf(*st->codecpar);
  // AVI stores no presentation times: with frames decoded out of order (B-frames) a frame's time
  // is guessed from its place in the file, and a seek by time lands a frame or two off. Such a
  // file is placed by decoding forward from its start (SeekTo refuses).
  seek_by_time_ =
      !(std::strcmp(format_->iformat->name, "avi") == 0 && st->codecpar->video_delay > 0);
  return true;
}

void FfmpegReader::Close() {
  sws_freeContext(sws_);
  sws_ = nullptr;
  av_packet_free(&packet_);
  av_frame_free(&frame_);
  avcodec_free_context(&codec_);
  avformat_close_input(&format_);
  stream_ = -1;
  flushing_ = false;
  held_ = false;
  fps_ = 0;
  frame_count_ = 0;
  fourcc_.clear();
}

bool FfmpegReader::DecodeNext() {
  if (!codec_) return false;
  for (;;) {
    int r = avcodec_receive_frame(codec_, frame_);
    if (r == 0) return true;
    if (r != AVERROR(EAGAIN) || flushing_) return false;  // the end, or a decoding error
    r = av_read_frame(format_, packet_);
    if (r < 0) {
      // The demuxer has ended (or failed): drain the frames the decoder still holds.
      flushing_ = true;
      avcodec_send_packet(codec_, nullptr);
      continue;
    }
    if (packet_->stream_index != stream_) {
      av_packet_unref(packet_);
      continue;
    }
    r = avcodec_send_packet(codec_, packet_);
    av_packet_unref(packet_);
    // A packet that does not decode is one damaged frame: it fails alone.
    if (r < 0 && r != AVERROR(EAGAIN)) return false;
  }
}

bool FfmpegReader::Grab() {
  if (held_) {
    held_ = false;
    return true;
  }
  return DecodeNext();
}

bool FfmpegReader::Read(cv::Mat* bgr) {
  if (!Grab()) return false;
  const int width = frame_->width;
  const int height = frame_->height;
  if (width <= 0 || height <= 0) return false;
  // The conversion OpenCV's capture makes: the coded size, bicubic, to packed BGR.
  const int conv_w = std::max(codec_->coded_width, width);
  const int conv_h = std::max(codec_->coded_height, height);
  sws_ =
      sws_getCachedContext(sws_, conv_w, conv_h, static_cast<AVPixelFormat>(frame_->format), conv_w,
                           conv_h, AV_PIX_FMT_BGR24, SWS_BICUBIC, nullptr, nullptr, nullptr);
  if (!sws_) return false;
  // swscale's vector code writes past the end of a row: convert into a buffer with aligned rows
  // and a spare row, as OpenCV's capture does, then copy the picture out of it.
  const int stride = (conv_w * 3 + 63) / 64 * 64;
  buffer_.create(conv_h + 1, stride, CV_8UC1);
  uint8_t* dst[4] = {buffer_.data, nullptr, nullptr, nullptr};
  int dst_stride[4] = {stride, 0, 0, 0};
  sws_scale(sws_, frame_->data, frame_->linesize, 0, conv_h, dst, dst_stride);
  cv::Mat out(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    std::memcpy(out.ptr(y), buffer_.ptr(y), static_cast<size_t>(width) * 3);
  }
  *bgr = out;
  return true;
}

bool FfmpegReader::SeekTo(int index) {
  if (!format_ || !seek_by_time_ || fps_ <= 0 || index < 0) return false;
  AVStream* st = format_->streams[stream_];
  const double tb = ToDouble(st->time_base);
  if (tb <= 0) return false;
  const int64_t start = st->start_time != AV_NOPTS_VALUE ? st->start_time : 0;
  const auto target = start + static_cast<int64_t>(std::floor(index / fps_ / tb + 0.5));
  if (av_seek_frame(format_, stream_, target, AVSEEK_FLAG_BACKWARD) < 0) return false;
  avcodec_flush_buffers(codec_);
  flushing_ = false;
  held_ = false;
  for (;;) {
    if (!DecodeNext()) return false;
    const int64_t pts = frame_->best_effort_timestamp;
    if (pts == AV_NOPTS_VALUE) return false;
    const int64_t at = std::llround(static_cast<double>(pts - start) * tb * fps_);
    if (at > index) return false;
    if (at == index) {
      held_ = true;
      return true;
    }
  }
}

}  // namespace armmimic::internal
