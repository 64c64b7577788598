// VideoSource over a video file, decoded by FFmpeg (ffmpeg_reader.h).
#include <cmath>
#include <cstdlib>

#include "ffmpeg_reader.h"
#include "video_source_impl.h"

namespace armmimic::internal {
namespace {

// Reads that fail in a row before the stream counts as ended: a damaged frame fails alone and
// the decoder resumes at the next one.
constexpr int kRetriesAfterFailure = 3;
// Forward seeks up to this many frames decode their way there instead of asking the demuxer.
constexpr int kMaxDecodeForward = 64;

class VideoFileSource : public VideoSource {
 public:
  explicit VideoFileSource(const std::string& path) { info_.path = path; }

  Status Init() {
    Status st = OpenCapture();
    if (!st) return st;
    cv::Mat first;
    if (!Decode(&first)) {
      return Status::Error(info_.path +
                           ": no frame could be decoded (a video with zero frames, or damaged)");
    }
    info_.kind = SourceKind::kVideo;
    info_.size = first.size();
    const double fps = reader_.fps();
    info_.fps = std::isfinite(fps) && fps > 0 && fps < 1000 ? fps : 0;
    info_.frame_count = reader_.frame_count() >= 1 ? reader_.frame_count() : -1;
    info_.codec = reader_.fourcc();
    // Keep the proving frame for the first Read() rather than rewinding the demuxer.
    pending_ = first;
    pending_index_ = 0;
    next_ = 0;
    cap_next_ = 1;
    return Status::Ok();
  }

  const VideoInfo& info() const override { return info_; }

  bool Read(Frame* frame, Status* status) override {
    Status local;
    Status& st = status ? *status : local;
    st = Status::Ok();
    cv::Mat img;
    if (!pending_.empty() && pending_index_ == next_) {
      img = pending_;
      pending_.release();
    } else {
      pending_.release();
      if (!Decode(&img)) {
        const int failed = next_;
        ++cap_next_;  // the decoder has moved past the frame it could not decode
        // Not yet at the announced end: a damaged frame, or the file stops early?
        if (info_.frame_count > 0 && failed < info_.frame_count) {
          for (int i = 0; i < kRetriesAfterFailure; ++i) {
            cv::Mat after;
            const bool ok = Decode(&after);
            ++cap_next_;
            if (ok) {
              pending_ = after;
              pending_index_ = cap_next_ - 1;
              next_ = pending_index_;
              st = Status::Error(info_.path + ": frame " + std::to_string(failed) +
                                 " cannot be decoded (damaged data; " + std::to_string(i + 1) +
                                 " frame(s) lost)");
              return false;
            }
          }
        }
        // The stream ended: from now on the count is what was really there.
        if (info_.frame_count < 0 || failed < info_.frame_count) info_.frame_count = failed;
        cap_next_ = next_ = failed;
        return false;
      }
      ++cap_next_;
    }
    if (!DeliverStreamFrame(img, next_, info_, frame, &st)) return false;
    ++next_;
    return true;
  }

  Status Seek(int index) override {
    if (index < 0 || (info_.frame_count >= 0 && index > info_.frame_count)) {
      return Status::Error(info_.path + ": cannot seek to frame " + std::to_string(index) +
                           "; the video has " + std::to_string(info_.frame_count) + " frames");
    }
    if (!pending_.empty() && pending_index_ == index) {
      next_ = index;
      return Status::Ok();
    }
    pending_.release();
    if (index < cap_next_ || index - cap_next_ > kMaxDecodeForward) {
      if (reader_.SeekTo(index)) {
        cap_next_ = next_ = index;
        return Status::Ok();
      }
      // The demuxer cannot place us exactly: start again and decode forward.
      Status st = OpenCapture();
      if (!st) return st;
      cap_next_ = 0;
    }
    while (cap_next_ < index) {
      if (!reader_.Grab()) {
        const int reached = cap_next_;
        next_ = cap_next_;
        return Status::Error(info_.path + ": cannot seek to frame " + std::to_string(index) +
                             "; decoding stops at frame " + std::to_string(reached));
      }
      ++cap_next_;
    }
    next_ = index;
    return Status::Ok();
  }

 private:
  Status OpenCapture() {
    std::string why;
    if (!reader_.Open(info_.path, &why)) {
      return Status::Error(info_.path +
                           ": cannot open as a video (not a video file, damaged header, or a "
                           "codec this build cannot decode: " +
                           why + ")");
    }
    return Status::Ok();
  }

  bool Decode(cv::Mat* img) { return reader_.Read(img) && !img->empty(); }

  VideoInfo info_;
  FfmpegReader reader_;
  cv::Mat pending_;  // a frame already decoded, to be returned when next_ == pending_index_
  int pending_index_ = -1;
  int next_ = 0;      // index of the frame the next Read() returns
  int cap_next_ = 0;  // index of the frame the capture decodes next
};

}  // namespace

std::unique_ptr<VideoSource> OpenVideoFileSource(const std::string& path, Status* status) {
  auto src = std::make_unique<VideoFileSource>(path);
  *status = src->Init();
  if (!*status) return nullptr;
  return src;
}

}  // namespace armmimic::internal
