// VideoSource over a list of image files (or a folder's images, sorted by name).
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "armmimic/core/image_io.h"
#include "video_source_impl.h"

namespace armmimic::internal {
namespace {

std::string SizeText(const cv::Size& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

std::string FileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

uint32_t Be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | p[1] << 16 | p[2] << 8 | p[3]; }
uint32_t Le32(const uint8_t* p) { return uint32_t(p[3]) << 24 | p[2] << 16 | p[1] << 8 | p[0]; }

// The image size from the file header alone (PNG, JPEG, BMP, binary/ASCII PNM), without
// decoding; nullopt when the format is another or the header is unclear. Lets Open() name an
// image of the wrong size before any frame is processed.
std::optional<cv::Size> PeekImageSize(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return std::nullopt;
  // 4 KiB hold every header but a JPEG's behind a large EXIF block; read on only for those.
  static thread_local std::vector<uint8_t> storage(64 * 1024);
  uint8_t* buf = storage.data();
  size_t n = std::fread(buf, 1, 4096, f);
  if (n == 4096 && buf[0] == 0xFF && buf[1] == 0xD8) {
    n += std::fread(buf + n, 1, storage.size() - n, f);
  }
  std::fclose(f);
  std::optional<cv::Size> out;
  if (n >= 24 && buf[0] == 0x89 && buf[1] == 'P' && buf[2] == 'N' && buf[3] == 'G' &&
      buf[12] == 'I' && buf[13] == 'H' && buf[14] == 'D' && buf[15] == 'R') {
    out = cv::Size(static_cast<int>(Be32(buf + 16)), static_cast<int>(Be32(buf + 20)));
  } else if (n >= 26 && buf[0] == 'B' && buf[1] == 'M') {
    const int32_t w = static_cast<int32_t>(Le32(buf + 18));
    const int32_t h = static_cast<int32_t>(Le32(buf + 22));
    out = cv::Size(w, h < 0 ? -h : h);
  } else if (n >= 4 && buf[0] == 0xFF && buf[1] == 0xD8) {
    // JPEG: walk the marker segments to the first start-of-frame.
    size_t i = 2;
    while (i + 9 < n) {
      if (buf[i] != 0xFF) return std::nullopt;
      const uint8_t marker = buf[i + 1];
      if (marker == 0xFF) {
        ++i;
        continue;
      }
      const size_t len = size_t(buf[i + 2]) << 8 | buf[i + 3];
      const bool sof =
          marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
      if (sof) {
        out = cv::Size(buf[i + 7] << 8 | buf[i + 8], buf[i + 5] << 8 | buf[i + 6]);
        break;
      }
      if (marker == 0xD9 || marker == 0xDA) return std::nullopt;
      i += 2 + len;
    }
  } else if (n >= 3 && buf[0] == 'P' && buf[1] >= '1' && buf[1] <= '6') {
    // PNM: magic, then width and height as decimal text, '#' comments allowed.
    size_t i = 2;
    int values[2] = {0, 0};
    for (int& v : values) {
      while (i < n && (std::isspace(buf[i]) || buf[i] == '#')) {
        if (buf[i] == '#') {
          while (i < n && buf[i] != '\n') ++i;
        } else {
          ++i;
        }
      }
      if (i >= n || !std::isdigit(buf[i])) return std::nullopt;
      while (i < n && std::isdigit(buf[i]) && v < 1000000) v = v * 10 + (buf[i++] - '0');
    }
    out = cv::Size(values[0], values[1]);
  }
  if (out && (out->width <= 0 || out->height <= 0)) return std::nullopt;
  return out;
}

class ImageSource : public VideoSource {
 public:
  ImageSource(std::vector<std::string> files, const std::string& shown_path)
      : files_(std::move(files)) {
    info_.kind = SourceKind::kImages;
    info_.path = shown_path;
    info_.frame_count = static_cast<int>(files_.size());
    info_.fps = 0;
  }

  Status Init() {
    Status st = ReadImage(files_[0], &first_);
    if (!st) return st;
    info_.size = first_.size();
    // Compare the header sizes of all images now, so a mixed sequence fails before the run.
    for (size_t i = 1; i < files_.size(); ++i) {
      const std::optional<cv::Size> s = PeekImageSize(files_[i]);
      if (s && *s != info_.size) return SizeMismatch(files_[i], *s);
    }
    return Status::Ok();
  }

  const VideoInfo& info() const override { return info_; }

  bool Read(Frame* frame, Status* status) override {
    Status local;
    Status& st = status ? *status : local;
    st = Status::Ok();
    if (next_ >= static_cast<int>(files_.size())) return false;
    const std::string& path = files_[next_];
    cv::Mat img;
    if (next_ == 0 && !first_.empty()) {
      img = first_;
      first_.release();  // the caller owns it now; a later Seek(0) reads the file again
    } else {
      st = ReadImage(path, &img);
      if (!st) {
        st = Status::Error(st.message() + " (image " + std::to_string(next_ + 1) + " of " +
                           std::to_string(files_.size()) + ")");
        return false;
      }
    }
    if (img.size() != info_.size) {
      st = SizeMismatch(path, img.size());
      return false;
    }
    frame->image = img;
    frame->index = next_;
    frame->time_s = 0;
    frame->name = FileName(path);
    ++next_;
    return true;
  }

  Status Seek(int index) override {
    if (index < 0 || index > static_cast<int>(files_.size())) {
      return Status::Error(info_.path + ": cannot seek to image " + std::to_string(index) +
                           "; there are " + std::to_string(files_.size()) + " (0-based indices)");
    }
    next_ = index;
    return Status::Ok();
  }

 private:
  Status SizeMismatch(const std::string& path, const cv::Size& size) const {
    return Status::Error(path + ": image size " + SizeText(size) + " differs from " +
                         SizeText(info_.size) + " of the first image " + FileName(files_[0]) +
                         "; all images of a sequence must have the same size");
  }

  std::vector<std::string> files_;
  VideoInfo info_;
  cv::Mat first_;  // decoded by Init(), handed out by the first Read()
  int next_ = 0;
};

}  // namespace

std::unique_ptr<VideoSource> OpenImageSource(const std::vector<std::string>& files,
                                             const std::string& shown_path, Status* status) {
  auto src = std::make_unique<ImageSource>(files, shown_path);
  *status = src->Init();
  if (!*status) return nullptr;
  return src;
}

}  // namespace armmimic::internal
