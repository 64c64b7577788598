// armmimic's depthwise convolution layer against cv::dnn's own grouped convolution on random
// tensors: every kernel size, stride, padding and activation the TensorFlow.js graphs use, on
// planes of odd and even sizes (where SAME padding puts its odd pixel after).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

#include "pose/depthwise_layer.h"

namespace armmimic::internal {
namespace {

struct Case {
  int channels, height, width, kernel, stride;
  std::string pad, activation;
};

cv::Mat Forward(const std::string& type, const cv::dnn::LayerParams& params,
                const std::string& activation, const cv::Mat& input) {
  cv::dnn::Net net;
  cv::dnn::LayerParams p = params;
  net.addLayerToPrev("conv", type, p);
  if (type == "Convolution" && !activation.empty()) {
    cv::dnn::LayerParams a;
    if (activation == "Relu6") {
      a.set("min_value", 0.0f);
      a.set("max_value", 6.0f);
    }
    net.addLayerToPrev("act", activation == "Relu6" ? "ReLU6" : "ReLU", a);
  }
  net.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net.setInput(input);
  return net.forward().clone();
}

TEST(DepthwiseLayerTest, AgreesWithGroupedConvolution) {
  RegisterDepthwiseLayer();
  const std::vector<Case> cases = {
      {5, 12, 12, 3, 1, "SAME", "Relu6"}, {7, 9, 8, 3, 1, "SAME", "Relu"},
      {4, 10, 11, 3, 1, "SAME", ""},      {3, 11, 7, 5, 1, "SAME", "Relu6"},
      {6, 16, 16, 5, 1, "SAME", ""},      {3, 9, 10, 3, 1, "VALID", ""},
      {2, 9, 9, 5, 1, "VALID", "Relu"},   {384, 12, 12, 3, 1, "SAME", "Relu6"},
      {2, 5, 6, 7, 1, "SAME", "Relu"}};
  cv::RNG rng(7);
  for (const Case& c : cases) {
    SCOPED_TRACE(std::to_string(c.channels) + " channels " + std::to_string(c.height) + "x" +
                 std::to_string(c.width) + " kernel " + std::to_string(c.kernel) + " stride " +
                 std::to_string(c.stride) + " " + c.pad + " " + c.activation);
    cv::Mat input(std::vector<int>{1, c.channels, c.height, c.width}, CV_32F);
    rng.fill(input, cv::RNG::UNIFORM, -3.0, 3.0);
    cv::Mat kernel(std::vector<int>{c.channels, 1, c.kernel, c.kernel}, CV_32F);
    rng.fill(kernel, cv::RNG::UNIFORM, -1.0, 1.0);
    cv::Mat bias(1, c.channels, CV_32F);
    rng.fill(bias, cv::RNG::UNIFORM, -1.0, 1.0);
    cv::dnn::LayerParams p;
    p.set("kernel_h", c.kernel);
    p.set("kernel_w", c.kernel);
    p.set("stride_h", c.stride);
    p.set("stride_w", c.stride);
    p.set("pad_mode", c.pad);
    p.blobs = {kernel, bias};
    cv::dnn::LayerParams grouped = p;
    grouped.set("num_output", c.channels);
    grouped.set("group", c.channels);
    grouped.set("bias_term", true);
    const cv::Mat want = Forward("Convolution", grouped, c.activation, input);
    p.set("activation", c.activation);
    const cv::Mat got = Forward(kDepthwiseLayerType, p, "", input);
    ASSERT_EQ(got.dims, 4);
    for (int d = 0; d < 4; ++d) ASSERT_EQ(got.size[d], want.size[d]) << "axis " << d;
    EXPECT_LT(cv::norm(got, want, cv::NORM_INF), 1e-4);
    if (c.activation == "Relu6") {
      double lo = 0, hi = 0;
      cv::minMaxIdx(got, &lo, &hi);
      EXPECT_GE(lo, 0.0);
      EXPECT_LE(hi, 6.0);
    }
  }
}

}  // namespace
}  // namespace armmimic::internal
