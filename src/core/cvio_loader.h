// Finds and loads the armmimic-cvio module (cvio/cvio_api.h) on first use. Private to src/core.
#pragma once

#include "armmimic/core/status.h"
#include "cvio/cvio_api.h"

namespace armmimic::internal {

// The module's Api, loaded once per process; nullptr with *status naming where it was looked
// for (beside the program, then in the build tree) and why it did not load.
const cvio::Api* CvioModule(Status* status);

}  // namespace armmimic::internal
