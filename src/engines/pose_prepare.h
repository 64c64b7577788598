// Private: the analysis pipeline's pose steps before the engine starts.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/status.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic::internal {

// The arm better seen over frames [start, start + one second): the scores summed over a few
// frames. *why says what was decided, for the shells to show.
Status ChoosePoseSide(const std::vector<std::string>& inputs, int start, double fps,
                      const std::string& model_dir, PoseSide* side, std::string* why);

}  // namespace armmimic::internal
