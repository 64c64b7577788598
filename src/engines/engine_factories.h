// Private: one factory per engine implementation, called by Engine::Create.
#pragma once

#include <memory>

#include "armmimic/engines/engine.h"

namespace armmimic::internal {

std::unique_ptr<Engine> CreateBgsubEngine(const BgsubOptions& options);
std::unique_ptr<Engine> CreateLkEngine(const LkOptions& options);
std::unique_ptr<Engine> CreateMarkerEngine(const MarkerOptions& options);
std::unique_ptr<Engine> CreatePoseEngine(const PoseOptions& options);

}  // namespace armmimic::internal
