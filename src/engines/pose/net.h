// Builds a cv::dnn::Net in code (addLayer/LayerParams) from a TensorFlow.js graph, cut at chosen
// output nodes: only the nodes those outputs depend on are built, so a decoder after them (done
// in C++ instead) does not need to be understood. The network takes one NCHW float blob of batch
// 1; shape-only ops on the batch axis pass their input through.
#pragma once

#include <string>
#include <vector>

#include <opencv2/dnn.hpp>

#include "armmimic/core/status.h"
#include "pose/graph.h"

namespace armmimic::internal {

// Ops the builder knows: Placeholder, Const, Identity, Cast, Unpack, ExpandDims, Squeeze (batch
// axis), Sub/Mul/AddV2 with a constant (per-channel scale and shift), AddV2 of two tensors,
// _FusedConv2D and FusedDepthwiseConv2dNative (BiasAdd, then Relu or Relu6),
// DepthwiseConv2dNative, Conv2D, ResizeBilinear, Relu, Relu6, Sigmoid, Pad (zeros around H and
// W), MaxPool (over H and W) and Reshape to [batch, K] (flattened in TF's NHWC order; the output
// is then a 2-D blob 1 x K). Any other op needed by an output fails with
// "unknown op 'OP' (node NAME)".
Status BuildTfjsNet(const TfjsGraph& graph, const std::string& input_node,
                    const std::vector<std::string>& output_nodes, cv::dnn::Net* net);

}  // namespace armmimic::internal
