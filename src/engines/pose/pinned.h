// The pinned model files of a pose network (scripts/models.sh lists the same SHA-256s): found in
// the model folders (FindPoseModelDir), checked by size and SHA-256. Every failure names the file
// and says which package, or which command of a source tree, provides it.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/status.h"

namespace armmimic::internal {

struct PinnedFile {
  const char* name;
  long long bytes;
  const char* sha256;
};

// "install the package armmimic-models, or fetch the model with scripts/deps.sh ...".
std::string FetchAdvice();

// The folder holding `files` (the first is the graph JSON that is looked for), checked; "" with
// `status` set (key analysis.model) when it is not found or a file is missing, truncated or
// altered.
std::string FindPinnedModel(const std::string& flag_dir, const std::vector<PinnedFile>& files,
                            Status* status);

}  // namespace armmimic::internal
