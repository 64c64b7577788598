// MoveNet's decoder, done in C++ on the network's four 48x48 heads instead of in the graph:
//   1. sigmoid(center) weighted by the shipped 48x48 map; its argmax is the person's centre;
//   2. each keypoint's regressed position is the centre plus kpt_regress at the centre;
//   3. sigmoid(heatmap) divided by (distance to the regressed position + a shipped constant);
//      its argmax is the keypoint's cell;
//   4. the keypoint is (cell + kpt_offset at the cell) times a shipped scale (1/48); its score
//      is sigmoid(heatmap) there.
// Ties go to the first cell in row-major order, as TensorFlow's ArgMax does.
#pragma once

#include <array>
#include <vector>

#include <opencv2/core.hpp>

namespace armmimic::internal {

struct MoveNetConstants {
  std::vector<float> center_weight;  // 48*48, row-major (truediv_2_recip)
  std::vector<float> grid_y;         // 48*48: each cell's row
  std::vector<float> grid_x;         // 48*48: each cell's column
  float distance_bias = 1.8f;        // add_5/y
  float scale_y = 1.0f / 48;         // Reshape_13
  float scale_x = 1.0f / 48;
};

struct NormalizedKeypoint {
  float y = 0, x = 0, score = 0;  // y, x in 0..1 of the network's input
};

// heads: NCHW blobs (batch 1) heatmap [17], center [1], regress [34], offset [34], all 48x48,
// heatmap and center before their sigmoid.
std::array<NormalizedKeypoint, 17> DecodeMoveNet(const cv::Mat& heatmap, const cv::Mat& center,
                                                 const cv::Mat& regress, const cv::Mat& offset,
                                                 const MoveNetConstants& k);

}  // namespace armmimic::internal
