// The armmimic-cvio module's Api: OpenCV's image codecs, and its video I/O for cameras, streams
// and writing videos (cvio_api.h says why they live apart from src/core).
#include <exception>

#include <opencv2/imgcodecs.hpp>

#include "armmimic/version.h"
#include "cvio_api.h"
#include "cvio_parts.h"

namespace armmimic::cvio {
namespace {

bool ReadImageFile(const std::vector<unsigned char>& bytes, cv::Mat* raw, std::string* error) {
  try {
    *raw = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    *error = e.msg;
    return false;
  }
  if (raw->empty()) {
    *error = "unknown format or corrupt data";
    return false;
  }
  return true;
}

bool HaveImageWriter(const std::string& ext) {
  try {
    return cv::haveImageWriter("x" + ext);
  } catch (const cv::Exception&) {
    return false;
  }
}

bool EncodeImage(const std::string& ext, const cv::Mat& image, const std::vector<int>& params,
                 std::vector<unsigned char>* bytes, std::string* error) {
  try {
    if (cv::imencode(ext, image, *bytes, params)) return true;
    *error = "the encoder failed";
  } catch (const cv::Exception& e) {
    *error = e.msg;
  }
  return false;
}

bool DecodeImage(const std::vector<unsigned char>& bytes, cv::Mat* bgr) {
  try {
    *bgr = cv::imdecode(bytes, cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
    bgr->release();
  }
  return !bgr->empty();
}

const Api kApi = {kAbi,        ARMMIMIC_VERSION, ReadImageFile, HaveImageWriter,
                  EncodeImage, DecodeImage,      OpenCamera,    OpenWriter};

}  // namespace
}  // namespace armmimic::cvio

extern "C" __attribute__((visibility("default"))) const armmimic::cvio::Api* armmimic_cvio_api() {
  return &armmimic::cvio::kApi;
}
