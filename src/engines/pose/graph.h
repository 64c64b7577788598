// TfjsGraph: a TensorFlow.js graph model (model.json and its weight shards) read into plain
// structs: the nodes with their ops, inputs and attributes, and every weight as float32 (float16
// weights dequantised, int32 ones converted). Only reading happens here; pose/net.h builds the
// network from it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "armmimic/core/status.h"

namespace armmimic::internal {

struct TfjsAttr {
  std::vector<long long> ints;       // "i" or "list.i"
  std::vector<std::string> strings;  // "s" or "list.s", base64-decoded
  double number = 0;                 // "f"
  bool flag = false;                 // "b"
};

struct TfjsNode {
  std::string name;
  std::string op;
  std::vector<std::string> inputs;  // "node" or "node:1"
  std::map<std::string, TfjsAttr> attrs;
  const TfjsAttr* Attr(const std::string& key) const {
    const auto it = attrs.find(key);
    return it == attrs.end() ? nullptr : &it->second;
  }
};

struct TfjsTensor {
  std::vector<int> shape;  // as in TensorFlow (conv kernels HWIO, depthwise HWCM)
  std::vector<float> values;
};

struct TfjsGraph {
  std::vector<TfjsNode> nodes;                // in the file's order
  std::map<std::string, TfjsTensor> weights;  // by node name
  const TfjsNode* Find(const std::string& name) const;
  const TfjsTensor* Weight(const std::string& name) const;
};

// Reads `json_path` and the shards its manifest names (beside it). Messages name the file: a
// missing or short shard, a dtype or quantisation it cannot read, JSON it cannot parse.
Status ReadTfjsGraph(const std::string& json_path, TfjsGraph* out);

}  // namespace armmimic::internal
