#include "pose/decode.h"

#include <cmath>

namespace armmimic::internal {
namespace {

constexpr int kGrid = 48;
constexpr int kCells = kGrid * kGrid;

float Sigmoid(float v) { return 1.0f / (1.0f + std::exp(-v)); }

// Channel c of an NCHW batch-1 blob as a 48*48 row-major array.
const float* Plane(const cv::Mat& blob, int c) { return blob.ptr<float>() + c * kCells; }

}  // namespace

std::array<NormalizedKeypoint, 17> DecodeMoveNet(const cv::Mat& heatmap, const cv::Mat& center,
                                                 const cv::Mat& regress, const cv::Mat& offset,
                                                 const MoveNetConstants& k) {
  const float* c = Plane(center, 0);
  int best = 0;
  float best_v = -1;
  for (int i = 0; i < kCells; ++i) {
    const float v = Sigmoid(c[i]) * k.center_weight[i];
    if (v > best_v) {
      best_v = v;
      best = i;
    }
  }
  const int cy = best / kGrid, cx = best % kGrid;
  std::array<NormalizedKeypoint, 17> out{};
  std::vector<float> score(kCells);
  for (int kp = 0; kp < 17; ++kp) {
    const float ry = static_cast<float>(cy) + Plane(regress, 2 * kp)[best];
    const float rx = static_cast<float>(cx) + Plane(regress, 2 * kp + 1)[best];
    const float* h = Plane(heatmap, kp);
    int cell = 0;
    float cell_v = -1;
    for (int i = 0; i < kCells; ++i) {
      score[i] = Sigmoid(h[i]);
      const float dy = k.grid_y[i] - ry, dx = k.grid_x[i] - rx;
      const float v = score[i] / (std::sqrt(dy * dy + dx * dx) + k.distance_bias);
      if (v > cell_v) {
        cell_v = v;
        cell = i;
      }
    }
    const int row = cell / kGrid, col = cell % kGrid;
    out[kp].y = (static_cast<float>(row) + Plane(offset, 2 * kp)[cell]) * k.scale_y;
    out[kp].x = (static_cast<float>(col) + Plane(offset, 2 * kp + 1)[cell]) * k.scale_x;
    out[kp].score = score[cell];
  }
  return out;
}

}  // namespace armmimic::internal
