// The TF.js graph builder's Pad, MaxPool and Reshape (the ops BlazePose adds to MoveNet's), each
// on a small hand-made graph whose output is worked out by hand in TensorFlow's NHWC order; and
// an op the builder does not know still fails naming it. None of these needs the real model.
#include "pose/net.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "pose/graph.h"
#include "test_util.h"

namespace armmimic::internal {
namespace {

using test::TempDir;
using test::WriteFile;

// "1,2,2,1" -> the JSON list of strings TF.js writes for list.i attributes.
std::string IntList(const std::vector<int>& v) {
  std::string s;
  for (int i : v) s += (s.empty() ? "\"" : ", \"") + std::to_string(i) + "\"";
  return "{\"list\": {\"i\": [" + s + "]}}";
}

// A graph: input (Placeholder) -> NODE_OP(input, const) named "out", with an int32 constant
// "c" of `shape` holding `values` when `values` is not empty; `attrs` is the node's attr JSON.
struct OneOpGraph {
  std::string op;
  std::string attrs = "{}";
  std::vector<int> const_shape;
  std::vector<std::int32_t> const_values;
};

Status Build(const TempDir& dir, const OneOpGraph& g, cv::dnn::Net* net) {
  const bool has_const = !g.const_values.empty();
  std::string shape;
  for (int d : g.const_shape) shape += (shape.empty() ? "" : ", ") + std::to_string(d);
  const std::string json =
      "{\"modelTopology\": {\"node\": [{\"name\": \"input\", \"op\": \"Placeholder\"}, "
      "{\"name\": \"out\", \"op\": \"" +
      g.op + "\", \"input\": [\"input\"" + (has_const ? ", \"c\"" : "") +
      "], \"attr\": " + g.attrs + "}" +
      (has_const ? ", {\"name\": \"c\", \"op\": \"Const\"}" : "") +
      "]}, \"weightsManifest\": [{\"paths\": [\"w.bin\"], \"weights\": [" +
      (has_const ? "{\"name\": \"c\", \"shape\": [" + shape + "], \"dtype\": \"int32\"}" : "") +
      "]}]}";
  WriteFile(dir.file("model.json"), json);
  std::string bytes(g.const_values.size() * 4, '\0');
  if (!bytes.empty()) std::memcpy(&bytes[0], g.const_values.data(), bytes.size());
  WriteFile(dir.file("w.bin"), bytes);
  TfjsGraph graph;
  Status st = ReadTfjsGraph(dir.file("model.json"), &graph);
  if (!st) return st;
  return BuildTfjsNet(graph, "input", {"out"}, net);
}

// An NCHW blob of batch 1 from an NHWC array (TensorFlow's order).
cv::Mat BlobFromNhwc(const std::vector<float>& nhwc, int h, int w, int c) {
  cv::Mat blob(std::vector<int>{1, c, h, w}, CV_32F);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < c; ++k) {
        blob.ptr<float>()[(k * h + y) * w + x] = nhwc[(y * w + x) * c + k];
      }
  return blob;
}

cv::Mat Forward(cv::dnn::Net* net, const cv::Mat& blob) {
  net->setInput(blob);
  return net->forward("out").clone();
}

// Channel k of an NCHW output as rows of a 2-D list.
std::vector<std::vector<float>> Plane(const cv::Mat& out, int k) {
  const int h = out.size[2], w = out.size[3];
  std::vector<std::vector<float>> rows(h, std::vector<float>(w));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) rows[y][x] = out.ptr<float>()[(k * h + y) * w + x];
  return rows;
}

// A 2x2 image of three channels: channel k of pixel (y, x) is 10 * k + 2 * y + x + 1.
std::vector<float> SmallImage() {
  std::vector<float> v;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (int k = 0; k < 3; ++k) v.push_back(10.0f * k + 2.0f * y + x + 1.0f);
  return v;
}

TEST(TfjsNetTest, PadPutsZerosAroundHeightAndWidthAsGiven) {
  TempDir dir;
  cv::dnn::Net net;
  // One row above, none below; none left, two right.
  ASSERT_TRUE(Build(dir, {"Pad", "{}", {4, 2}, {0, 0, 1, 0, 0, 2, 0, 0}}, &net));
  const cv::Mat out = Forward(&net, BlobFromNhwc(SmallImage(), 2, 2, 3));
  ASSERT_EQ(out.dims, 4);
  EXPECT_EQ(out.size[1], 3);
  EXPECT_EQ(out.size[2], 3);
  EXPECT_EQ(out.size[3], 4);
  EXPECT_EQ(Plane(out, 0),
            (std::vector<std::vector<float>>{{0, 0, 0, 0}, {1, 2, 0, 0}, {3, 4, 0, 0}}));
  EXPECT_EQ(Plane(out, 2),
            (std::vector<std::vector<float>>{{0, 0, 0, 0}, {21, 22, 0, 0}, {23, 24, 0, 0}}));
}

TEST(TfjsNetTest, PadOfTheChannelAxisIsRefusedNamingTheNode) {
  TempDir dir;
  cv::dnn::Net net;
  const Status st = Build(dir, {"Pad", "{}", {4, 2}, {0, 0, 1, 1, 1, 1, 0, 1}}, &net);
  EXPECT_EQ(st.message(), "node out (Pad): pads the batch or channel axis, only H and W are read");
}

const std::string kPool2x2 = "{\"ksize\": " + IntList({1, 2, 2, 1}) +
                             ", \"strides\": " + IntList({1, 2, 2, 1}) +
                             ", \"padding\": {\"s\": \"VkFMSUQ=\"}, \"data_format\": {\"s\": "
                             "\"TkhXQw==\"}}";  // VALID, NHWC

TEST(TfjsNetTest, MaxPoolTakesEachWindowsLargestValuePerChannel) {
  TempDir dir;
  cv::dnn::Net net;
  ASSERT_TRUE(Build(dir, {"MaxPool", kPool2x2, {}, {}}, &net));
  // 4x4, three channels: channel k of (y, x) is (k + 1) * v(y, x), v with one peak per window.
  const float v[4][4] = {{1, 5, 2, 0}, {3, -1, 7, 6}, {-4, -3, 0, 9}, {-2, -8, 8, 1}};
  std::vector<float> nhwc;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int k = 0; k < 3; ++k) nhwc.push_back((k + 1) * v[y][x]);
  const cv::Mat out = Forward(&net, BlobFromNhwc(nhwc, 4, 4, 3));
  ASSERT_EQ(out.dims, 4);
  EXPECT_EQ(Plane(out, 0), (std::vector<std::vector<float>>{{5, 7}, {-2, 9}}));
  EXPECT_EQ(Plane(out, 2), (std::vector<std::vector<float>>{{15, 21}, {-6, 27}}));
}

TEST(TfjsNetTest, MaxPoolValidDropsTheOddLastRowAndColumn) {
  TempDir dir;
  cv::dnn::Net net;
  ASSERT_TRUE(Build(dir, {"MaxPool", kPool2x2, {}, {}}, &net));
  std::vector<float> nhwc;
  for (int i = 0; i < 9; ++i)
    for (int k = 0; k < 3; ++k) nhwc.push_back(i == 8 ? 100.0f : static_cast<float>(i));
  const cv::Mat out = Forward(&net, BlobFromNhwc(nhwc, 3, 3, 3));
  EXPECT_EQ(Plane(out, 1), (std::vector<std::vector<float>>{{4}}));  // the 100 is cut off
}

TEST(TfjsNetTest, ReshapeFlattensInTensorFlowsNhwcOrder) {
  TempDir dir;
  cv::dnn::Net net;
  ASSERT_TRUE(Build(dir, {"Reshape", "{}", {2}, {-1, 12}}, &net));
  const std::vector<float> nhwc = SmallImage();
  const cv::Mat out = Forward(&net, BlobFromNhwc(nhwc, 2, 2, 3));
  ASSERT_EQ(out.total(), 12u);
  EXPECT_EQ(std::vector<float>(out.ptr<float>(), out.ptr<float>() + 12), nhwc);
}

TEST(TfjsNetTest, ReshapeOfAOneByOneMapIsItsChannels) {
  TempDir dir;
  cv::dnn::Net net;
  ASSERT_TRUE(Build(dir, {"Reshape", "{}", {2}, {1, 3}}, &net));
  const cv::Mat out = Forward(&net, BlobFromNhwc({7, -8, 9}, 1, 1, 3));
  ASSERT_EQ(out.total(), 3u);
  EXPECT_EQ(std::vector<float>(out.ptr<float>(), out.ptr<float>() + 3),
            (std::vector<float>{7, -8, 9}));
}

TEST(TfjsNetTest, AReshapeToAnotherShapeIsRefusedNamingTheNode) {
  TempDir dir;
  cv::dnn::Net net;
  const Status st = Build(dir, {"Reshape", "{}", {3}, {1, 2, 6}}, &net);
  EXPECT_EQ(st.message(), "node out (Reshape): only a reshape to [batch, K] is read");
}

TEST(TfjsNetTest, AnOpTheBuilderDoesNotKnowIsNamed) {
  TempDir dir;
  cv::dnn::Net net;
  const Status st = Build(dir, {"MirrorPad", "{}", {4, 2}, {0, 0, 1, 1, 1, 1, 0, 0}}, &net);
  EXPECT_EQ(st.message(), "unknown op 'MirrorPad' (node out)");
}

}  // namespace
}  // namespace armmimic::internal
