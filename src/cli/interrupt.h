// Interrupts: Ctrl-C (SIGINT), SIGTERM (timeout, systemd, GNU parallel, Slurm) and SIGHUP (a
// closed terminal) all ask a command to stop the same way. The command finishes what it must
// (an angle file keeps its rows, marked complete=no; an unfinished image is not written; no
// temporary file stays behind) and says which signal stopped it. Repeated signals change
// nothing to a command that stops in one step: GNU parallel sends SIGTERM several times, and a
// second one must not cut short the clean-up the first one started. A command that stops in two
// steps (mimic: a clean stop, then at once) counts the signals with count(). Every command's
// signal handling is this one.
#pragma once

#include <atomic>
#include <csignal>
#include <string>

namespace armmimic::cli {

class InterruptGuard {
 public:
  // Installs the handler for SIGINT, SIGTERM and SIGHUP; the destructor restores the old ones.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Set by the first signal; for AnalysisCallbacks::cancel and loops.
  static const std::atomic<bool>* flag();
  static bool interrupted();
  // How many signals came since the guard was installed.
  static int count();
  // "interrupted (SIGTERM)"; "" when no signal came.
  static std::string Message();

 private:
  struct sigaction old_[3] = {};
};

}  // namespace armmimic::cli
