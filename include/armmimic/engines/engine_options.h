// EngineOptions: the engine choice and every engine's parameters. The CLI and the GUI fill the
// same struct, so they produce the same angle file for the same options.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/status.h"
#include "armmimic/engines/bgsub_options.h"
#include "armmimic/engines/lk_options.h"
#include "armmimic/engines/marker_options.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic {

enum class EngineKind { kBgsub, kLk, kMarker, kPose };

const char* EngineName(EngineKind kind);  // "bgsub", "lk", "marker", "pose"
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
  Status Check() const;  // checks the chosen engine's options
};

}  // namespace armmimic
