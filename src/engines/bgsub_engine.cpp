// Placeholder until the bgsub engine lands; replaced wholesale by its implementation.
#include <stdexcept>

#include "engine_factories.h"

namespace armmimic {

Status BgsubOptions::Check() const { return Status::Ok(); }

namespace internal {
std::unique_ptr<Engine> CreateBgsubEngine(const BgsubOptions&) {
  throw std::logic_error("the bgsub engine is not built yet");
}
}  // namespace internal
}  // namespace armmimic
