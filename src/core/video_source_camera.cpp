// Cameras and network streams, and writing videos: through the armmimic-cvio module.
#include "armmimic/core/video_writer.h"
#include "cvio_loader.h"
#include "video_source_impl.h"

namespace armmimic {

namespace internal {

std::unique_ptr<VideoSource> OpenCameraSource(const std::string& spec, Status* status) {
  const cvio::Api* api = CvioModule(status);
  if (!api) {
    *status = Status::Error(spec + ": cannot open (" + status->message() + ")");
    return nullptr;
  }
  return api->open_camera(spec, status);
}

}  // namespace internal

std::unique_ptr<VideoFileWriter> VideoFileWriter::Open(const std::string& path,
                                                       const std::string& fourcc, double fps,
                                                       cv::Size size, int jpeg_quality,
                                                       Status* status) {
  const cvio::Api* api = internal::CvioModule(status);
  if (!api) {
    *status = Status::Error(path + ": cannot write a video (" + status->message() + ")");
    return nullptr;
  }
  return api->open_writer(path, fourcc, fps, size, jpeg_quality, status);
}

}  // namespace armmimic
