// EngineOptions: the engine choice and every engine's parameters. The CLI and the GUI fill the
// same struct, so they produce the same angle file for the same options.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/status.h"
#include "armmimic/engines/bgsub_options.h"
#include "armmimic/engines/hybrid_options.h"
#include "armmimic/engines/lk_options.h"
#include "armmimic/engines/marker_options.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic {

// New kinds go last: the GUI stores a kind as its number.
enum class EngineKind { kBgsub, kLk, kMarker, kPose, kHybrid };

const char* EngineName(EngineKind kind);  // "bgsub", "lk", "marker", "pose", "hybrid"
bool ParseEngineKind(const std::string& name, EngineKind* out);
// Every engine, in the order above. A new engine joins this list, and the parsers and the
// robustness benchmark (bench/robustness.cpp) find it here.
const std::vector<EngineKind>& AllEngineKinds();
// Engines that measure a human arm (all but the marker engine).
bool IsArmEngine(EngineKind kind);

struct EngineOptions {
  EngineKind kind = EngineKind::kBgsub;
  BgsubOptions bgsub;
  LkOptions lk;
  MarkerOptions marker;
  PoseOptions pose;
  HybridOptions hybrid;  // the hybrid engine's own; it also takes lk's and bgsub's
  Status Check() const;  // checks the chosen engine's options
};

}  // namespace armmimic
