// plan's and send's word on an angle file marked complete=no (an interrupted run, a truncated
// video): a warning, or with --strict a refusal (docs/cli.md).
#pragma once

#include <optional>
#include <string>

#include "armmimic/core/angle_file.h"

namespace armmimic::cli {

// Warns on stderr when `angles` (read from `path`) is marked complete=no; with `strict`,
// prints the refusal instead and returns exit 1 (the file's content is the fault, not a flag).
std::optional<int> CheckCompleteInput(const std::string& command, const std::string& path,
                                      const AngleFile& angles, bool strict);

}  // namespace armmimic::cli
