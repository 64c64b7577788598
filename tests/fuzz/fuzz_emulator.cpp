// Fuzzes the emulator's VAL command parser and interpreter with arbitrary bytes and time steps.
// Properties: it never throws; the joints (interpolated mid-motion) and every logged move stay
// within the configured limits and are finite; logged moves are numbered 1, 2, ... with
// end >= start; no printed line exceeds the longest input line it keeps (4096) plus a prompt.
#include "fuzz_input.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "armmimic/sim/puma_emulator.h"

namespace {

void CheckJoints(const armmimic::robot::JointLimits& lim, const armmimic::robot::JointArray& d) {
  for (int j = 0; j < armmimic::robot::kJoints; ++j) {
    const double slack = 1e-9 * (1 + std::abs(lim.max_deg[j]) + std::abs(lim.min_deg[j]));
    if (!std::isfinite(d[j]) || d[j] < lim.min_deg[j] - slack || d[j] > lim.max_deg[j] + slack) {
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  armmimic::fuzz::FuzzInput fdp(data, size);
  armmimic::sim::EmulatorOptions opt;
  opt.time_scale = 0.01;
  const uint8_t flags = fdp.Byte();
  if (flags & 1) opt.limits.min_deg[0] = -90, opt.limits.max_deg[0] = 90;  // narrower J1
  if (flags & 2) opt.fail_after = (flags >> 4) & 7;
  if (flags & 4) opt.garble_after = (flags >> 4) & 7;
  if (flags & 8) opt.silent_after = (flags >> 5) & 7;
  armmimic::robot::JointLimits lim = opt.limits;

  try {
    armmimic::sim::PumaEmulator emu(opt);
    int expected_seq = 1;
    emu.SetMoveCallback([&](const armmimic::sim::LoggedMove& m) {
      if (m.seq != expected_seq++) std::abort();
      if (!(m.end_s >= m.start_s)) std::abort();
      CheckJoints(lim, m.target_deg);
    });
    double now = 0;
    std::string pending;  // printed text not yet ended by a newline
    auto check_out = [&](const std::string& out) {
      pending += out;
      std::size_t nl;
      while ((nl = pending.find('\n')) != std::string::npos) {
        // A line may carry the echo of what was typed (a too-long line is echoed too, and input
        // lines are read up to 4096 characters), a prompt and the "\r" before the "\n".
        if (nl > 4096 + 16) std::abort();
        pending.erase(0, nl + 1);
      }
    };
    while (!fdp.empty()) {
      const uint8_t op = fdp.Byte();
      switch (op & 3) {
        case 0:
        case 1:
          check_out(emu.Feed(fdp.Chunk(120), now));
          break;
        case 2:
          now += (op >> 2) * 0.1;
          check_out(emu.Tick(now));
          break;
        default:
          emu.OnDisconnect();
          break;
      }
      CheckJoints(lim, emu.joints());
      CheckJoints(lim, emu.target());
    }
    // Let everything finish.
    for (int i = 0; i < 50 && emu.busy(); ++i) {
      now += 100;
      check_out(emu.Tick(now));
      CheckJoints(lim, emu.joints());
    }
    for (const auto& m : emu.log()) CheckJoints(lim, m.target_deg);
  } catch (...) {
    std::abort();
  }
  return 0;
}
