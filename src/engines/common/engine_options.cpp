#include "armmimic/engines/engine_options.h"

namespace armmimic {

const char* EngineName(EngineKind kind) {
  switch (kind) {
    case EngineKind::kBgsub:
      return "bgsub";
    case EngineKind::kLk:
      return "lk";
    case EngineKind::kMarker:
      return "marker";
    case EngineKind::kPose:
      return "pose";
    case EngineKind::kHybrid:
      return "hybrid";
  }
  return "?";
}

const std::vector<EngineKind>& AllEngineKinds() {
  static const std::vector<EngineKind> kinds = {EngineKind::kBgsub, EngineKind::kLk,
                                                EngineKind::kMarker, EngineKind::kPose,
                                                EngineKind::kHybrid};
  return kinds;
}

bool IsArmEngine(EngineKind kind) { return kind != EngineKind::kMarker; }

bool ParseEngineKind(const std::string& name, EngineKind* out) {
  for (EngineKind k : AllEngineKinds()) {
    if (name == EngineName(k)) {
      *out = k;
      return true;
    }
  }
  return false;
}

Status EngineOptions::Check() const {
  switch (kind) {
    case EngineKind::kBgsub:
      return bgsub.Check();
    case EngineKind::kLk:
      return lk.Check();
    case EngineKind::kMarker:
      return marker.Check();
    case EngineKind::kPose:
      return pose.Check();
    case EngineKind::kHybrid:
      if (Status st = hybrid.Check(); !st) return st;
      if (Status st = lk.Check(); !st) return st;
      return bgsub.Check();
  }
  return Status::Ok();
}

}  // namespace armmimic
