// Fuzzes the PNG reader (src/core/png_reader.h), which backgrounds and arm-length images go
// through: any bytes either decode into a non-empty 8-bit BGR image, or fail with a message.
#include <cstdint>
#include <cstdlib>
#include <string>

#include <opencv2/core.hpp>

#include "png_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  cv::Mat bgr;
  std::string error;
  if (!armmimic::internal::DecodePng(data, size, &bgr, &error)) {
    if (error.empty()) std::abort();  // a refusal says why
    return 0;
  }
  if (bgr.empty() || bgr.type() != CV_8UC3) std::abort();
  return 0;
}
