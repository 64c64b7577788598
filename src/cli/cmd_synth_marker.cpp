// Placeholder until the marker scene generator lands; replaced wholesale by it.
#include <iostream>

#include "synth_commands.h"

namespace armmimic::cli {

int RunSynthMarker(const std::vector<std::string>&, const GlobalOptions&) {
  std::cerr << "armmimic-cli synth marker: not built yet\n";
  return kExitFailure;
}

}  // namespace armmimic::cli
