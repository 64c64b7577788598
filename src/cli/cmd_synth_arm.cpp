// Placeholder until the arm scene generator lands; replaced wholesale by it.
#include <iostream>

#include "synth_commands.h"

namespace armmimic::cli {

int RunSynthArm(const std::vector<std::string>&, const GlobalOptions&) {
  std::cerr << "armmimic-cli synth arm: not built yet\n";
  return kExitFailure;
}

}  // namespace armmimic::cli
