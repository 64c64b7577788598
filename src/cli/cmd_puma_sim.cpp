// armmimic-cli puma-sim [--link PATH]: the VAL controller emulator on a pseudo-terminal.
#include <chrono>
#include <iostream>
#include <thread>

#include "args.h"
#include "armmimic/core/output_file.h"
#include "armmimic/sim/pty_server.h"
#include "command.h"
#include "flag_for_key.h"
#include "interrupt.h"

namespace armmimic::cli {
namespace {

int RunPumaSim(const std::vector<std::string>& args, const GlobalOptions& global) {
  sim::EmulatorOptions options;
  std::string link_path, log_path;
  double exit_after_idle_s = 0;
  ArgParser p(
      "puma-sim",
      "  armmimic-cli puma-sim [--link PATH] [--log FILE] [--time-scale X] [--line-baud N]\n"
      "          [--fail-after N] [--silent-after N] [--garble-after N] "
      "[--exit-after-idle S]",
      "Emulates a PUMA 760 VAL II controller on a pseudo-terminal and prints the device "
      "path to connect to (first line of standard output). It echoes, prompts with '.', "
      "takes CR-ended lines of at most 80 characters and interprets SPEED, DO MOVE "
      "#PPOINT(...), DO DRIVE, HERE, WHERE, EDIT/E, EXECUTE and ABORT within the joint "
      "limits (docs/val-dialect.md). Runs until SIGINT, SIGTERM or SIGHUP, then prints "
      "the final joint angles.");
  p.String("--link", &link_path, "PATH", "also make PATH a symlink to the device");
  p.String("--log", &log_path, "FILE", "write one line per executed move (seq, joints, command)");
  p.Double("--time-scale", &options.time_scale, "X",
           "motions last X times their real duration (0.01: 100x faster; default 1)");
  p.Custom("--limits", "J2=-200:20,...", "override joint limits (degrees)",
           [&](const std::string& v) { return robot::ParseLimitsOverride(v, &options.limits); });
  p.Int("--fail-after", &options.fail_after, "N",
        "fault: refuse command line N+1 with '*Servo error*' (once)", 0);
  p.Int("--silent-after", &options.silent_after, "N",
        "fault: run line N+1, then answer nothing until the client reconnects", 0);
  p.Int("--garble-after", &options.garble_after, "N",
        "fault: a line of noise bytes before every prompt after line N", 0);
  p.Int("--line-baud", &options.line_baud, "N",
        "answer like a VAL terminal on an N-baud RS-232 line: every byte in and out takes a "
        "character time (10 bits), e.g. 9600 (default 0: the pseudo-terminal's speed)",
        0, 4000000);
  p.Double("--exit-after-idle", &exit_after_idle_s, "S",
           "exit after S seconds without traffic or motion (for scripts and tests)");
  if (auto code = p.Parse(args)) return *code;
  if (!(options.time_scale >= 0)) return p.UsageError("--time-scale must be >= 0");
  if (exit_after_idle_s < 0) return p.UsageError("--exit-after-idle must be >= 0");
  {
    const Status s = options.limits.Check();
    if (!s.ok()) return p.UsageError("--limits: " + s.message());
  }

  if (const Status s = CheckOutputKinds({{"--log", log_path}}); !s.ok()) {
    return p.UsageError(s.message());
  }

  InterruptGuard guard;  // before the device exists: whoever sees it may signal at once
  sim::PtyServer server(options);
  const Status s = server.Start(link_path, log_path);
  if (!s.ok()) {
    std::cerr << "armmimic-cli puma-sim: " << Worded(s) << "\n";
    return kExitFailure;
  }
  std::cout << server.device_path() << std::endl;
  if (!global.quiet) {
    std::cerr << "puma-sim: VAL controller emulator on " << server.device_path()
              << (link_path.empty() ? "" : " (" + link_path + ")") << "; Ctrl-C to stop\n";
  }
  while (!InterruptGuard::interrupted()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (exit_after_idle_s > 0 && server.idle_s() > exit_after_idle_s) break;
  }
  const robot::JointArray j = server.joints();
  const std::size_t moves = server.log().size();
  server.Stop();
  std::cout << "final joints:" << sim::PumaEmulator::FormatJoints(j) << "\n"
            << "moves executed: " << moves << std::endl;
  return kExitOk;
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(puma_sim, "puma-sim", "emulate the PUMA's VAL controller on a pty", 90,
                          RunPumaSim);

}  // namespace armmimic::cli
