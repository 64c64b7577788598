// Placeholder until the marker engine lands; replaced wholesale by its implementation.
#include <stdexcept>

#include "engine_factories.h"

namespace armmimic {

Status MarkerOptions::Check() const { return Status::Ok(); }

namespace internal {
std::unique_ptr<Engine> CreateMarkerEngine(const MarkerOptions&) {
  throw std::logic_error("the marker engine is not built yet");
}
}  // namespace internal
}  // namespace armmimic
