#include "common/evidence_bound.h"

#include <algorithm>

namespace armmimic::arm {

namespace {
// The blend's weights sum to 1 up to rounding: its value exceeds the largest pixel by far less.
constexpr float kRounding = 1e-4f;
}  // namespace

EvidenceBound::EvidenceBound(const EvidenceMap& evidence) {
  const cv::Mat& map = evidence.map();
  x0_ = evidence.region().x;
  y0_ = evidence.region().y;
  nbx_ = (map.cols + kBlock - 1) / kBlock;
  nby_ = (map.rows + kBlock - 1) / kBlock;
  std::vector<float> most(static_cast<std::size_t>(nbx_) * nby_, 0.f);
  for (int y = 0; y < map.rows; ++y) {
    const float* row = map.ptr<float>(y);
    float* m = most.data() + static_cast<std::size_t>(y / kBlock) * nbx_;
    for (int b = 0; b < nbx_; ++b) {
      // One block's row at a time: the largest of a few values, with no store between them.
      float v = m[b];
      for (int x = b * kBlock; x < std::min(map.cols, (b + 1) * kBlock); ++x) {
        v = std::max(v, row[x]);
      }
      m[b] = v;
    }
  }
  // A point's samples read pixels in its block or a neighbour; a point up to a block off the
  // map still has samples on it.
  const int w = nbx_ + 2;
  near_.assign(static_cast<std::size_t>(w) * (nby_ + 2), 0.f);
  for (int cy = -1; cy <= nby_; ++cy) {
    for (int cx = -1; cx <= nbx_; ++cx) {
      float v = 0.f;
      for (int by = std::max(0, cy - 1); by <= std::min(nby_ - 1, cy + 1); ++by) {
        for (int bx = std::max(0, cx - 1); bx <= std::min(nbx_ - 1, cx + 1); ++bx) {
          v = std::max(v, most[static_cast<std::size_t>(by) * nbx_ + bx]);
        }
      }
      near_[static_cast<std::size_t>(cy + 1) * w + cx + 1] = v * (1 + kRounding);
    }
  }
}

}  // namespace armmimic::arm
