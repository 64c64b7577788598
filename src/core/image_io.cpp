#include "armmimic/core/image_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/output_file.h"
#include "cvio_loader.h"
#include "png_reader.h"

namespace armmimic {
namespace {

std::string LowerExtension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Converts any depth/channel count OpenCV decodes into 8-bit BGR.
Status ToBgr8(const cv::Mat& in, const std::string& path, cv::Mat* bgr) {
  cv::Mat img = in;
  if (img.depth() != CV_8U) {
    double scale = 1.0;
    if (img.depth() == CV_16U) scale = 1.0 / 257.0;
    if (img.depth() == CV_32F || img.depth() == CV_64F) scale = 255.0;
    img.convertTo(img, CV_MAKETYPE(CV_8U, img.channels()), scale);
  }
  switch (img.channels()) {
    case 1:
      cv::cvtColor(img, *bgr, cv::COLOR_GRAY2BGR);
      return Status::Ok();
    case 3:
      *bgr = img;
      return Status::Ok();
    case 4:
      cv::cvtColor(img, *bgr, cv::COLOR_BGRA2BGR);
      return Status::Ok();
    default:
      return Status::Error(path + ": unsupported image with " + std::to_string(img.channels()) +
                           " channels");
  }
}

}  // namespace

bool HasImageExtension(const std::string& path) {
  static const char* const kExts[] = {".png", ".jpg",  ".jpeg", ".bmp",
                                      ".tif", ".tiff", ".pgm",  ".ppm"};
  const std::string ext = LowerExtension(path);
  return std::any_of(std::begin(kExts), std::end(kExts), [&](const char* e) { return ext == e; });
}

Status ReadImage(const std::string& path, cv::Mat* bgr) {
  if (path.empty()) return Status::Error("image path is empty");
  if (Status checked = CheckInputFile(path); !checked) return checked;
  // The file is read once: PNG, the format of backgrounds and arm-length images, is decoded
  // here; any other format by the codec module, from the same bytes.
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(path + ": cannot open image (" + FileErrorText(errno) + ")");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  if (in.bad()) return Status::Error(path + ": cannot read image (" + FileErrorText(errno) + ")");
  if (bytes.empty()) return Status::Error(path + ": empty file (0 bytes), not an image");
  cv::Mat raw;
  std::string why;
  if (internal::IsPng(bytes.data(), bytes.size())) {
    if (!internal::DecodePng(bytes.data(), bytes.size(), &raw, &why)) {
      return Status::Error(path + ": not a readable image (corrupt PNG data: " + why + ")");
    }
  } else {
    Status loaded;
    const cvio::Api* api = internal::CvioModule(&loaded);
    if (!api) return Status::Error(path + ": cannot decode image (" + loaded.message() + ")");
    if (!api->read_image(bytes, &raw, &why)) {
      return Status::Error(path + ": not a readable image (" + why + ")");
    }
  }
  cv::Mat out;
  Status s = ToBgr8(raw, path, &out);
  if (!s) return s;
  *bgr = out;
  return Status::Ok();
}

Status WriteImageAtomically(const std::string& path, const cv::Mat& image) {
  if (path.empty()) return Status::Error("image path is empty");
  if (image.empty()) return Status::Error(path + ": nothing to write (empty image)");
  const std::string ext = LowerExtension(path);
  if (ext.empty()) {
    return Status::Error(path + ": no file extension; use .png, .jpg, .bmp, .tif, .pgm or .ppm");
  }
  std::vector<unsigned char> bytes;
  if (Status st = EncodeImage(ext, image, {}, &bytes); !st) {
    return Status::Error(path + ": " + st.message());
  }
  return WriteOutputFile(path, std::string(bytes.begin(), bytes.end()));
}

Status EncodeImage(const std::string& ext, const cv::Mat& image, const std::vector<int>& params,
                   std::vector<unsigned char>* bytes) {
  Status loaded;
  const cvio::Api* api = internal::CvioModule(&loaded);
  if (!api) return Status::Error("cannot encode images (" + loaded.message() + ")");
  if (!api->have_image_writer(ext)) {
    return Status::Error("cannot write images with extension " + ext);
  }
  std::string why;
  if (!api->encode_image(ext, image, params, bytes, &why)) {
    return Status::Error("encoding as " + ext + " failed (" + why + ")");
  }
  return Status::Ok();
}

Status DecodeImage(const std::vector<unsigned char>& bytes, cv::Mat* bgr) {
  Status loaded;
  const cvio::Api* api = internal::CvioModule(&loaded);
  if (!api) return Status::Error("cannot decode images (" + loaded.message() + ")");
  if (!api->decode_image(bytes, bgr)) return Status::Error("the encoded image does not decode");
  return Status::Ok();
}

}  // namespace armmimic
