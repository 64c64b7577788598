#include "interrupt.h"

namespace armmimic::cli {
namespace {

constexpr int kSignals[3] = {SIGINT, SIGTERM, SIGHUP};

std::atomic<bool> g_interrupted{false};
volatile std::sig_atomic_t g_signal = 0;
volatile std::sig_atomic_t g_count = 0;

extern "C" void OnInterrupt(int sig) {
  if (g_signal == 0) g_signal = sig;
  g_count = g_count + 1;
  g_interrupted.store(true);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_interrupted.store(false);
  g_signal = 0;
  g_count = 0;
  struct sigaction sa {};
  sa.sa_handler = OnInterrupt;
  sigemptyset(&sa.sa_mask);
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &sa, &old_[i]);
}

InterruptGuard::~InterruptGuard() {
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &old_[i], nullptr);
}

const std::atomic<bool>* InterruptGuard::flag() { return &g_interrupted; }

bool InterruptGuard::interrupted() { return g_interrupted.load(); }

int InterruptGuard::count() { return g_count; }

std::string InterruptGuard::Message() {
  switch (g_signal) {
    case SIGINT:
      return "interrupted (SIGINT, Ctrl-C)";
    case SIGTERM:
      return "interrupted (SIGTERM)";
    case SIGHUP:
      return "interrupted (SIGHUP)";
    default:
      return g_interrupted.load() ? "interrupted" : "";
  }
}

}  // namespace armmimic::cli
