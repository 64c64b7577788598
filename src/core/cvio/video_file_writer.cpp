// VideoFileWriter over OpenCV's video writer: part of the armmimic-cvio module (cvio_api.h).
#include <opencv2/videoio.hpp>

#include "cvio_parts.h"

namespace armmimic::cvio {
namespace {

class OpenCvWriter : public VideoFileWriter {
 public:
  bool Open(const std::string& path, const std::string& c, double fps, cv::Size size,
            int jpeg_quality) {
    int api = cv::CAP_FFMPEG;
    if (c == "MJPG" && jpeg_quality > 0) {
      // An explicit quality needs OpenCV's own MJPEG writer, which honours it (FFmpeg's does
      // not; it gives about half the size at the same fidelity, so it is the default).
      api = cv::CAP_OPENCV_MJPEG;
    }
    const int fourcc = cv::VideoWriter::fourcc(c[0], c[1], c[2], c[3]);
    auto open = [&](int backend) {
      try {
        writer_.open(path, backend, fourcc, fps, size);
      } catch (const cv::Exception&) {
        writer_.release();
      }
    };
    open(api);
    if (!writer_.isOpened() && c == "MJPG" && api != cv::CAP_OPENCV_MJPEG) {
      open(cv::CAP_OPENCV_MJPEG);  // always built in
    }
    if (writer_.isOpened() && c == "MJPG" && jpeg_quality > 0) {
      writer_.set(cv::VIDEOWRITER_PROP_QUALITY, jpeg_quality);
    }
    return writer_.isOpened();
  }

  void Write(const cv::Mat& frame) override { writer_.write(frame); }
  void Close() override { writer_.release(); }

 private:
  cv::VideoWriter writer_;
};

}  // namespace

std::unique_ptr<VideoFileWriter> OpenWriter(const std::string& path, const std::string& fourcc,
                                            double fps, cv::Size size, int jpeg_quality,
                                            Status* status) {
  if (fourcc.size() != 4) {
    *status = Status::Error("codec", "codec '" + fourcc + "' is not a four-character code");
    return nullptr;
  }
  auto writer = std::make_unique<OpenCvWriter>();
  if (!writer->Open(path, fourcc, fps, size, jpeg_quality)) {
    *status = Status::Error("codec", path + ": codec " + fourcc +
                                         " has no encoder for AVI in this OpenCV build (try MJPG)");
    return nullptr;
  }
  *status = Status::Ok();
  return writer;
}

}  // namespace armmimic::cvio
