#include "armmimic/core/atomic_file.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "armmimic/core/text.h"

namespace armmimic {
namespace {

std::string DirName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string BaseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

AtomicFile::~AtomicFile() { Discard(); }

Status AtomicFile::Open(const std::string& path) {
  Discard();
  path_ = path;
  if (path.empty()) return Status::Error("output path is empty");
  const std::string dir = DirName(path);
  struct stat st {};
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    return Status::Error(path + ": directory " + dir + " does not exist");
  }
  struct stat target {};
  if (stat(path.c_str(), &target) == 0 && S_ISDIR(target.st_mode)) {
    return Status::Error(path + ": is a directory");
  }
  std::string templ = dir + "/." + BaseName(path) + ".XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  const int fd = mkstemp(buf.data());
  if (fd < 0) return Status::Error(path + ": cannot write (" + ErrnoText(errno) + ")");
  fchmod(fd, 0644);
  temp_path_ = buf.data();
  file_ = fdopen(fd, "wb");
  if (!file_) {
    ::close(fd);
    unlink(temp_path_.c_str());
    temp_path_.clear();
    return Status::Error(path + ": cannot write (" + ErrnoText(errno) + ")");
  }
  return Status::Ok();
}

Status AtomicFile::Commit() {
  if (!file_) return Status::Error(path_ + ": not open for writing");
  bool ok = std::fflush(file_) == 0;
  ok = ok && fsync(fileno(file_)) == 0;
  const int err = errno;
  ok = (std::fclose(file_) == 0) && ok;
  file_ = nullptr;
  if (!ok) {
    unlink(temp_path_.c_str());
    temp_path_.clear();
    return Status::Error(path_ + ": write failed (" + ErrnoText(err) + ")");
  }
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const int rerr = errno;
    unlink(temp_path_.c_str());
    temp_path_.clear();
    return Status::Error(path_ + ": cannot replace (" + ErrnoText(rerr) + ")");
  }
  temp_path_.clear();
  return Status::Ok();
}

void AtomicFile::Discard() {
  if (file_) {
    std::fclose(file_);
    file_ = nullptr;
  }
  if (!temp_path_.empty()) {
    unlink(temp_path_.c_str());
    temp_path_.clear();
  }
}

Status WriteFileAtomically(const std::string& path, const std::string& bytes) {
  AtomicFile out;
  Status st = out.Open(path);
  if (!st) return st;
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), out.file()) != bytes.size()) {
    return Status::Error(path + ": write failed (" + ErrnoText(errno) + ")");
  }
  return out.Commit();
}

}  // namespace armmimic
