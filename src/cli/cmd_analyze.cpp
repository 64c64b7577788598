// armmimic-cli analyze INPUT... -o ANGLES.tsv --engine bgsub|lk|marker|pose: video or images in, an
// angle file v1 out (docs/cli.md). Ctrl-C keeps the rows so far in a file marked complete=no.
#include <signal.h>

#include <atomic>
#include <cstdio>
#include <iostream>

#include "analysis_flags.h"
#include "args.h"
#include "armmimic/engines/analysis.h"
#include "command.h"
#include "progress.h"

namespace armmimic::cli {
namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void OnInterrupt(int) { g_interrupted.store(true); }

// Installs the SIGINT handler for the lifetime of the object.
class InterruptGuard {
 public:
  InterruptGuard() {
    g_interrupted.store(false);
    struct sigaction sa {};
    sa.sa_handler = OnInterrupt;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_);
  }
  ~InterruptGuard() { sigaction(SIGINT, &old_, nullptr); }

 private:
  struct sigaction old_ {};
};

std::string BaseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

int RunAnalyze(const std::vector<std::string>& args, const GlobalOptions& global) {
  AnalysisOptions o;
  AnalysisFlags flags(&o);
  std::string output;
  ArgParser p(
      "analyze",
      "  armmimic-cli analyze VIDEO -o ANGLES.tsv --engine bgsub\n"
      "          (--background BG.png | --background-frames K) --arm-length ARM.png\n"
      "          [--start F] [--standstill-frames 60] [--threshold 45]\n"
      "  armmimic-cli analyze VIDEO -o ANGLES.tsv --engine lk\n"
      "          (--background BG.png | --background-frames K | --shoulder X,Y) [--start F]\n"
      "          [--standstill-frames 60] [--initial-upper -90] [--initial-fore -90]\n"
      "  armmimic-cli analyze VIDEO -o ANGLES.tsv --engine lk\n"
      "          --shoulder X,Y --elbow X,Y --wrist X,Y [--start F]\n"
      "  armmimic-cli analyze VIDEO -o ANGLES.tsv --engine lk --auto-calibrate\n"
      "          [--side left|right] [--start F] [--model DIR]\n"
      "  armmimic-cli analyze INPUT... -o ANGLES.tsv --engine marker --reference REF.png\n"
      "          [--low 20] [--high 80]\n"
      "  armmimic-cli analyze VIDEO -o ANGLES.tsv --engine pose [--side left|right] [--start F]\n"
      "          [--model DIR]\n"
      "  Arm engines also take [--roi X,Y,W,H] [--shoulder X,Y] [--thesis].",
      "Turns a video (or images) into an angle file v1, one row per analysed frame.\n"
      "bgsub, and lk without --shoulder: frames [F, F+standstill) are the standstill (no rows);\n"
      "every later frame is a row. lk with --shoulder has no standstill: frame F is the known\n"
      "starting posture and already gets a row (--standstill-frames is then refused). With\n"
      "--elbow and --wrist too, the three clicked joints give the starting directions and the\n"
      "segment lengths; otherwise the arm length is estimated and the estimate is printed.\n"
      "lk --auto-calibrate: the pose network finds the shoulder, elbow and wrist in frame F, as\n"
      "if clicked (--side names the person's own arm; default: the better seen).\n"
      "marker: one row per input image, in input order.\n"
      "pose: a pose network (MoveNet) finds the person's arm in every frame from F on, with no\n"
      "background or calibration; a row is lost where the arm is not seen or a segment points at\n"
      "the camera, and a confidence column (0-1) follows the angles. --side names the person's\n"
      "own arm (default: the better seen over the first second). The model is fetched by\n"
      "scripts/deps.sh --with-model and found without flags (docs/pose.md).\n"
      "Ctrl-C keeps the rows so far in a valid file marked complete=no (exit 1).\n" +
          AnalysisFlags::ParamList());
  p.Positionals(&o.inputs, "INPUT", 1, -1);
  p.String("-o,--output", &output, "ANGLES.tsv", "the angle file to write (required)");
  flags.Register(p);
  if (auto code = p.Parse(args)) return *code;

  if (auto code = flags.CheckEngine(p)) return *code;
  if (output.empty()) return p.UsageError("missing -o ANGLES.tsv (the angle file to write)");
  if (auto code = flags.Finish(p)) return *code;

  InterruptGuard guard;
  ProgressBar bar("analyze", -1, global.ShowProgress());
  AnalysisCallbacks cb;
  cb.cancel = &g_interrupted;
  int frames_read = 0;
  cb.on_phase = [&](const std::string& phase) { bar.SetLabel(phase); };
  cb.on_progress = [&](int done, int total) {
    bar.SetTotal(total);
    bar.Update(done);
    frames_read = done;
  };
  cb.on_estimate = [&](const std::string& text) {
    if (global.quiet) return;
    bar.Finish();  // clears the bar line; the next update draws it again
    std::cerr << "analyze: estimated: " << text << "\n";
  };
  AnalysisSummary summary;
  const Status st = AnalyzeToFile(o, output, cb, &summary);
  bar.Finish();
  if (!st) {
    std::cerr << "armmimic-cli analyze: " << st.message() << "\n";
    return kExitFailure;
  }
  const std::string source = summary.video.path.empty() ? o.inputs[0] : summary.video.path;
  if (summary.cancelled) {
    std::cerr << "analyze: interrupted; " << summary.frames << " rows kept in " << output
              << " (marked complete=no)\n";
    return kExitFailure;
  }
  if (summary.EndedEarly()) {
    // Not an error (every row written is valid), but the operator must know rows stop early.
    std::cerr << "armmimic-cli analyze: warning: " << source << ": the file announces "
              << summary.video.frame_count << " frames but only " << summary.last_frame + 1
              << " could be read (truncated or damaged video); the rows stop at frame "
              << summary.last_frame << "\n";
  }
  if (!global.quiet) {
    char rate[64];
    std::snprintf(rate, sizeof(rate), "%.2f s, %.0f frames/s", summary.seconds,
                  summary.seconds > 0 ? frames_read / summary.seconds : 0.0);
    std::cerr << "analyze: " << summary.frames << " rows (" << summary.ok << " ok, " << summary.lost
              << " lost) from " << BaseName(source) << " in " << rate << " -> " << output << "\n";
  }
  return kExitOk;
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(analyze, "analyze", "turn a video or images into an angle file", 20,
                          RunAnalyze);

}  // namespace armmimic::cli
