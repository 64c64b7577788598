// Where the pose model is looked for: the --model folder, a developer's source tree and caches,
// then where an installed program keeps it (the armmimic-models package).
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "armmimic/engines/pose.h"

// The source tree's model cache and the build folder whose programs look in it.
#ifndef ARMMIMIC_REPO_CACHE_DIR
#define ARMMIMIC_REPO_CACHE_DIR ""
#endif
#ifndef ARMMIMIC_BUILD_DIR
#define ARMMIMIC_BUILD_DIR ""
#endif

namespace armmimic {
namespace fs = std::filesystem;
namespace {

// The running program's own file, symbolic links resolved ("" if unknown).
fs::path RunningProgram() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

// Whether `path` lies inside the folder `dir` (both resolved).
bool IsInside(const fs::path& path, const std::string& dir) {
  if (dir.empty() || path.empty()) return false;
  std::error_code ec;
  const fs::path root = fs::weakly_canonical(dir, ec);
  if (ec) return false;
  const auto mismatch = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
  return mismatch.first == root.end();
}

}  // namespace

std::string InstalledPoseModelDir() {
  const fs::path exe = RunningProgram();
  if (exe.empty()) return std::string();
  return (exe.parent_path().parent_path() / kPoseModelInstallSubdir).string();
}

std::vector<std::string> PoseModelSearchPath(const std::string& flag_dir) {
  if (!flag_dir.empty()) return {flag_dir};
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("ARMMIMIC_MODEL_DIR"); env && *env) dirs.push_back(env);
  // Only a program of the build tree (not an installed or copied one) looks in the source tree
  // it was built from, so an installed program never names the build machine's folders.
  if (*ARMMIMIC_REPO_CACHE_DIR && IsInside(RunningProgram(), ARMMIMIC_BUILD_DIR)) {
    dirs.push_back(ARMMIMIC_REPO_CACHE_DIR);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
    dirs.push_back(std::string(xdg) + "/armmimic");
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    dirs.push_back(std::string(home) + "/.cache/armmimic");
  }
  if (const std::string installed = InstalledPoseModelDir(); !installed.empty()) {
    dirs.push_back(installed);
  }
  dirs.push_back(kPackagedPoseModelDir);
  std::vector<std::string> unique;
  for (const std::string& d : dirs) {
    if (std::find(unique.begin(), unique.end(), d) == unique.end()) unique.push_back(d);
  }
  return unique;
}

std::string FindPoseModelDir(const std::string& flag_dir, std::vector<std::string>* tried,
                             const std::string& json) {
  const std::vector<std::string> dirs = PoseModelSearchPath(flag_dir);
  for (const std::string& d : dirs) {
    std::error_code ec;
    if (fs::is_regular_file(d + "/" + json, ec)) return d;
  }
  if (tried) *tried = dirs;
  return std::string();
}

}  // namespace armmimic
