// Reading and writing single images (backgrounds, arm-length and reference images, plots).
// Errors name the file; writes are atomic (a temporary beside the target, then a rename).
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"

namespace armmimic {

// Reads `path` as CV_8UC3 BGR (grey and 16-bit images are converted; alpha is dropped).
// Fails with a message naming the file when it is missing, a directory, empty or not an image.
Status ReadImage(const std::string& path, cv::Mat* bgr);

// Encodes `image` in the format its extension names (.png, .jpg, .bmp, .tif, .pgm, .ppm ...)
// and writes it atomically. A missing directory or an unknown extension is named in the message.
Status WriteImageAtomically(const std::string& path, const cv::Mat& image);

// Encodes `image` in the format of `ext` (".png", ".jpg" ...) with OpenCV's IMWRITE_* `params`
// (e.g. {cv::IMWRITE_JPEG_QUALITY, 80}). The message names the extension when it has no encoder.
Status EncodeImage(const std::string& ext, const cv::Mat& image, const std::vector<int>& params,
                   std::vector<unsigned char>* bytes);

// Decodes an encoded image held in memory to 8-bit BGR.
Status DecodeImage(const std::vector<unsigned char>& bytes, cv::Mat* bgr);

// True when `path` ends in an image extension VideoSource reads as a still image
// (png, jpg, jpeg, bmp, tif, tiff, pgm, ppm; case-insensitive).
bool HasImageExtension(const std::string& path);

}  // namespace armmimic
