// VideoSource: frames from a video file (AVI with MJPG/XVID/H.264 and whatever else FFmpeg
// decodes), a list of image files, a folder of images (sorted by name) or a camera.
// Open() checks the input up front and names the file in every error.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/frame.h"
#include "armmimic/core/status.h"

namespace armmimic {

enum class SourceKind { kVideo, kImages, kCamera };

struct VideoInfo {
  SourceKind kind = SourceKind::kVideo;
  std::string path;     // the video, the folder, or the first image
  int frame_count = 0;  // frames actually decodable as far as known; -1 for a camera
  double fps = 0;       // 0 when unknown (images)
  cv::Size size;        // frame size in pixels
  std::string codec;    // FOURCC for videos, e.g. "MJPG"; empty otherwise
};

class VideoSource {
 public:
  virtual ~VideoSource() = default;

  // `inputs`: one video file; or one folder of images; or one or more image files; or
  // "camera:N" / a stream URL (rtsp://, http://). Returns nullptr with *status set on failure:
  // missing file, unreadable, corrupt, zero frames, unsupported format.
  static std::unique_ptr<VideoSource> Open(const std::vector<std::string>& inputs, Status* status);
  static std::unique_ptr<VideoSource> Open(const std::string& input, Status* status) {
    return Open(std::vector<std::string>{input}, status);
  }

  // Frames held in memory (CV_8UC3 BGR, all of the first one's size), read as a video named
  // `name` at `fps`: benchmarks and tests run rendered scenes through the analysis pipeline
  // without writing a file. Returns nullptr with *status set when there are no frames.
  static std::unique_ptr<VideoSource> FromFrames(std::shared_ptr<const std::vector<cv::Mat>> frames,
                                                 double fps, const std::string& name,
                                                 Status* status);

  virtual const VideoInfo& info() const = 0;
  // Reads the next frame. Returns false at the end (status ok) or on a decode error (status
  // names the file and frame). Frames are CV_8UC3 BGR.
  //  - A video that ends before its announced frame count ends with an ok status, and
  //    info().frame_count becomes the number of frames really decoded.
  //  - A damaged frame in the middle of a video fails with "<file>: frame N cannot be decoded";
  //    a caller that wants to skip it may call Read() again and gets the frames after it.
  //  - An image of another size than the first, or one that does not decode, fails naming it.
  //    (Open() already rejects sizes it can read from PNG/JPEG/BMP/PNM headers.)
  virtual bool Read(Frame* frame, Status* status) = 0;
  // Positions so that the next Read() returns frame `index` (0 <= index; for videos and images
  // index < frame_count). Cameras cannot seek and return an error.
  virtual Status Seek(int index) = 0;
};

}  // namespace armmimic
