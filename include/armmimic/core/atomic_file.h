// AtomicFile: write a file as a temporary beside the target and rename it into place, so an
// interrupted run leaves either the complete previous file or the complete new one.
#pragma once

#include <cstdio>
#include <string>

#include "armmimic/core/status.h"

namespace armmimic {

class AtomicFile {
 public:
  AtomicFile() = default;
  ~AtomicFile();  // removes the temporary if Commit() was not reached
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Creates "<dir>/.<name>.XXXXXX". Fails with a message naming `path` when the directory is
  // missing or not writable.
  Status Open(const std::string& path);
  std::FILE* file() { return file_; }
  const std::string& temp_path() const { return temp_path_; }
  const std::string& path() const { return path_; }
  // Flushes, fsyncs and renames over the target.
  Status Commit();
  // Closes and removes the temporary.
  void Discard();

 private:
  std::string path_;
  std::string temp_path_;
  std::FILE* file_ = nullptr;
};

// Writes `bytes` to `path` atomically.
Status WriteFileAtomically(const std::string& path, const std::string& bytes);

}  // namespace armmimic
