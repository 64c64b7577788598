// The earlier names of the output path in output_file.h: AtomicFile is OutputFile, and
// WriteFileAtomically is WriteOutputFile. New code includes output_file.h.
#pragma once

#include <string>

#include "armmimic/core/output_file.h"

namespace armmimic {

using AtomicFile = OutputFile;

inline Status WriteFileAtomically(const std::string& path, const std::string& bytes) {
  return WriteOutputFile(path, bytes);
}

}  // namespace armmimic
