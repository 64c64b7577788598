// The pinned MoveNet model: found, checked (size and SHA-256), read as a TensorFlow.js graph and
// built for cv::dnn, cut at its four heads; the decoder's shipped constants are read from the
// same weights.
#include <cstring>
#include <fstream>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include "armmimic/engines/pose.h"
#include "pose/decode.h"
#include "pose/graph.h"
#include "pose/net.h"
#include "pose/pinned.h"

namespace armmimic {
namespace {

// @vladmandic/human 3.3.6, models/: MoveNet SinglePose Lightning v4 as a TF.js graph model.
const std::vector<internal::PinnedFile> kPinned = {
    {kPoseModelJson, 161813, "df8cbde44d00f533ccc4916a7c6ebc17316532fb3fadad114ec667fef22872e9"},
    {kPoseModelWeights, 4650216,
     "bf97bc10d9c8a11200b0190ed64ce039b6252f1aff7cb552aca99b3d191c2f34"},
};

constexpr const char* kInputNode = "input";
// The heads: the last node of each of these name scopes.
constexpr const char* kHeadScopes[4] = {"kpt_heatmap_0/", "center_0/", "kpt_regress_0/",
                                        "kpt_offset_0/"};

// The last node of `scope`: the one no other node of the scope reads.
std::string HeadOf(const internal::TfjsGraph& g, const std::string& scope) {
  std::string head;
  for (const auto& n : g.nodes) {
    if (n.name.find(scope) == std::string::npos || n.op == "Const") continue;
    bool read = false;
    for (const auto& m : g.nodes) {
      if (m.name.find(scope) == std::string::npos) continue;
      for (const auto& in : m.inputs) read = read || in == n.name;
    }
    if (!read) head = n.name;
  }
  return head;
}

// A decoder constant: the weight whose name ends with `suffix`.
const internal::TfjsTensor* ConstantEnding(const internal::TfjsGraph& g,
                                           const std::string& suffix) {
  for (const auto& [name, t] : g.weights) {
    if (name.size() >= suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      return &t;
    }
  }
  return nullptr;
}

Status ReadConstants(const internal::TfjsGraph& g, const std::string& json,
                     internal::MoveNetConstants* k) {
  const internal::TfjsTensor* weight = ConstantEnding(g, "truediv_2_recip");
  const internal::TfjsTensor* bias = ConstantEnding(g, "/add_5/y");
  const internal::TfjsTensor* scale = ConstantEnding(g, "/Reshape_13");
  const internal::TfjsTensor* gy = ConstantEnding(g, "/strided_slice_3");
  const internal::TfjsTensor* gx = ConstantEnding(g, "/strided_slice_4");
  if (!weight || weight->values.size() != 48 * 48 || !bias || bias->values.size() != 1 || !scale ||
      scale->values.size() != 2 || !gy || gy->values.size() != 48 * 48 || !gx ||
      gx->values.size() != 48 * 48) {
    return Status::Error(json +
                         ": the MoveNet decoder's constants (truediv_2_recip, add_5/y, "
                         "Reshape_13, strided_slice_3/4) are missing or misshapen");
  }
  k->center_weight = weight->values;
  k->grid_y = gy->values;
  k->grid_x = gx->values;
  k->distance_bias = bias->values[0];
  k->scale_y = scale->values[0];
  k->scale_x = scale->values[1];
  return Status::Ok();
}

// Input pixels to image pixels (MoveNet's demo: crop corner + normalised keypoint * crop size).
void ToImage(const PoseCrop& crop, PoseKeypoints* k) {
  const double n = PoseNetwork::kInputSize;
  for (cv::Point2d& p : k->px) p = {crop.x + p.x / n * crop.size, crop.y + p.y / n * crop.size};
}

}  // namespace

struct PoseNetwork::Impl {
  std::string dir;
  cv::dnn::Net net;
  std::vector<std::string> heads;  // heatmap, center, regress, offset
  internal::MoveNetConstants constants;
};

PoseNetwork::PoseNetwork(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PoseNetwork::~PoseNetwork() = default;
const std::string& PoseNetwork::dir() const { return impl_->dir; }

std::unique_ptr<PoseNetwork> PoseNetwork::Load(const std::string& flag_dir, Status* status) {
  const std::string dir = internal::FindPinnedModel(flag_dir, kPinned, status);
  if (dir.empty()) return nullptr;
  auto net = LoadUnchecked(dir + "/" + kPoseModelJson, status);
  if (net) net->impl_->dir = dir;
  return net;
}

std::unique_ptr<PoseNetwork> PoseNetwork::LoadUnchecked(const std::string& json_path,
                                                        Status* status) {
  internal::TfjsGraph graph;
  *status = internal::ReadTfjsGraph(json_path, &graph);
  if (!*status) return nullptr;
  auto impl = std::make_unique<Impl>();
  for (const char* scope : kHeadScopes) {
    impl->heads.push_back(HeadOf(graph, scope));
    if (impl->heads.back().empty()) {
      *status = Status::Error(json_path + ": no " + std::string(scope, std::strlen(scope) - 1) +
                              " head (not a MoveNet graph)");
      return nullptr;
    }
  }
  *status = internal::BuildTfjsNet(graph, kInputNode, impl->heads, &impl->net);
  if (!*status) {
    *status = Status::Error(json_path + ": " + status->message());
    return nullptr;
  }
  *status = ReadConstants(graph, json_path, &impl->constants);
  if (!*status) return nullptr;
  impl->net.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  impl->net.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  return std::unique_ptr<PoseNetwork>(new PoseNetwork(std::move(impl)));
}

cv::Mat PoseNetwork::MakeInput(const cv::Mat& bgr, const PoseCrop& crop) {
  // TensorFlow's crop_and_resize: output pixel i samples y0 + i * size / 191 (bilinear, black
  // outside the image), with y0 and size in pixels of the (H-1)-spanning grid.
  const double n = kInputSize - 1;
  const double sx = crop.size * (bgr.cols - 1) / bgr.cols / n;
  const double sy = crop.size * (bgr.rows - 1) / bgr.rows / n;
  const double x0 = crop.x * (bgr.cols - 1) / bgr.cols;
  const double y0 = crop.y * (bgr.rows - 1) / bgr.rows;
  const cv::Matx23d m(sx, 0, x0, 0, sy, y0);
  cv::Mat out;
  cv::warpAffine(bgr, out, m, cv::Size(kInputSize, kInputSize),
                 cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar());
  cv::cvtColor(out, out, cv::COLOR_BGR2RGB);
  return out;
}

PoseKeypoints PoseNetwork::RunInput(const cv::Mat& rgb192) {
  CV_Assert(rgb192.type() == CV_8UC3 && rgb192.rows == kInputSize && rgb192.cols == kInputSize);
  cv::Mat blob =
      cv::dnn::blobFromImage(rgb192, 1.0, cv::Size(), cv::Scalar(), false, false, CV_32F);
  impl_->net.setInput(blob);
  std::vector<cv::Mat> outs;
  impl_->net.forward(outs, impl_->heads);
  const auto n = internal::DecodeMoveNet(outs[0], outs[1], outs[2], outs[3], impl_->constants);
  PoseKeypoints k;
  for (int i = 0; i < kPoseKeypointCount; ++i) {
    k.px[i] = {n[i].x * kInputSize, n[i].y * kInputSize};  // input pixels
    k.score[i] = n[i].score;
  }
  return k;
}

PoseKeypoints PoseNetwork::Run(const cv::Mat& bgr, const PoseCrop& crop) {
  PoseKeypoints k = RunInput(MakeInput(bgr, crop));
  ToImage(crop, &k);
  return k;
}

PoseKeypoints PoseNetwork::RunMirrored(const cv::Mat& bgr, const PoseCrop& crop) {
  cv::Mat mirrored;
  cv::flip(MakeInput(bgr, crop), mirrored, 1);
  const PoseKeypoints m = RunInput(mirrored);
  PoseKeypoints k;
  for (int i = 0; i < kPoseKeypointCount; ++i) {
    // The nose is 0; left and right pairs follow (1, 2), (3, 4), ... (15, 16).
    const int j = i == 0 ? 0 : (i % 2 == 1 ? i + 1 : i - 1);
    // Input column c mirrors to column 191 - c, and the network's x counts columns.
    k.px[i] = {(kInputSize - 1) - m.px[j].x, m.px[j].y};
    k.score[i] = m.score[j];
  }
  ToImage(crop, &k);
  return k;
}

}  // namespace armmimic
