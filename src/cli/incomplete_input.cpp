#include "incomplete_input.h"

#include <iostream>

#include "command.h"

namespace armmimic::cli {

std::optional<int> CheckCompleteInput(const std::string& command, const std::string& path,
                                      const AngleFile& angles, bool strict) {
  if (angles.complete) return std::nullopt;
  const std::string reason = angles.Meta("incomplete", "the run that wrote it stopped early");
  const std::string what = path + ": marked complete=no (" + reason + "); its rows stop early";
  if (strict) {
    std::cerr << "armmimic-cli " << command << ": " << what << "; refused by --strict\n";
    return kExitFailure;
  }
  std::cerr << "armmimic-cli " << command << ": warning: " << what << "\n";
  return std::nullopt;
}

}  // namespace armmimic::cli
