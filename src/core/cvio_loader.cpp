#include "cvio_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstring>
#include <string>
#include <vector>

#include "armmimic/version.h"

namespace armmimic::internal {
namespace {

// The program's own folder, from /proc/self/exe; "" when it cannot be read.
std::string ProgramDir() {
  std::vector<char> buf(4096);
  const ssize_t n = readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return "";
  std::string path(buf.data(), static_cast<size_t>(n));
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "" : path.substr(0, slash);
}

struct Loaded {
  const cvio::Api* api = nullptr;
  Status status;
};

Loaded Load() {
  Loaded out;
  std::vector<std::string> candidates;
  const std::string dir = ProgramDir();
  // Installed: <bindir>/<relative>; the build tree mirrors it beside build/bin.
  if (!dir.empty()) candidates.push_back(dir + "/" + ARMMIMIC_CVIO_RELATIVE);
  // Programs elsewhere in the build tree (the test suites).
  candidates.emplace_back(ARMMIMIC_CVIO_BUILD_PATH);
  std::string tried;
  for (const std::string& path : candidates) {
    if (!tried.empty()) tried += ", ";
    tried += path;
    if (access(path.c_str(), F_OK) != 0) continue;
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      out.status = Status::Error(path + ": cannot load (" + (why ? why : "unknown error") +
                                 "); reinstall armmimic");
      return out;
    }
    using Entry = const cvio::Api* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(handle, "armmimic_cvio_api"));
    const cvio::Api* api = entry ? entry() : nullptr;
    if (!api || api->abi != cvio::kAbi || std::strcmp(api->version, ARMMIMIC_VERSION) != 0) {
      out.status = Status::Error(path + ": belongs to another armmimic version than " +
                                 ARMMIMIC_VERSION + "; reinstall armmimic");
      return out;
    }
    out.api = api;
    return out;
  }
  out.status = Status::Error(
      "armmimic-cvio.so, which holds OpenCV's image codecs and video I/O, was not found (looked "
      "for " +
      tried + "); reinstall armmimic");
  return out;
}

}  // namespace

const cvio::Api* CvioModule(Status* status) {
  static const Loaded loaded = Load();
  *status = loaded.status;
  return loaded.api;
}

}  // namespace armmimic::internal
