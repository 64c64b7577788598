// TensorFlow ops to cv::dnn layers. TF tensors are NHWC with HWIO kernels; cv::dnn is NCHW with
// OIHW kernels, so every kernel is transposed here. TF's SAME padding (on a stride-2 conv over an
// even size: 0 before, 1 after) is cv::dnn's pad_mode SAME, which splits the padding the same way.
#include "pose/net.h"

#include <functional>
#include <map>
#include <set>

#include "pose/depthwise_layer.h"

namespace armmimic::internal {
namespace {

struct Ref {
  int layer = 0;     // cv::dnn layer id (0: the net's input)
  int output = 0;    // output index of that layer
  int channels = 0;  // C of the NCHW blob
};

std::string BaseName(const std::string& input) {
  std::string s = input;
  if (!s.empty() && s[0] == '^') s.erase(0, 1);
  const auto colon = s.find(':');
  return colon == std::string::npos ? s : s.substr(0, colon);
}

class Builder {
 public:
  Builder(const TfjsGraph& g, cv::dnn::Net* net) : g_(g), net_(net) {}

  Status Build(const std::string& input_node, const std::vector<std::string>& outputs) {
    input_ = input_node;
    for (const std::string& o : outputs) {
      Status st = Visit(o);
      if (!st) return st;
    }
    net_->setInputsNames({input_node});
    return Status::Ok();
  }

 private:
  // Depth-first: a node's inputs are built before it.
  Status Visit(const std::string& name) {
    if (refs_.count(name) || g_.Weight(name)) return Status::Ok();
    if (visiting_.count(name)) return Status::Error("the graph has a cycle at node " + name);
    const TfjsNode* n = g_.Find(name);
    if (!n) return Status::Error("node " + name + " is used but not defined");
    visiting_.insert(name);
    for (const std::string& in : n->inputs) {
      if (in.empty() || in[0] == '^') continue;
      Status st = Visit(BaseName(in));
      if (!st) return st;
    }
    visiting_.erase(name);
    return Add(*n);
  }

  const TfjsTensor* Const(const TfjsNode& n, std::size_t i) const {
    return i < n.inputs.size() ? g_.Weight(BaseName(n.inputs[i])) : nullptr;
  }
  const Ref* Tensor(const TfjsNode& n, std::size_t i) const {
    if (i >= n.inputs.size()) return nullptr;
    const auto it = refs_.find(BaseName(n.inputs[i]));
    return it == refs_.end() ? nullptr : &it->second;
  }
  Status Need(const TfjsNode& n, bool ok, const std::string& what) const {
    return ok ? Status::Ok() : Status::Error("node " + n.name + " (" + n.op + "): " + what);
  }

  int AddLayer(const std::string& name, const std::string& type, cv::dnn::LayerParams& p,
               const std::vector<Ref>& inputs) {
    p.name = name;
    p.type = type;
    const int id = net_->addLayer(name, type, p);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      net_->connect(inputs[i].layer, inputs[i].output, id, static_cast<int>(i));
    }
    return id;
  }

  // y = x * scale + shift per channel (scalars broadcast).
  Status AddAffine(const TfjsNode& n, const Ref& x, const std::vector<float>& scale,
                   const std::vector<float>& shift) {
    auto expand = [&](const std::vector<float>& v) -> cv::Mat {
      cv::Mat m(1, x.channels, CV_32F);
      for (int c = 0; c < x.channels; ++c) m.at<float>(c) = v.size() == 1 ? v[0] : v[c];
      return m;
    };
    const bool per_channel_ok =
        (scale.size() == 1 || static_cast<int>(scale.size()) == x.channels) &&
        (shift.size() == 1 || static_cast<int>(shift.size()) == x.channels);
    Status st = Need(n, per_channel_ok, "its constant is neither a scalar nor per channel");
    if (!st) return st;
    cv::dnn::LayerParams p;
    p.set("axis", 1);
    p.set("bias_term", true);
    p.blobs = {expand(scale), expand(shift)};
    refs_[n.name] = {AddLayer(n.name, "Scale", p, {x}), 0, x.channels};
    return Status::Ok();
  }

  Status AddConv(const TfjsNode& n, bool depthwise) {
    const Ref* x = Tensor(n, 0);
    const TfjsTensor* w = Const(n, 1);
    Status st = Need(n, x && w && w->shape.size() == 4, "needs a tensor and a 4-D kernel");
    if (!st) return st;
    const TfjsAttr* strides = n.Attr("strides");
    const TfjsAttr* dil = n.Attr("dilations");
    const TfjsAttr* pad = n.Attr("padding");
    const std::string padding = pad && !pad->strings.empty() ? pad->strings[0] : "VALID";
    st = Need(n, padding == "SAME" || padding == "VALID", "padding " + padding + " is not read");
    if (!st) return st;
    std::vector<std::string> fused;
    if (const TfjsAttr* f = n.Attr("fused_ops")) fused = f->strings;
    const bool has_bias = !fused.empty() && fused[0] == "BiasAdd";
    const TfjsTensor* bias = has_bias ? Const(n, 2) : nullptr;
    st = Need(n, !has_bias || bias, "BiasAdd without a constant bias");
    if (!st) return st;
    std::string activation;
    for (std::size_t i = has_bias ? 1 : 0; i < fused.size(); ++i) {
      st = Need(n, fused[i] == "Relu" || fused[i] == "Relu6" || fused[i] == "BiasAdd",
                "fused op " + fused[i] + " is not read");
      if (!st) return st;
      if (fused[i] != "BiasAdd") activation = fused[i];
    }
    const int kh = w->shape[0], kw = w->shape[1], cin = w->shape[2], m = w->shape[3];
    st = Need(n, cin == x->channels,
              "kernel expects " + std::to_string(cin) + " channels, its input has " +
                  std::to_string(x->channels));
    if (!st) return st;
    const int cout = depthwise ? cin * m : m;
    cv::Mat kernel(std::vector<int>{cout, depthwise ? 1 : cin, kh, kw}, CV_32F);
    float* k = kernel.ptr<float>();
    for (int y = 0; y < kh; ++y)
      for (int xk = 0; xk < kw; ++xk)
        for (int c = 0; c < cin; ++c)
          for (int o = 0; o < m; ++o) {
            const float v = w->values[((y * kw + xk) * cin + c) * m + o];
            if (depthwise) {
              k[((c * m + o) * kh + y) * kw + xk] = v;
            } else {
              k[((o * cin + c) * kh + y) * kw + xk] = v;
            }
          }
    cv::dnn::LayerParams p;
    p.set("kernel_h", kh);
    p.set("kernel_w", kw);
    p.set("stride_h",
          strides && strides->ints.size() == 4 ? static_cast<int>(strides->ints[1]) : 1);
    p.set("stride_w",
          strides && strides->ints.size() == 4 ? static_cast<int>(strides->ints[2]) : 1);
    p.set("dilation_h", dil && dil->ints.size() == 4 ? static_cast<int>(dil->ints[1]) : 1);
    p.set("dilation_w", dil && dil->ints.size() == 4 ? static_cast<int>(dil->ints[2]) : 1);
    p.set("pad_mode", padding);
    p.set("num_output", cout);
    p.set("group", depthwise ? cin : 1);
    p.set("bias_term", has_bias);
    p.blobs.push_back(kernel);
    if (has_bias) {
      st = Need(n, static_cast<int>(bias->values.size()) == cout, "bias size");
      if (!st) return st;
      p.blobs.push_back(cv::Mat(1, cout, CV_32F, const_cast<float*>(bias->values.data())).clone());
    }
    if (depthwise && m == 1 && p.get<int>("stride_h") == 1 && p.get<int>("stride_w") == 1 &&
        p.get<int>("dilation_h") == 1 && p.get<int>("dilation_w") == 1) {
      // One kernel per channel, stride 1: armmimic's own layer, the activation in its pass.
      p.set("activation", activation);
      refs_[n.name] = {AddLayer(n.name, kDepthwiseLayerType, p, {*x}), 0, cout};
      return Status::Ok();
    }
    const std::string conv_name = activation.empty() ? n.name : n.name + "/conv";
    Ref out{AddLayer(conv_name, "Convolution", p, {*x}), 0, cout};
    if (!activation.empty()) out = AddActivation(n.name, activation, out);
    refs_[n.name] = out;
    return Status::Ok();
  }

  Ref AddActivation(const std::string& name, const std::string& op, const Ref& x) {
    cv::dnn::LayerParams p;
    std::string type = op == "Sigmoid" ? "Sigmoid" : "ReLU";
    if (op == "Relu6") {
      type = "ReLU6";
      p.set("min_value", 0.0f);
      p.set("max_value", 6.0f);
    }
    return {AddLayer(name, type, p, {x}), 0, x.channels};
  }

  Status AddResize(const TfjsNode& n) {
    const Ref* x = Tensor(n, 0);
    const TfjsTensor* size = Const(n, 1);
    Status st = Need(n, x && size && size->values.size() == 2, "needs a tensor and a size");
    if (!st) return st;
    cv::dnn::LayerParams p;
    p.set("interpolation", "bilinear");
    p.set("height", static_cast<int>(size->values[0]));
    p.set("width", static_cast<int>(size->values[1]));
    const TfjsAttr* ac = n.Attr("align_corners");
    const TfjsAttr* hp = n.Attr("half_pixel_centers");
    p.set("align_corners", ac && ac->flag);
    p.set("half_pixel_centers", hp && hp->flag);
    refs_[n.name] = {AddLayer(n.name, "Resize", p, {*x}), 0, x->channels};
    return Status::Ok();
  }

  // TF's Pad with constant paddings [4, 2] (NHWC): zeros around H and W only.
  Status AddPad(const TfjsNode& n) {
    const Ref* x = Tensor(n, 0);
    const TfjsTensor* pads = Const(n, 1);
    Status st = Need(n, x && pads && pads->values.size() == 8,
                     "needs a tensor and constant paddings of shape [4, 2]");
    if (!st) return st;
    const std::vector<float>& v = pads->values;  // (N, H, W, C) x (before, after)
    st = Need(n, v[0] == 0 && v[1] == 0 && v[6] == 0 && v[7] == 0,
              "pads the batch or channel axis, only H and W are read");
    if (!st) return st;
    for (float p : v) {
      st = Need(n, p >= 0, "a negative padding");
      if (!st) return st;
    }
    if (const TfjsAttr* mode = n.Attr("mode"); mode && !mode->strings.empty()) {
      st = Need(n, mode->strings[0] == "CONSTANT", "mode " + mode->strings[0] + " is not read");
      if (!st) return st;
    }
    const int nchw[8] = {0,
                         0,
                         0,
                         0,
                         static_cast<int>(v[2]),
                         static_cast<int>(v[3]),
                         static_cast<int>(v[4]),
                         static_cast<int>(v[5])};
    cv::dnn::LayerParams p;
    p.set("paddings", cv::dnn::DictValue::arrayInt(nchw, 8));
    p.set("value", 0.0f);
    p.set("type", "constant");
    refs_[n.name] = {AddLayer(n.name, "Padding", p, {*x}), 0, x->channels};
    return Status::Ok();
  }

  // MaxPool over H and W (NHWC ksize and strides, SAME or VALID).
  Status AddMaxPool(const TfjsNode& n) {
    const Ref* x = Tensor(n, 0);
    const TfjsAttr* ksize = n.Attr("ksize");
    const TfjsAttr* strides = n.Attr("strides");
    const TfjsAttr* pad = n.Attr("padding");
    const TfjsAttr* format = n.Attr("data_format");
    Status st =
        Need(n, x && ksize && ksize->ints.size() == 4 && strides && strides->ints.size() == 4,
             "needs a tensor, ksize and strides of four");
    if (!st) return st;
    st = Need(n, !format || format->strings.empty() || format->strings[0] == "NHWC",
              "data_format " + (format && !format->strings.empty() ? format->strings[0] : "") +
                  " is not read");
    if (!st) return st;
    st = Need(n,
              ksize->ints[0] == 1 && ksize->ints[3] == 1 && strides->ints[0] == 1 &&
                  strides->ints[3] == 1,
              "pools across the batch or channels");
    if (!st) return st;
    const std::string padding = pad && !pad->strings.empty() ? pad->strings[0] : "VALID";
    st = Need(n, padding == "SAME" || padding == "VALID", "padding " + padding + " is not read");
    if (!st) return st;
    cv::dnn::LayerParams p;
    p.set("pool", "max");
    p.set("kernel_h", static_cast<int>(ksize->ints[1]));
    p.set("kernel_w", static_cast<int>(ksize->ints[2]));
    p.set("stride_h", static_cast<int>(strides->ints[1]));
    p.set("stride_w", static_cast<int>(strides->ints[2]));
    p.set("pad_mode", padding);
    refs_[n.name] = {AddLayer(n.name, "Pooling", p, {*x}), 0, x->channels};
    return Status::Ok();
  }

  // Reshape to [batch, K] (a constant shape [-1 or 1, K]): the NHWC blob flattened in TF's order,
  // so the NCHW blob is put back to NHWC first. Other shapes are not read.
  Status AddReshape(const TfjsNode& n) {
    const Ref* x = Tensor(n, 0);
    const TfjsTensor* shape = Const(n, 1);
    Status st = Need(n, x && shape, "needs a tensor and a constant shape");
    if (!st) return st;
    const std::vector<float>& v = shape->values;
    st = Need(n, v.size() == 2 && (v[0] == -1 || v[0] == 1) && v[1] > 0,
              "only a reshape to [batch, K] is read");
    if (!st) return st;
    const int k = static_cast<int>(v[1]);
    st = Need(n, k % x->channels == 0,
              "K " + std::to_string(k) + " is not a multiple of the input's " +
                  std::to_string(x->channels) + " channels");
    if (!st) return st;
    const int order[4] = {0, 2, 3, 1};
    cv::dnn::LayerParams permute;
    permute.set("order", cv::dnn::DictValue::arrayInt(order, 4));
    const Ref nhwc{AddLayer(n.name + "/nhwc", "Permute", permute, {*x}), 0, x->channels};
    cv::dnn::LayerParams flatten;
    flatten.set("axis", 1);
    flatten.set("end_axis", -1);
    refs_[n.name] = {AddLayer(n.name, "Flatten", flatten, {nhwc}), 0, k};
    return Status::Ok();
  }

  // Sub, Mul and AddV2: with a constant operand a per-channel affine layer, else an element sum.
  Status AddArithmetic(const TfjsNode& n) {
    const Ref* a = Tensor(n, 0);
    const Ref* b = Tensor(n, 1);
    const TfjsTensor* ca = Const(n, 0);
    const TfjsTensor* cb = Const(n, 1);
    if (n.op == "AddV2" && a && b) {
      cv::dnn::LayerParams p;
      p.set("operation", "sum");
      refs_[n.name] = {AddLayer(n.name, "Eltwise", p, {*a, *b}), 0, a->channels};
      return Status::Ok();
    }
    const Ref* x = a ? a : b;
    const TfjsTensor* c = a ? cb : ca;
    Status st = Need(n, x && c, "needs one tensor and one constant operand");
    if (!st) return st;
    if (n.op == "Mul") return AddAffine(n, *x, c->values, {0.0f});
    std::vector<float> shift = c->values;
    if (n.op == "Sub" && a) {
      for (float& v : shift) v = -v;  // x - c
      return AddAffine(n, *x, {1.0f}, shift);
    }
    if (n.op == "Sub") return AddAffine(n, *x, {-1.0f}, shift);  // c - x
    return AddAffine(n, *x, {1.0f}, shift);                      // x + c
  }

  Status Add(const TfjsNode& n) {
    const std::string& op = n.op;
    if (op == "Const") return Status::Error("constant " + n.name + " has no weight data");
    if (op == "Placeholder") {
      Status st = Need(n, n.name == input_, "is not the input " + input_);
      if (!st) return st;
      int channels = 3;
      if (const TfjsAttr* s = n.Attr("shape"); s && s->ints.size() == 4) {
        channels = static_cast<int>(s->ints[3]);
      }
      refs_[n.name] = {0, 0, channels};
      return Status::Ok();
    }
    if (op == "Identity" || op == "Cast" || op == "Unpack" || op == "ExpandDims" ||
        op == "Squeeze") {
      const Ref* x = Tensor(n, 0);
      Status st = Need(n, x != nullptr, "needs a tensor input");
      if (!st) return st;
      refs_[n.name] = *x;  // batch-1 shape ops and the int32 to float cast change nothing here
      return Status::Ok();
    }
    if (op == "_FusedConv2D" || op == "Conv2D") return AddConv(n, false);
    if (op == "FusedDepthwiseConv2dNative" || op == "DepthwiseConv2dNative")
      return AddConv(n, true);
    if (op == "ResizeBilinear") return AddResize(n);
    if (op == "Pad") return AddPad(n);
    if (op == "MaxPool") return AddMaxPool(n);
    if (op == "Reshape") return AddReshape(n);
    if (op == "Sub" || op == "Mul" || op == "AddV2") return AddArithmetic(n);
    if (op == "Relu" || op == "Relu6" || op == "Sigmoid") {
      const Ref* x = Tensor(n, 0);
      Status st = Need(n, x != nullptr, "needs a tensor input");
      if (!st) return st;
      refs_[n.name] = AddActivation(n.name, op, *x);
      return Status::Ok();
    }
    return Status::Error("unknown op '" + op + "' (node " + n.name + ")");
  }

  const TfjsGraph& g_;
  cv::dnn::Net* net_;
  std::string input_;
  std::map<std::string, Ref> refs_;
  std::set<std::string> visiting_;
};

}  // namespace

Status BuildTfjsNet(const TfjsGraph& graph, const std::string& input_node,
                    const std::vector<std::string>& output_nodes, cv::dnn::Net* net) {
  *net = cv::dnn::Net();
  RegisterDepthwiseLayer();
  try {
    return Builder(graph, net).Build(input_node, output_nodes);
  } catch (const cv::Exception& e) {
    return Status::Error("building the network failed: " + e.msg);
  }
}

}  // namespace armmimic::internal
