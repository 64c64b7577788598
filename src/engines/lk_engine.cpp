// Placeholder until the lk engine lands; replaced wholesale by its implementation.
#include <stdexcept>

#include "engine_factories.h"

namespace armmimic {

Status LkOptions::Check() const { return Status::Ok(); }

namespace internal {
std::unique_ptr<Engine> CreateLkEngine(const LkOptions&) {
  throw std::logic_error("the lk engine is not built yet");
}
}  // namespace internal
}  // namespace armmimic
