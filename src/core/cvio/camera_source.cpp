// VideoSource over a live camera ("camera:N") or a network stream (rtsp://, http://, https://),
// through OpenCV's video I/O: part of the armmimic-cvio module (cvio_api.h).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <mutex>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "cvio_parts.h"
#include "video_source_impl.h"

namespace armmimic::cvio {
namespace {

using internal::DeliverStreamFrame;

// FFmpeg's own warnings would interleave with our messages, which name the stream. OpenCV reads
// OPENCV_FFMPEG_LOGLEVEL before its first FFmpeg capture; a user who wants them sets it (or
// OPENCV_FFMPEG_DEBUG) themselves. (Video files are read by src/core's own FFmpeg reader, which
// quiets the log itself.) The environment is written once per process, whichever thread opens
// first.
void QuietFfmpegLog() {
  static std::once_flag once;
  std::call_once(once, [] {
    // NOLINTNEXTLINE(concurrency-mt-unsafe): once, before any capture of ours reads it
    if (!std::getenv("OPENCV_FFMPEG_DEBUG")) setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);
  });
}

constexpr int kOpenTimeoutMs = 10000;
constexpr int kReadTimeoutMs = 10000;

class CameraSource : public VideoSource {
 public:
  explicit CameraSource(const std::string& spec) {
    info_.kind = SourceKind::kCamera;
    info_.path = spec;
    info_.frame_count = -1;
  }

  Status Init() {
    const std::string& spec = info_.path;
    bool opened = false;
    try {
      if (spec.rfind("camera:", 0) == 0) {
        const std::string num = spec.substr(7);
        if (num.empty() || num.size() > 4 ||
            !std::all_of(num.begin(), num.end(), [](unsigned char c) { return std::isdigit(c); })) {
          return Status::Error(spec + ": expected camera:N with N a camera number, e.g. camera:0");
        }
#ifdef __linux__
        // V4L2 directly: CAP_ANY would first try GStreamer, which probes USB devices, prints
        // warnings and never frees what it found.
        opened = cap_.open(std::stoi(num), cv::CAP_V4L2);
#else
        opened = cap_.open(std::stoi(num), cv::CAP_ANY);
#endif
      } else {
        // Our message names the stream; FFmpeg's own log stays quiet.
        QuietFfmpegLog();
        opened = cap_.open(spec, cv::CAP_FFMPEG,
                           {cv::CAP_PROP_OPEN_TIMEOUT_MSEC, kOpenTimeoutMs,
                            cv::CAP_PROP_READ_TIMEOUT_MSEC, kReadTimeoutMs});
      }
    } catch (const cv::Exception& e) {
      return Status::Error(spec + ": cannot open (" + e.msg + ")");
    }
    if (!opened) return Status::Error(spec + ": cannot open (no such camera or stream)");
    cv::Mat first;
    if (!Grab(&first)) return Status::Error(spec + ": opened, but delivers no frames");
    info_.size = first.size();
    const double fps = cap_.get(cv::CAP_PROP_FPS);
    info_.fps = std::isfinite(fps) && fps > 0 && fps < 1000 ? fps : 0;
    pending_ = first;
    return Status::Ok();
  }

  const VideoInfo& info() const override { return info_; }

  bool Read(Frame* frame, Status* status) override {
    Status local;
    Status& st = status ? *status : local;
    st = Status::Ok();
    cv::Mat img;
    if (!pending_.empty()) {
      img = pending_;
      pending_.release();
    } else if (!Grab(&img)) {
      return false;  // the stream ended or the camera went away
    }
    if (!DeliverStreamFrame(img, next_, info_, frame, &st)) return false;
    ++next_;
    return true;
  }

  Status Seek(int index) override {
    if (index == next_) return Status::Ok();
    return Status::Error(info_.path + ": a live camera or stream cannot seek");
  }

 private:
  bool Grab(cv::Mat* img) {
    try {
      if (!cap_.read(*img) || img->empty()) return false;
    } catch (const cv::Exception&) {
      return false;
    }
    if (img->channels() == 1) cv::cvtColor(*img, *img, cv::COLOR_GRAY2BGR);
    if (img->channels() == 4) cv::cvtColor(*img, *img, cv::COLOR_BGRA2BGR);
    return img->type() == CV_8UC3;
  }

  VideoInfo info_;
  cv::VideoCapture cap_;
  cv::Mat pending_;
  int next_ = 0;
};

}  // namespace

std::unique_ptr<VideoSource> OpenCamera(const std::string& spec, Status* status) {
  auto src = std::make_unique<CameraSource>(spec);
  *status = src->Init();
  if (!*status) return nullptr;
  return src;
}

}  // namespace armmimic::cvio
