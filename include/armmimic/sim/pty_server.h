// PtyServer: runs a PumaEmulator behind a pseudo-terminal on its own thread, so any serial
// client (armmimic-cli send, the GUI, a terminal program) can connect to device_path() as if
// it were the controller's RS-232 port.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "armmimic/core/status.h"
#include "armmimic/sim/puma_emulator.h"

namespace armmimic::sim {

class PtyServer {
 public:
  explicit PtyServer(EmulatorOptions options = {});
  ~PtyServer();  // Stop()
  PtyServer(const PtyServer&) = delete;
  PtyServer& operator=(const PtyServer&) = delete;

  // Opens the pseudo-terminal (raw mode) and starts the thread. With `link_path`, also makes
  // that path a symlink to the device (replacing an existing symlink, never a regular file).
  // `log_path` (optional) receives one line per executed move, flushed as it happens.
  Status Start(const std::string& link_path = "", const std::string& log_path = "");
  // Stops the thread, closes the pseudo-terminal, removes the symlink. Safe to call twice.
  void Stop();

  const std::string& device_path() const { return device_path_; }
  // Thread-safe snapshots of the emulator's state.
  robot::JointArray joints() const;
  std::vector<LoggedMove> log() const;
  int lines_received() const;
  bool busy() const;
  // Seconds since the last byte in or out, or the end of the last motion.
  double idle_s() const;

  // While held, the controller reads and answers nothing (bytes wait in the pseudo-terminal), so
  // a client waits on its line in flight for as long as a test needs, whatever the machine's speed.
  void Hold(bool on) { held_ = on; }

  // The log line format: "seq<TAB>j1 .. j6<TAB>source".
  static std::string FormatLogLine(const LoggedMove& move);

 private:
  void Run();
  double Now() const;
  // With EmulatorOptions::line_baud: bytes queued with the time each is due (in or out).
  struct Paced {
    std::string bytes;
    std::vector<double> due_s;
    double clock_s = 0;  // when the line finishes the last byte queued
    void Push(const std::string& data, double now_s, double byte_s);
    std::string Take(double now_s);  // the bytes due by now
  };

  mutable std::mutex mutex_;
  int line_baud_ = 0;
  PumaEmulator emulator_;
  int master_fd_ = -1;
  std::string device_path_;
  std::string link_path_;
  std::FILE* log_file_ = nullptr;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> held_{false};
  std::chrono::steady_clock::time_point start_;
  double last_activity_s_ = 0;
  double byte_s_ = 0;  // one character time on the paced line (0: not paced)
};

}  // namespace armmimic::sim
