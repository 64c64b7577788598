#include "armmimic/core/output_file.h"
#include "armmimic/core/text.h"

#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>
#include <utility>

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace armmimic {
namespace {

constexpr int kMaxLinks = 40;  // as the kernel's own limit on a chain of symlinks
constexpr const char* kTempTag = "armmimic-tmp.";
constexpr int kTempRandom = 6;             // mkstemp's XXXXXX
constexpr std::size_t kMaxTempBase = 200;  // keeps the temporary's name within NAME_MAX
constexpr double kFifoReaderWait_s = 5.0;  // a reader started just after the run

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

// "is a folder", "is a socket", ... for a node no output may be; "" for one it may.
std::string RefusedKind(mode_t mode) {
  if (S_ISREG(mode) || S_ISCHR(mode) || S_ISFIFO(mode)) return "";
  if (S_ISDIR(mode)) return "is a folder";
  if (S_ISSOCK(mode)) return "is a socket";
  if (S_ISBLK(mode)) return "is a block device";
  return "is not a file, a character device or a FIFO";
}

// Follows `path` through symlinks to the name of its final target (which may not exist yet).
Status FollowLinks(const std::string& path, std::string* final_path) {
  std::string p = path;
  for (int hop = 0; hop <= kMaxLinks; ++hop) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
      *final_path = p;
      return Status::Ok();
    }
    std::string target(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 255) + 1, '\0');
    const ssize_t n = ::readlink(p.c_str(), target.data(), target.size());
    if (n < 0) return Status::Error(path + ": " + FileErrorText(errno));
    target.resize(static_cast<std::size_t>(n));
    p = (target.empty() || target[0] == '/') ? target : DirName(p) + "/" + target;
  }
  return Status::Error(path + ": too many levels of symbolic links");
}

// The target's extension with its dot (".avi"), which a temporary may carry as a suffix.
std::string Extension(const std::string& resolved) {
  const std::string base = BaseName(resolved);
  const auto dot = base.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? std::string() : base.substr(dot);
}

bool IsTempName(const std::string& name, const std::string& prefix, const std::string& ext) {
  const std::size_t end = prefix.size() + kTempRandom;
  if (name.size() < end || name.compare(0, prefix.size(), prefix) != 0) return false;
  for (std::size_t i = prefix.size(); i < end; ++i) {
    if (!std::isalnum(static_cast<unsigned char>(name[i]))) return false;
  }
  const std::string rest = name.substr(end);
  return rest.empty() || (!ext.empty() && rest == ext);
}

// Opens a character device or FIFO for writing, without truncating it and without waiting for
// a modem line. A FIFO nobody reads is waited for (a reader that starts a moment after us),
// then refused rather than hanging the run.
Status OpenStream(const OutputTarget& t, std::FILE** out) {
  const auto start = std::chrono::steady_clock::now();
  int fd = -1;
  for (;;) {
    fd = ::open(t.path.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd >= 0 || errno != ENXIO || !t.fifo) break;
    const std::chrono::duration<double> waited = std::chrono::steady_clock::now() - start;
    if (waited.count() >= kFifoReaderWait_s) {
      return Status::Error(t.path + ": the FIFO has no reader (waited " +
                           std::to_string(static_cast<int>(kFifoReaderWait_s)) + " s)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (fd < 0) return Status::Error(t.path + ": cannot write (" + FileErrorText(errno) + ")");
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  // A reader that goes away must fail the write ("broken pipe"), not kill the program unheard.
  std::signal(SIGPIPE, SIG_IGN);
  *out = ::fdopen(fd, "wb");
  if (!*out) {
    const int err = errno;
    ::close(fd);
    return Status::Error(t.path + ": cannot write (" + FileErrorText(err) + ")");
  }
  return Status::Ok();
}

}  // namespace

std::string FileErrorText(int err) {
  switch (err) {
    case EACCES:
    case EPERM:
      return "permission denied";
    case EISDIR:
      return "is a folder";
    case ENOENT:
      return "not found";
    case ENOTDIR:
      return "a part of the path is not a folder";
    case ELOOP:
      return "too many levels of symbolic links";
    case EROFS:
      return "read-only file system";
    case ENOSPC:
      return "no space left on the device";
    case EPIPE:
      return "broken pipe: the reader went away";
    default:
      return ErrnoText(err);
  }
}

Status ResolveOutput(const std::string& path, OutputTarget* out) {
  *out = OutputTarget{};
  out->path = path;
  out->resolved = path;
  if (path.empty()) return Status::Error("output path is empty");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (const std::string refused = RefusedKind(st.st_mode); !refused.empty()) {
      return Status::Error(path + ": " + refused);
    }
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      // Opened by the name given: /dev/stdout and its kind lead to a pipe no other name reaches.
      out->kind = OutputKind::kStream;
      out->fifo = S_ISFIFO(st.st_mode);
      return Status::Ok();
    }
  } else if (errno != ENOENT) {
    return Status::Error(path + ": " + FileErrorText(errno));
  }
  if (Status s = FollowLinks(path, &out->resolved); !s) return s;
  const std::string dir = DirName(out->resolved);
  struct stat dir_st {};
  if (::stat(dir.c_str(), &dir_st) != 0) {
    const int err = errno;
    if (err == ENOENT) return Status::Error(path + ": folder " + dir + " does not exist");
    return Status::Error(path + ": folder " + dir + ": " + FileErrorText(err));
  }
  if (!S_ISDIR(dir_st.st_mode)) return Status::Error(path + ": " + dir + " is not a folder");
  return Status::Ok();
}

Status CheckOutputKinds(const std::vector<NamedPath>& outputs) {
  for (const NamedPath& out : outputs) {
    // Only what a path already is: a missing folder is the write's own error, later.
    struct stat st {};
    if (out.path.empty()) continue;
    if (::stat(out.path.c_str(), &st) != 0) {
      if (errno == ELOOP)
        return Status::Error(out.role + " " + out.path + ": " + FileErrorText(errno));
      continue;
    }
    if (const std::string refused = RefusedKind(st.st_mode); !refused.empty()) {
      return Status::Error(out.role + " " + out.path + ": " + refused +
                           "; an output must be a file, a character device or a FIFO");
    }
  }
  return Status::Ok();
}

Status CheckOutputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  if (Status s = CheckOutputKinds(outputs); !s) return s;
  return CheckOutputsAreNotInputs(inputs, outputs);
}

Status CheckInputFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return Status::Error(path + ": " + FileErrorText(errno));
  if (S_ISDIR(st.st_mode)) return Status::Error(path + ": is a folder, not a file");
  if (::access(path.c_str(), R_OK) != 0) {
    return Status::Error(path + ": " + FileErrorText(errno));
  }
  return Status::Ok();
}

std::string OutputTempPrefix(const std::string& resolved) {
  return "." + BaseName(resolved).substr(0, kMaxTempBase) + "." + kTempTag;
}

int RemoveStaleOutputTemps(const std::string& resolved) {
  const std::string dir = DirName(resolved);
  const std::string prefix = OutputTempPrefix(resolved);
  const std::string ext = Extension(resolved);
  DIR* d = ::opendir(dir.c_str());
  if (!d) return 0;
  int removed = 0;
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (!IsTempName(name, prefix, ext)) continue;
    const std::string p = dir + "/" + name;
    const int fd = ::open(p.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat by_fd {};
    struct stat by_name {};
    // Only a regular file whose writer is gone (its lock is free), still under that name.
    if (::fstat(fd, &by_fd) == 0 && S_ISREG(by_fd.st_mode) && ::flock(fd, LOCK_EX | LOCK_NB) == 0 &&
        ::lstat(p.c_str(), &by_name) == 0 && by_name.st_ino == by_fd.st_ino &&
        by_name.st_dev == by_fd.st_dev && ::unlink(p.c_str()) == 0) {
      ++removed;
    }
    ::close(fd);
  }
  ::closedir(d);
  return removed;
}

OutputFile::~OutputFile() { Discard(); }

Status OutputFile::Open(const std::string& path, Mode mode) {
  Discard();
  if (Status s = ResolveOutput(path, &target_); !s) return s;
  if (target_.kind == OutputKind::kStream) return OpenStream(target_, &file_);
  const std::string& final_path = target_.resolved;
  const auto fail = [&](int err) {
    return Status::Error(path + ": cannot write (" + FileErrorText(err) + ")");
  };
  if (mode != Mode::kReplace) {
    const int flags =
        O_WRONLY | O_CREAT | O_CLOEXEC | (mode == Mode::kAppendLog ? O_APPEND : O_TRUNC);
    const int fd = ::open(final_path.c_str(), flags, 0644);
    if (fd < 0) return fail(errno);
    file_ = ::fdopen(fd, mode == Mode::kAppendLog ? "ab" : "wb");
    if (file_) return Status::Ok();
    const int err = errno;
    ::close(fd);
    return fail(err);
  }
  return CreateTemp("");
}

Status OutputFile::OpenNamed(const std::string& path) {
  Discard();
  if (Status s = ResolveOutput(path, &target_); !s) return s;
  if (target_.kind == OutputKind::kStream) {
    return Status::Error(path +
                         ": is a character device or a FIFO; this file needs a regular "
                         "file (it is written by name and rewound)");
  }
  return CreateTemp(Extension(target_.resolved));
}

Status OutputFile::CreateTemp(const std::string& suffix) {
  const std::string& path = target_.path;
  const std::string& final_path = target_.resolved;
  RemoveStaleOutputTemps(final_path);
  struct stat existing {};
  const bool replaces = ::stat(final_path.c_str(), &existing) == 0;
  const std::string templ =
      DirName(final_path) + "/" + OutputTempPrefix(final_path) + "XXXXXX" + suffix;
  for (int attempt = 0; attempt < 5; ++attempt) {
    std::string name = templ;
    const int fd = ::mkostemps(name.data(), static_cast<int>(suffix.size()), O_CLOEXEC);
    if (fd < 0) {
      return Status::Error(path + ": cannot write (" + FileErrorText(errno) + ")");
    }
    // Locked so that no other run takes it for a stale one; checked to be still ours, since
    // such a run may have removed it between its creation and the lock.
    struct stat by_fd {};
    struct stat by_name {};
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0 || ::fstat(fd, &by_fd) != 0 ||
        ::lstat(name.c_str(), &by_name) != 0 || by_fd.st_ino != by_name.st_ino) {
      ::close(fd);
      continue;
    }
    ::fchmod(fd, replaces ? (existing.st_mode & 07777) : 0644);
    file_ = ::fdopen(fd, "wb");
    if (!file_) {
      const int err = errno;
      ::close(fd);
      ::unlink(name.c_str());
      return Status::Error(path + ": cannot write (" + FileErrorText(err) + ")");
    }
    temp_path_ = name;
    return Status::Ok();
  }
  return Status::Error(path + ": cannot create a temporary file beside " + final_path);
}

Status OutputFile::Commit() {
  if (!file_) return Status::Error(target_.path + ": not open for writing");
  bool ok = std::fflush(file_) == 0;
  int err = ok ? 0 : errno;
  if (ok && !SyncOutput(file_)) {
    ok = false;
    err = errno;
  }
  if (ok && replacing() && std::rename(temp_path_.c_str(), target_.resolved.c_str()) != 0) {
    const int rerr = errno;
    std::fclose(file_);
    file_ = nullptr;
    Discard();
    return Status::Error(target_.path + ": cannot replace (" + FileErrorText(rerr) + ")");
  }
  if (ok) temp_path_.clear();  // renamed: the lock goes with the close below
  if (std::fclose(file_) != 0 && ok) {
    ok = false;
    err = errno;
  }
  file_ = nullptr;
  if (!ok) {
    Discard();
    return Status::Error(target_.path + ": write failed (" + FileErrorText(err) + ")");
  }
  return Status::Ok();
}

void OutputFile::Discard() {
  if (file_) {
    std::fclose(file_);
    file_ = nullptr;
  }
  if (!temp_path_.empty()) {
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
  }
}

Status OpenLogFile(const std::string& path, bool append, std::FILE** out) {
  *out = nullptr;
  OutputFile log;
  if (Status st = log.Open(path, append ? OutputFile::Mode::kAppendLog : OutputFile::Mode::kLog);
      !st) {
    return st;
  }
  std::swap(*out, log.file_);  // a log has no temporary: nothing is left for Discard()
  return Status::Ok();
}

bool SyncOutput(std::FILE* file) {
  if (std::fflush(file) != 0) return false;
  return ::fsync(fileno(file)) == 0 || errno == EINVAL || errno == EROFS;
}

Status WriteOutputFile(const std::string& path, const std::string& bytes) {
  OutputFile out;
  if (Status st = out.Open(path); !st) return st;
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), out.file()) != bytes.size()) {
    return Status::Error(path + ": write failed (" + FileErrorText(errno) + ")");
  }
  return out.Commit();
}

}  // namespace armmimic
