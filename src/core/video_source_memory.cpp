// VideoSource over frames already in memory: rendered scenes run through the same analysis
// pipeline as a video file, without writing one.
#include "armmimic/core/video_source.h"

namespace armmimic {
namespace {

class MemorySource : public VideoSource {
 public:
  MemorySource(std::shared_ptr<const std::vector<cv::Mat>> frames, double fps,
               const std::string& name)
      : frames_(std::move(frames)) {
    info_.kind = SourceKind::kVideo;
    info_.path = name;
    info_.frame_count = static_cast<int>(frames_->size());
    info_.fps = fps;
    info_.size = frames_->empty() ? cv::Size() : frames_->front().size();
  }

  const VideoInfo& info() const override { return info_; }

  bool Read(Frame* frame, Status* status) override {
    *status = Status::Ok();
    if (next_ >= info_.frame_count) return false;
    const cv::Mat& img = (*frames_)[static_cast<std::size_t>(next_)];
    if (img.size() != info_.size || img.type() != CV_8UC3) {
      *status = Status::Error(info_.path + ": frame " + std::to_string(next_) +
                              " is not a colour image of the first frame's size");
      ++next_;
      return false;
    }
    frame->image = img.clone();  // a reader may write into its frame; the next run must not see it
    frame->index = next_;
    frame->time_s = info_.fps > 0 ? next_ / info_.fps : 0;
    frame->name.clear();
    ++next_;
    return true;
  }

  Status Seek(int index) override {
    if (index < 0 || index >= info_.frame_count) {
      return Status::Error(info_.path + ": cannot seek to frame " + std::to_string(index) + " of " +
                           std::to_string(info_.frame_count));
    }
    next_ = index;
    return Status::Ok();
  }

 private:
  std::shared_ptr<const std::vector<cv::Mat>> frames_;
  VideoInfo info_;
  int next_ = 0;
};

}  // namespace

std::unique_ptr<VideoSource> VideoSource::FromFrames(
    std::shared_ptr<const std::vector<cv::Mat>> frames, double fps, const std::string& name,
    Status* status) {
  if (!frames || frames->empty()) {
    *status = Status::Error(name + ": no frames");
    return nullptr;
  }
  *status = Status::Ok();
  return std::make_unique<MemorySource>(std::move(frames), fps, name);
}

}  // namespace armmimic
