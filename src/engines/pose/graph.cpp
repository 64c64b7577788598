// Reading a TensorFlow.js graph model with OpenCV's JSON reader (cv::FileStorage): the topology's
// nodes, then the weights manifest, whose entries lie back to back in the concatenated shards.
#include "pose/graph.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include <opencv2/core.hpp>

#include "armmimic/core/text.h"

namespace armmimic::internal {
namespace {

std::string Base64Decode(const std::string& in) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+' || c == '-') return 62;
    if (c == '/' || c == '_') return 63;
    return -1;
  };
  std::string out;
  int bits = 0;
  unsigned acc = 0;  // holds fewer than 14 bits between characters
  for (char c : in) {
    const int v = value(c);
    if (v < 0) continue;  // '=' padding, whitespace
    acc = (acc << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((acc >> bits) & 0xffu);
      acc &= (1u << bits) - 1;
    }
  }
  return out;
}

long long NodeInt(const cv::FileNode& n) {
  if (n.isString()) return std::stoll(static_cast<std::string>(n));
  return static_cast<long long>(static_cast<double>(n));
}

TfjsAttr ReadAttr(const cv::FileNode& a) {
  TfjsAttr attr;
  const cv::FileNode list = a["list"];
  const cv::FileNode ints = list.isMap() ? list["i"] : a["i"];
  if (ints.isSeq()) {
    for (const cv::FileNode& v : ints) attr.ints.push_back(NodeInt(v));
  } else if (!ints.empty() && !ints.isNone()) {
    attr.ints.push_back(NodeInt(ints));
  }
  const cv::FileNode strs = list.isMap() ? list["s"] : a["s"];
  if (strs.isSeq()) {
    for (const cv::FileNode& v : strs) attr.strings.push_back(Base64Decode(v));
  } else if (strs.isString()) {
    attr.strings.push_back(Base64Decode(strs));
  }
  if (a["f"].isReal() || a["f"].isInt()) attr.number = static_cast<double>(a["f"]);
  if (a["b"].isInt() || a["b"].isString()) {
    attr.flag = a["b"].isInt() ? static_cast<int>(a["b"]) != 0 : std::string(a["b"]) == "true";
  }
  return attr;
}

Status ReadNodes(const cv::FileNode& topology, const std::string& path, TfjsGraph* out) {
  const cv::FileNode nodes = topology["node"];
  if (!nodes.isSeq() || nodes.size() == 0) {
    return Status::Error(path + ": no modelTopology.node list (not a TensorFlow.js graph model)");
  }
  for (const cv::FileNode& n : nodes) {
    TfjsNode node;
    node.name = static_cast<std::string>(n["name"]);
    node.op = static_cast<std::string>(n["op"]);
    if (node.name.empty() || node.op.empty()) {
      return Status::Error(path + ": a node without a name or op");
    }
    for (const cv::FileNode& i : n["input"]) node.inputs.push_back(static_cast<std::string>(i));
    const cv::FileNode attrs = n["attr"];
    if (attrs.isMap()) {
      for (const cv::FileNode& a : attrs) {
        if (a.name() == "value" || a.name() == "_output_shapes") continue;
        node.attrs[a.name()] = ReadAttr(a);
      }
    }
    out->nodes.push_back(std::move(node));
  }
  return Status::Ok();
}

std::string Dir(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// One manifest group: its shards concatenated, then its weights read back to back.
Status ReadGroup(const cv::FileNode& group, const std::string& json_path, TfjsGraph* out) {
  std::string bytes;
  std::string shard_names;
  for (const cv::FileNode& p : group["paths"]) {
    const std::string shard = Dir(json_path) + static_cast<std::string>(p);
    std::ifstream in(shard, std::ios::binary);
    if (!in) return Status::Error(shard + ": cannot open (" + ErrnoText(errno) + ")");
    bytes.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    shard_names += (shard_names.empty() ? "" : ", ") + shard;
  }
  std::size_t offset = 0;
  for (const cv::FileNode& w : group["weights"]) {
    const std::string name = w["name"];
    const std::string dtype = w["dtype"];
    TfjsTensor t;
    std::size_t count = 1;
    for (const cv::FileNode& d : w["shape"]) {
      t.shape.push_back(static_cast<int>(NodeInt(d)));
      count *= static_cast<std::size_t>(t.shape.back());
    }
    const cv::FileNode q = w["quantization"];
    const std::string qtype = q.isMap() ? static_cast<std::string>(q["dtype"]) : std::string();
    std::size_t item = 4;
    if (!qtype.empty()) {
      if (qtype != "float16") {
        return Status::Error(json_path + ": weight " + name + " is quantised as " + qtype +
                             ", only float16 is read");
      }
      item = 2;
    } else if (dtype != "float32" && dtype != "int32") {
      return Status::Error(json_path + ": weight " + name + " has dtype " + dtype +
                           ", only float32 and int32 are read");
    }
    if (offset + count * item > bytes.size()) {
      return Status::Error(shard_names + " is truncated: " + std::to_string(bytes.size()) +
                           " bytes, but weight " + name + " needs bytes up to " +
                           std::to_string(offset + count * item));
    }
    t.values.resize(count);
    const char* src = bytes.data() + offset;
    for (std::size_t i = 0; i < count; ++i) {
      if (item == 2) {
        std::uint16_t h;
        std::memcpy(&h, src + 2 * i, 2);
        t.values[i] = static_cast<float>(cv::float16_t::fromBits(h));
      } else if (dtype == "int32") {
        std::int32_t v;
        std::memcpy(&v, src + 4 * i, 4);
        t.values[i] = static_cast<float>(v);
      } else {
        std::memcpy(&t.values[i], src + 4 * i, 4);
      }
    }
    offset += count * item;
    out->weights[name] = std::move(t);
  }
  if (offset != bytes.size()) {
    return Status::Error(shard_names + " has " + std::to_string(bytes.size()) +
                         " bytes, the manifest in " + json_path + " describes " +
                         std::to_string(offset));
  }
  return Status::Ok();
}

}  // namespace

const TfjsNode* TfjsGraph::Find(const std::string& name) const {
  for (const TfjsNode& n : nodes) {
    if (n.name == name) return &n;
  }
  return nullptr;
}

const TfjsTensor* TfjsGraph::Weight(const std::string& name) const {
  const auto it = weights.find(name);
  return it == weights.end() ? nullptr : &it->second;
}

Status ReadTfjsGraph(const std::string& json_path, TfjsGraph* out) {
  *out = TfjsGraph();
  try {
    cv::FileStorage fs(json_path, cv::FileStorage::READ | cv::FileStorage::FORMAT_JSON);
    if (!fs.isOpened()) return Status::Error(json_path + ": cannot open");
    Status st = ReadNodes(fs["modelTopology"], json_path, out);
    if (!st) return st;
    const cv::FileNode manifest = fs["weightsManifest"];
    if (!manifest.isSeq()) return Status::Error(json_path + ": no weightsManifest");
    for (const cv::FileNode& group : manifest) {
      st = ReadGroup(group, json_path, out);
      if (!st) return st;
    }
  } catch (const cv::Exception& e) {
    return Status::Error(json_path + ": not readable as JSON (" + e.msg + ")");
  } catch (const std::exception& e) {
    return Status::Error(json_path + ": malformed (" + e.what() + ")");
  }
  return Status::Ok();
}

}  // namespace armmimic::internal
