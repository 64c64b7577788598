// Engine settings this version no longer has: options that no path the user can reach read any
// more, removed with the code that read them. Old angle files and GUI sessions still name them
// (a header records every setting), and old command lines may still set them. One list, used by
// every reader: a recorded run (analyze --params-from, an angle file or session opened in the
// GUI) skips them and says once which it skipped and why; setting one is refused with what
// replaced it.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/status.h"

namespace armmimic {

struct RemovedEngineOption {
  const char* key;          // "bgsub.reject_shadow", as the header and SetEngineOption spell it
  const char* replaced_by;  // what does its work now, or why nothing needs to
};

// Every removed setting.
const std::vector<RemovedEngineOption>& RemovedEngineOptions();

// The removed setting `key` ("ENGINE.KEY"), or nullptr when `key` was never removed.
const RemovedEngineOption* FindRemovedEngineOption(const std::string& key);

// The refusal to set `removed`, about its key: it was removed, why, and what replaced it.
Status RemovedEngineOptionError(const RemovedEngineOption& removed);

// One line that names the recorded settings `keys` (each a removed key) that were ignored, why,
// and what replaced each; "" when `keys` is empty.
std::string DescribeIgnoredEngineOptions(const std::vector<std::string>& keys);

}  // namespace armmimic
