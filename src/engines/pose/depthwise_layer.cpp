#include "pose/depthwise_layer.h"

#include <algorithm>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

namespace armmimic::internal {
namespace {

// The geometry of one layer's planes, stride 1.
struct Planes {
  int h = 0, w = 0;       // input
  int oh = 0, ow = 0;     // output
  int top = 0, left = 0;  // padding before
  int ph = 0, pw = 0;     // padded input
  int kh = 1, kw = 1;
  bool relu = false;
  float ceiling = 0;  // Relu6's 6, or the largest float
};

// One channel: the input is copied into a zero-padded plane of row pitch pw, and the sums are
// taken over whole padded rows as one long contiguous loop (a 3x3 kernel's nine taps in one pass,
// other kernels one pass per tap), which the compiler vectorises, instead of short rows with edge
// cases; the first ow sums of each row are the outputs. Compiled at -O3 (pose/CMakeLists.txt) and
// for AVX2 too, picked at run time where the processor has it. padded holds ph * pw + kw floats,
// zero outside the copied input; sums oh * pw.
__attribute__((target_clones("avx2", "default"))) void Plane(
    const Planes& g, const float* __restrict in, const float* __restrict w, float bias,
    float* __restrict padded, float* __restrict sums, float* __restrict out) {
  for (int y = 0; y < g.h; ++y) {
    float* __restrict row = padded + (y + g.top) * g.pw + g.left;
    for (int x = 0; x < g.w; ++x) row[x] = in[y * g.w + x];
  }
  // Bands of about 2048 sums, so that a band's sums and the rows it reads stay in the L1 cache
  // over all the taps.
  const int band = std::max(1, 2048 / g.pw);
  for (int y0 = 0; y0 < g.oh; y0 += band) {
    const int n = (std::min(y0 + band, g.oh) - y0) * g.pw;
    float* __restrict s = sums + y0 * g.pw;
    if (g.kh == 3 && g.kw == 3) {  // the common kernel: its nine sums kept in registers
      const float* __restrict r0 = padded + y0 * g.pw;
      const float* __restrict r1 = r0 + g.pw;
      const float* __restrict r2 = r1 + g.pw;
      for (int i = 0; i < n; ++i) {
        s[i] = bias + w[0] * r0[i] + w[1] * r0[i + 1] + w[2] * r0[i + 2] + w[3] * r1[i] +
               w[4] * r1[i + 1] + w[5] * r1[i + 2] + w[6] * r2[i] + w[7] * r2[i + 1] +
               w[8] * r2[i + 2];
      }
      continue;
    }
    for (int i = 0; i < n; ++i) s[i] = bias;
    for (int ky = 0; ky < g.kh; ++ky) {
      for (int kx = 0; kx < g.kw; ++kx) {
        const float wv = w[ky * g.kw + kx];
        const float* __restrict src = padded + (y0 + ky) * g.pw + kx;
        for (int i = 0; i < n; ++i) s[i] += wv * src[i];
      }
    }
  }
  for (int y = 0; y < g.oh; ++y) {
    const float* __restrict row = sums + y * g.pw;
    float* __restrict o = out + y * g.ow;
    if (g.relu) {
      // Written as comparisons, not std::min/max, so that it compiles to vector max and min.
      for (int x = 0; x < g.ow; ++x) {
        const float v = row[x] > 0.0f ? row[x] : 0.0f;
        o[x] = v < g.ceiling ? v : g.ceiling;
      }
    } else {
      for (int x = 0; x < g.ow; ++x) o[x] = row[x];
    }
  }
}

class DepthwiseLayer : public cv::dnn::Layer {
 public:
  explicit DepthwiseLayer(const cv::dnn::LayerParams& p) : cv::dnn::Layer(p) {
    kh_ = p.get<int>("kernel_h");
    kw_ = p.get<int>("kernel_w");
    CV_Assert(p.get<int>("stride_h", 1) == 1 && p.get<int>("stride_w", 1) == 1);
    same_ = p.get<std::string>("pad_mode", "VALID") == "SAME";
    const std::string act = p.get<std::string>("activation", "");
    relu_ = act == "Relu" || act == "Relu6";
    relu6_ = act == "Relu6";
    CV_Assert(!blobs.empty() && blobs[0].total() % static_cast<std::size_t>(kh_ * kw_) == 0);
  }

  static cv::Ptr<cv::dnn::Layer> Create(cv::dnn::LayerParams& p) {
    return cv::Ptr<cv::dnn::Layer>(new DepthwiseLayer(p));
  }

  bool getMemoryShapes(const std::vector<cv::dnn::MatShape>& inputs, int /*required*/,
                       std::vector<cv::dnn::MatShape>& outputs,
                       std::vector<cv::dnn::MatShape>& /*internals*/) const override {
    CV_Assert(inputs.size() == 1 && inputs[0].size() == 4);
    const cv::dnn::MatShape& s = inputs[0];
    CV_Assert(static_cast<std::size_t>(s[1]) * kh_ * kw_ == blobs[0].total());
    CV_Assert(same_ || (s[2] >= kh_ && s[3] >= kw_));
    outputs.assign(1, cv::dnn::MatShape{s[0], s[1], same_ ? s[2] : s[2] - kh_ + 1,
                                        same_ ? s[3] : s[3] - kw_ + 1});
    return false;
  }

  void forward(cv::InputArrayOfArrays inputs_arr, cv::OutputArrayOfArrays outputs_arr,
               cv::OutputArrayOfArrays /*internals*/) override {
    std::vector<cv::Mat> inputs, outputs;
    inputs_arr.getMatVector(inputs);
    outputs_arr.getMatVector(outputs);
    const cv::Mat& in = inputs[0];
    cv::Mat& out = outputs[0];
    const int channels = in.size[1];
    Planes g;
    g.h = in.size[2];
    g.w = in.size[3];
    g.oh = out.size[2];
    g.ow = out.size[3];
    // TensorFlow's SAME padding with stride 1: k - 1 pixels, the odd one after.
    g.top = same_ ? (kh_ - 1) / 2 : 0;
    g.left = same_ ? (kw_ - 1) / 2 : 0;
    g.ph = same_ ? g.h + kh_ - 1 : g.h;
    g.pw = same_ ? g.w + kw_ - 1 : g.w;
    g.kh = kh_;
    g.kw = kw_;
    g.relu = relu_;
    g.ceiling = relu6_ ? 6.0f : std::numeric_limits<float>::max();
    const float* src = in.ptr<float>();
    float* dst = out.ptr<float>();
    const float* kernel = blobs[0].ptr<float>();
    const float* bias = blobs.size() > 1 ? blobs[1].ptr<float>() : nullptr;
    cv::parallel_for_(cv::Range(0, in.size[0] * channels), [&](const cv::Range& r) {
      // kw floats of slack: the last tap reads past the last padded row.
      std::vector<float> padded(static_cast<std::size_t>(g.ph) * g.pw + kw_, 0.0f);
      std::vector<float> sums(static_cast<std::size_t>(g.oh) * g.pw);
      for (int p = r.start; p < r.end; ++p) {
        const int c = p % channels;
        Plane(g, src + static_cast<std::size_t>(p) * g.h * g.w, kernel + c * kh_ * kw_,
              bias ? bias[c] : 0.0f, padded.data(), sums.data(),
              dst + static_cast<std::size_t>(p) * g.oh * g.ow);
      }
    });
  }

 private:
  int kh_ = 1, kw_ = 1;
  bool same_ = false, relu_ = false, relu6_ = false;
};

}  // namespace

void RegisterDepthwiseLayer() {
  static std::once_flag once;
  std::call_once(once, [] {
    cv::dnn::LayerFactory::registerLayer(kDepthwiseLayerType, &DepthwiseLayer::Create);
  });
}

}  // namespace armmimic::internal
