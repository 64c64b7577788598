// The command line's words for a setting: the library keys its errors by setting ("analysis.start",
// Status::key()) and never names a flag; the CLI names the flag the setting is given with.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "armmimic/core/status.h"

namespace armmimic::cli {

// The flag that sets `key` ("analysis.arm_length" -> "--arm-length"); an engine parameter with no
// flag of its own is named as --param sets it ("--param lk.window_px"); "" for an unknown key.
std::string FlagForKey(const std::string& key);

// The analysis inputs (AnalysisOptions: no option table of their own) and their flags, as
// ("analysis.arm_length", "--arm-length"); analyze and mimic bind them to their parsers.
const std::vector<std::pair<std::string, std::string>>& AnalysisInputFlags();

// The status's message for a CLI user: "FLAG: message" when the status is keyed by a setting
// with a flag, else the message alone.
std::string Worded(const Status& status);

}  // namespace armmimic::cli
