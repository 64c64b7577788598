// The same-file rule: no command writes over one of its own inputs. Files are compared by
// device and inode, so a symlink, a hard link or another spelling of the path ("./a.tsv" and
// "a.tsv") is caught too. Both shells call this before they read anything.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/status.h"

namespace armmimic {

// A file a command reads or writes, with the flag or argument it came from ("-o", "VIDEO",
// "--background"), so the message can name both.
struct NamedPath {
  std::string role;
  std::string path;
};

// Fails when an output is the same file as an input. A folder among the inputs stands for the
// files directly in it (an image sequence). Outputs that do not exist yet match nothing. The
// message names both paths and their roles; the shells treat it as a usage error.
Status CheckOutputsAreNotInputs(const std::vector<NamedPath>& inputs,
                                const std::vector<NamedPath>& outputs);

// Fails when two outputs name the same file (two videos of a batch with the same name, or the
// same existing file reached by two spellings).
Status CheckOutputsAreDistinct(const std::vector<NamedPath>& outputs);

}  // namespace armmimic
