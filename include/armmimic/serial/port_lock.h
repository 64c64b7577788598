// PortLock: one lock per device, whatever name reaches it. A serial port or pseudo-terminal can
// be named many ways (/dev/pts/3, a link made by `puma-sim --link`, /dev/serial/by-id/...), and
// two programs writing one device at once interleave their moves. The lock is therefore keyed by
// the device's identity, the device and inode of the path with every symlink followed.
//
// Why a lock file, and why flock: a lock held by a process that died must not count, so the lock
// is the kernel's flock on an open file, which ends with its holder, however it ends. A lock on
// the device itself would do that too, but flock does not tell who holds it and fcntl locks are
// dropped when any descriptor of the device in the process closes (the serial library opens its
// own). So the lock is an flock on "armmimic-port-<dev>-<ino>.lock" in the system's lock folder
// (/run/lock, where every user may write; /tmp when that is missing or closed), and the holder
// writes its process id into the file, for the refusal to name.
#pragma once

#include <sys/types.h>
#include <string>

#include "armmimic/core/status.h"

namespace armmimic::serial {

class PortLock {
 public:
  PortLock() = default;
  ~PortLock() { Release(); }
  PortLock(const PortLock&) = delete;
  PortLock& operator=(const PortLock&) = delete;

  // Takes the lock of the device `device` leads to, without waiting. Fails when another process
  // holds it, naming that process ("... is in use by process 1234").
  Status Acquire(const std::string& device);
  // Gives the lock up (and removes the lock file); nothing when none is held.
  void Release();
  bool held() const { return fd_ >= 0; }
  // The lock file of the device `device` leads to ("" when it does not exist).
  static std::string LockPathFor(const std::string& device);

 private:
  int fd_ = -1;
  std::string path_;
};

}  // namespace armmimic::serial
