// The interface between src/core and the image-codec and video-I/O module (armmimic-cvio.so).
//
// OpenCV's image codecs and video I/O pull about a hundred libraries into a process (GDAL, GDCM,
// poppler, xerces ...), and binding their symbols is most of a short run's start. Reading videos
// and PNG images, which every analysis does, goes through FFmpeg and libpng directly in src/core;
// everything else (other image formats, encoding images, writing videos, cameras and network
// streams) lives in this module, which src/core loads on first use (cvio_loader.h).
//
// Both sides are built from one source tree by one compiler: the module is found beside the
// programs and must report the same kAbi and version, so C++ types cross the boundary as they
// are.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"
#include "armmimic/core/video_source.h"
#include "armmimic/core/video_writer.h"

namespace armmimic::cvio {

// Raised whenever a signature below changes.
constexpr int kAbi = 2;

struct Api {
  int abi;
  const char* version;  // ARMMIMIC_VERSION of the build
  // Decodes the bytes of any image file OpenCV reads, as imread with IMREAD_UNCHANGED does; false
  // with *error set otherwise.
  bool (*read_image)(const std::vector<unsigned char>& bytes, cv::Mat* raw, std::string* error);
  // True when an image with extension `ext` (".png") can be encoded.
  bool (*have_image_writer)(const std::string& ext);
  // Encodes `image` in the format of `ext` with OpenCV's IMWRITE_* `params`.
  bool (*encode_image)(const std::string& ext, const cv::Mat& image, const std::vector<int>& params,
                       std::vector<unsigned char>* bytes, std::string* error);
  // Decodes an encoded image in memory to 8-bit BGR; false when it does not decode.
  bool (*decode_image)(const std::vector<unsigned char>& bytes, cv::Mat* bgr);
  // "camera:N" or a stream URL; nullptr with *status set on failure.
  std::unique_ptr<VideoSource> (*open_camera)(const std::string& spec, Status* status);
  // See VideoFileWriter::Open.
  std::unique_ptr<VideoFileWriter> (*open_writer)(const std::string& path,
                                                  const std::string& fourcc, double fps,
                                                  cv::Size size, int jpeg_quality, Status* status);
};

}  // namespace armmimic::cvio

// The module's one exported symbol.
extern "C" const armmimic::cvio::Api* armmimic_cvio_api();
