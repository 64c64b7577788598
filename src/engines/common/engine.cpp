#include "armmimic/engines/engine.h"

#include <stdexcept>

#include "common/engine_internal.h"

namespace armmimic {

std::unique_ptr<Engine> Engine::Create(const EngineOptions& options) {
  const Status st = options.Check();
  if (!st) throw std::invalid_argument("Engine::Create: " + st.message());
  switch (options.kind) {
    case EngineKind::kBgsub:
      return internal::CreateBgsubEngine(options.bgsub);
    case EngineKind::kLk:
      return internal::CreateLkEngine(options.lk);
    case EngineKind::kMarker:
      return internal::CreateMarkerEngine(options.marker);
    case EngineKind::kPose:
      return internal::CreatePoseEngine(options.pose);
    case EngineKind::kHybrid:
      return internal::CreateHybridEngine(options.hybrid, options.lk, options.bgsub, options.pose);
  }
  throw std::invalid_argument("Engine::Create: unknown engine kind");
}

}  // namespace armmimic
