// The two scene kinds of `armmimic-cli synth`, each in its own file.
#pragma once

#include <string>
#include <vector>

#include "command.h"

namespace armmimic::cli {

int RunSynthArm(const std::vector<std::string>& args,
                const GlobalOptions& global);  // cmd_synth_arm.cpp
int RunSynthMarker(const std::vector<std::string>& args,
                   const GlobalOptions& global);  // cmd_synth_marker.cpp

}  // namespace armmimic::cli
