// armmimic-cli synth arm|marker OUTDIR: scenes with ground truth.
#include <iostream>

#include "command.h"
#include "flag_for_key.h"
#include "interrupt.h"
#include "progress.h"
#include "synth_commands.h"

namespace armmimic::cli {

int WriteSceneWithProgress(const std::string& kind, int total, const GlobalOptions& global,
                           const SceneWriter& write, const std::string& interrupted_note) {
  InterruptGuard guard;
  ProgressBar bar("synth " + kind, total, global.ShowProgress());
  const Status st = write([&bar](int done, int) { bar.Update(done); }, InterruptGuard::flag());
  bar.Finish();
  if (!st.ok() && InterruptGuard::interrupted()) {
    std::cerr << "synth " << kind << ": " << InterruptGuard::Message() << "; " << interrupted_note
              << "\n";
    return kExitFailure;
  }
  if (!st.ok()) {
    std::cerr << "armmimic-cli synth " << kind << ": " << Worded(st) << "\n";
    return kExitFailure;
  }
  return kExitOk;
}

namespace {

int RunSynth(const std::vector<std::string>& args, const GlobalOptions& global) {
  const std::string usage =
      "Usage:\n  armmimic-cli synth arm OUTDIR [--seed N] [...]\n"
      "  armmimic-cli synth marker OUTDIR [--seed N] [...]\n\n"
      "Renders a scene with known angles and writes its ground truth (truth.tsv).\n"
      "See 'armmimic-cli synth arm --help' and 'armmimic-cli synth marker --help'.\n";
  if (args.empty()) {
    std::cerr << "armmimic-cli synth: missing the scene kind (arm or marker)\n" << usage;
    return kExitUsage;
  }
  if (args[0] == "-h" || args[0] == "--help") {
    std::cout << usage;
    return kExitOk;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "arm") return RunSynthArm(rest, global);
  if (args[0] == "marker") return RunSynthMarker(rest, global);
  std::cerr << "armmimic-cli synth: unknown scene kind '" << args[0] << "' (arm or marker)\n";
  return kExitUsage;
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(synth, "synth", "render a scene with ground truth (arm or marker)", 50,
                          RunSynth);

}  // namespace armmimic::cli
