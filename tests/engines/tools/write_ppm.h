// Writes an RGB image (CV_8UC3, R first) as a binary PPM, the format the TensorFlow.js reference
// scripts read (scripts/tfjs-model.js); for the parity tools pose_inputs and blazepose_inputs.
#pragma once

#include <cstdio>
#include <string>

#include <opencv2/core.hpp>

namespace armmimic::test {

inline bool WritePpm(const std::string& path, const cv::Mat& rgb) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  std::fprintf(f, "P6\n%d %d\n255\n", rgb.cols, rgb.rows);
  for (int y = 0; y < rgb.rows; ++y) std::fwrite(rgb.ptr(y), 1, rgb.cols * 3, f);
  return std::fclose(f) == 0;
}

}  // namespace armmimic::test
