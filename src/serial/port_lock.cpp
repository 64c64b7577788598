#include "armmimic/serial/port_lock.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "armmimic/core/output_file.h"

namespace armmimic::serial {
namespace {

std::string LockFolder() {
  struct stat st {};
  if (::stat("/run/lock", &st) == 0 && S_ISDIR(st.st_mode) && ::access("/run/lock", W_OK) == 0) {
    return "/run/lock";
  }
  return "/tmp";
}

// The process id the holder wrote, or "" while it has not yet.
std::string HolderOf(const std::string& path) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
      char buf[32] = {0};
      const ssize_t n = ::read(fd, buf, sizeof buf - 1);
      ::close(fd);
      std::string pid(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
      while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
      if (!pid.empty()) return pid;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return "";
}

}  // namespace

std::string PortLock::LockPathFor(const std::string& device) {
  struct stat st {};
  if (::stat(device.c_str(), &st) != 0) return "";
  return LockFolder() + "/armmimic-port-" +
         std::to_string(static_cast<unsigned long long>(st.st_dev)) + "-" +
         std::to_string(static_cast<unsigned long long>(st.st_ino)) + ".lock";
}

Status PortLock::Acquire(const std::string& device) {
  Release();
  const std::string path = LockPathFor(device);
  if (path.empty()) return Status::Error(device + ": " + FileErrorText(errno));
  // The holder removes the file when it lets go, so a lock taken on a file that is no longer
  // under its name locks nothing: try again on the new file.
  for (int attempt = 0; attempt < 10; ++attempt) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0) {
      return Status::Error(device + ": cannot take the port's lock " + path + " (" +
                           FileErrorText(errno) + ")");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd);
      if (err != EWOULDBLOCK) {
        return Status::Error(device + ": cannot take the port's lock " + path + " (" +
                             FileErrorText(err) + ")");
      }
      const std::string pid = HolderOf(path);
      return Status::Error("the port is busy: " + device + " is in use by " +
                           (pid.empty() ? std::string("another process") : "process " + pid) +
                           " (which holds the device's lock " + path +
                           ", whatever name it gave the device)");
    }
    struct stat by_fd {};
    struct stat by_name {};
    if (::fstat(fd, &by_fd) != 0 || ::stat(path.c_str(), &by_name) != 0 ||
        by_fd.st_ino != by_name.st_ino || by_fd.st_dev != by_name.st_dev) {
      ::close(fd);
      continue;
    }
    ::fchmod(fd, 0666);  // the next user's run must be able to open it (umask aside)
    const std::string pid = std::to_string(static_cast<long>(::getpid())) + "\n";
    // Should this fail, the lock holds all the same; only its holder's name would be missing.
    [[maybe_unused]] const bool named =
        ::ftruncate(fd, 0) == 0 &&
        ::pwrite(fd, pid.data(), pid.size(), 0) == static_cast<ssize_t>(pid.size());
    fd_ = fd;
    path_ = path;
    return Status::Ok();
  }
  return Status::Error(device + ": cannot take the port's lock " + path +
                       " (it keeps being replaced)");
}

void PortLock::Release() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still locked: see Acquire()
  ::close(fd_);
  fd_ = -1;
  path_.clear();
}

}  // namespace armmimic::serial
