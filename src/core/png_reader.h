// PNG images decoded with libpng directly: the pixels OpenCV's image reader gives for the same
// file, without loading OpenCV's image codecs (see docs/architecture.md, "Start of a process").
// Private to src/core; ReadImage uses it for PNG files and hands every other format to the
// image-codec module.
#pragma once

#include <cstddef>
#include <string>

#include <opencv2/core.hpp>

namespace armmimic::internal {

// True when the `size` bytes at `data` start with the PNG signature.
bool IsPng(const unsigned char* data, std::size_t size);

// Decodes the PNG held in memory (`size` bytes at `data`) into 8-bit BGR: grey is spread to three
// channels, a palette is expanded, alpha is dropped (not composited) and 16-bit samples are scaled
// by 1/257, as OpenCV's reader with IMREAD_UNCHANGED and its conversion to BGR do. False with
// *error set when the data does not decode.
bool DecodePng(const unsigned char* data, std::size_t size, cv::Mat* bgr, std::string* error);

}  // namespace armmimic::internal
