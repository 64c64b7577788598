#include "pose/pinned.h"

#include <sys/stat.h>

#include "armmimic/core/sha256.h"
#include "armmimic/engines/pose.h"

namespace armmimic::internal {
namespace {

bool FileExists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

long long FileSize(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? static_cast<long long>(st.st_size) : -1;
}

Status CheckPinned(const std::string& dir, const std::vector<PinnedFile>& files) {
  for (const PinnedFile& f : files) {
    const std::string path = dir + "/" + f.name;
    if (!FileExists(path)) return Status::Error(path + " not found; " + FetchAdvice());
  }
  for (const PinnedFile& f : files) {
    const std::string path = dir + "/" + f.name;
    const long long size = FileSize(path);
    if (size != f.bytes) {
      return Status::Error(path + " is " + (size < f.bytes ? "truncated" : "not the pinned file") +
                           " (" + std::to_string(size) + " bytes, the pinned model has " +
                           std::to_string(f.bytes) + "); " + FetchAdvice());
    }
    std::string hex;
    Status st = Sha256File(path, &hex);
    if (!st) return st;
    if (hex != f.sha256) {
      return Status::Error(path + " does not match the pinned model (SHA-256 " + hex +
                           ", expected " + f.sha256 + "); " + FetchAdvice());
    }
  }
  return Status::Ok();
}

}  // namespace

std::string FetchAdvice() {
  return std::string("install the package ") + kPoseModelPackage +
         ", or fetch the model with scripts/deps.sh --with-model in armmimic's source tree, or "
         "name the folder holding it";
}

std::string FindPinnedModel(const std::string& flag_dir, const std::vector<PinnedFile>& files,
                            Status* status) {
  const std::string json = files.front().name;
  std::vector<std::string> tried;
  const std::string dir = FindPoseModelDir(flag_dir, &tried, json);
  if (dir.empty()) {
    if (!flag_dir.empty()) {
      *status =
          Status::Error("analysis.model", flag_dir + "/" + json + " not found; " + FetchAdvice());
    } else {
      std::string list;
      for (const std::string& d : tried) list += (list.empty() ? "" : ", ") + d;
      *status = Status::Error("analysis.model", "the pose model (" + json + ") is in none of " +
                                                    list + "; " + FetchAdvice());
    }
    return std::string();
  }
  *status = CheckPinned(dir, files).WithKey("analysis.model");
  return *status ? dir : std::string();
}

}  // namespace armmimic::internal
