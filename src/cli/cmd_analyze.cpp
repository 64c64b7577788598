// armmimic-cli analyze INPUT... -o ANGLES.tsv --engine bgsub|lk|marker: video or images in, an
// angle file v1 out (docs/cli.md). Ctrl-C keeps the rows so far in a file marked complete=no.
#include <signal.h>

#include <atomic>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>

#include "args.h"
#include "armmimic/engines/analysis.h"
#include "armmimic/engines/option_fields.h"
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

// The flags each engine uses; any other engine flag given is a usage error.
const std::map<std::string, std::set<EngineKind>>& EngineFlags() {
  static const std::map<std::string, std::set<EngineKind>> flags = {
      {"--background", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--background-frames", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--arm-length", {EngineKind::kBgsub}},
      {"--start", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--standstill-frames", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--threshold", {EngineKind::kBgsub}},
      {"--shoulder", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--elbow", {EngineKind::kLk}},
      {"--wrist", {EngineKind::kLk}},
      {"--roi", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--initial-upper", {EngineKind::kLk}},
      {"--initial-fore", {EngineKind::kLk}},
      {"--reference", {EngineKind::kMarker}},
      {"--low", {EngineKind::kMarker}},
      {"--high", {EngineKind::kMarker}},
      {"--fov", {EngineKind::kMarker}},
  };
  return flags;
}

// The --param keys with their defaults, indented, for the help text.
std::string ParamList() {
  std::string out = "\nEvery engine parameter, for --param, with its default:\n";
  std::string line;
  for (char c : DescribeEngineOptions(76)) {
    if (c == '\n') {
      out += (line.empty() ? "" : "  " + line) + "\n";
      line.clear();
    } else {
      line += c;
    }
  }
  out.pop_back();  // the help text adds the paragraph's last newline
  return out;
}

int RunAnalyze(const std::vector<std::string>& args, const GlobalOptions& global) {
  AnalysisOptions o;
  std::vector<std::string> params;
  std::string output;
  std::string engine_name;
  int standstill = 60;
  int threshold = o.engine.bgsub.threshold;
  bool thesis = false;
  cv::Point2d shoulder, elbow, wrist;
  cv::Rect roi;
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
      "  armmimic-cli analyze INPUT... -o ANGLES.tsv --engine marker --reference REF.png\n"
      "          [--low 20] [--high 80] [--fov 60]\n"
      "  Arm engines also take [--roi X,Y,W,H] [--shoulder X,Y] [--thesis].",
      "Turns a video (or images) into an angle file v1, one row per analysed frame.\n"
      "bgsub, and lk without --shoulder: frames [F, F+standstill) are the standstill (no rows);\n"
      "every later frame is a row. lk with --shoulder has no standstill: frame F is the known\n"
      "starting posture and already gets a row (--standstill-frames is then refused). With\n"
      "--elbow and --wrist too, the three clicked joints give the starting directions and the\n"
      "segment lengths; otherwise the arm length is estimated and the estimate is printed.\n"
      "marker: one row per input image, in input order, with the image's name and the signed\n"
      "yaw (yaw_signed_deg) after the listed columns; --thesis reads yaw as acos(n/N), unsigned.\n"
      "Ctrl-C keeps the rows so far in a valid file marked complete=no (exit 1).\n" +
          ParamList());
  p.Positionals(&o.inputs, "INPUT", 1, -1);
  p.String("-o,--output", &output, "ANGLES.tsv", "the angle file to write (required)");
  p.String("--engine", &engine_name, "NAME", "bgsub, lk or marker (required)");
  p.String("--background", &o.background_path, "BG.png", "bgsub/lk: the empty scene image");
  p.Int("--background-frames", &o.background_frames, "K",
        "bgsub/lk: estimate the background from frames [0, K) of the video", 1, 1000000);
  p.String("--arm-length", &o.arm_length_path, "ARM.png",
           "bgsub: straight horizontal arm at zero yaw (gives b)");
  p.Int("--start", &o.start, "F",
        "bgsub/lk: first standstill frame (default 0; a camera or stream drops F frames)", 0);
  p.Int("--standstill-frames", &standstill, "N", "bgsub/lk: standstill length (default 60)", 1,
        100000);
  p.Int("--threshold", &threshold, "T", "bgsub: grey-level difference threshold (default 45)", 1,
        254);
  p.Custom("--shoulder", "X,Y", "bgsub/lk: fixed shoulder position in pixels",
           [&](const std::string& v) {
             const std::string e = ParsePointArg(v, &shoulder);
             if (e.empty()) o.shoulder_px = shoulder;
             return e;
           });
  p.Custom("--elbow", "X,Y", "lk: the elbow in frame F (with --shoulder and --wrist)",
           [&](const std::string& v) {
             const std::string e = ParsePointArg(v, &elbow);
             if (e.empty()) o.elbow_px = elbow;
             return e;
           });
  p.Custom("--wrist", "X,Y", "lk: the wrist in frame F (with --shoulder and --elbow)",
           [&](const std::string& v) {
             const std::string e = ParsePointArg(v, &wrist);
             if (e.empty()) o.wrist_px = wrist;
             return e;
           });
  p.Custom("--roi", "X,Y,W,H", "bgsub/lk: analyse only this rectangle", [&](const std::string& v) {
    const std::string e = ParseRectArg(v, &roi);
    if (e.empty()) o.roi = roi;
    return e;
  });
  p.Double("--initial-upper", &o.engine.lk.initial_upper_deg, "DEG",
           "lk: upper-arm direction at the start (default -90)");
  p.Double("--initial-fore", &o.engine.lk.initial_fore_deg, "DEG",
           "lk: forearm direction at the start (default -90)");
  p.String("--reference", &o.reference_path, "REF.png",
           "marker: the joint at zero yaw and zero bend");
  p.Int("--low", &o.engine.marker.low, "L", "marker: lower grey level of the markers (default 20)",
        0, 255);
  p.Int("--high", &o.engine.marker.high, "H",
        "marker: upper grey level of the markers (default 80)", 0, 255);
  p.Double("--fov", &o.engine.marker.fov_deg, "D",
           "marker: the camera's horizontal field of view, degrees (default 60; 0: a distant "
           "camera)");
  p.Flag("--thesis", &thesis, "run the thesis method only, without the improvements");
  p.Custom("--param", "ENGINE.KEY=VALUE",
           "any engine parameter listed above; repeatable, applied after the other flags",
           [&](const std::string& v) {
             EngineOptions probe;
             const Status st = SetEngineOption(v, &probe);
             if (st) params.push_back(v);
             return st ? std::string() : st.message();
           });
  if (auto code = p.Parse(args)) return *code;

  if (engine_name.empty()) return p.UsageError("missing --engine (bgsub, lk or marker)");
  if (!ParseEngineKind(engine_name, &o.engine.kind)) {
    return p.UsageError("--engine: unknown engine '" + engine_name + "' (bgsub, lk or marker)");
  }
  if (output.empty()) return p.UsageError("missing -o ANGLES.tsv (the angle file to write)");
  for (const auto& [flag, engines] : EngineFlags()) {
    if (p.Given(flag) && !engines.count(o.engine.kind)) {
      return p.UsageError(flag + " is not used by --engine " + engine_name);
    }
  }
  for (const std::string& assignment : params) {
    if (assignment.rfind(engine_name + ".", 0) != 0) {
      return p.UsageError("--param " + assignment + " is not used by --engine " + engine_name);
    }
  }
  if (o.engine.kind == EngineKind::kLk && p.Given("--shoulder") && p.Given("--standstill-frames")) {
    return p.UsageError(
        "--standstill-frames is not used by --engine lk with --shoulder: frame F is the starting "
        "posture and gets a row");
  }
  if (p.Given("--elbow") && (p.Given("--initial-upper") || p.Given("--initial-fore"))) {
    return p.UsageError(
        std::string(p.Given("--initial-upper") ? "--initial-upper" : "--initial-fore") +
        " cannot be given with --elbow and --wrist: the clicked joints give the "
        "starting directions");
  }
  o.engine.bgsub.standstill_frames = standstill;
  o.engine.lk.standstill_frames = standstill;
  o.engine.bgsub.threshold = threshold;
  if (o.background_frames > 0) o.engine.bgsub.background_frames = o.background_frames;
  o.engine.bgsub.thesis_mode = thesis;
  o.engine.lk.thesis_mode = thesis;
  o.engine.marker.thesis_mode = thesis;
  // An explicit grey window is used as given; otherwise the marker engine may shift it when the
  // reference's markers do not show in 20..80 (other illumination).
  if (p.Given("--low") || p.Given("--high")) o.engine.marker.auto_window = false;
  for (const std::string& assignment : params) SetEngineOption(assignment, &o.engine);
  if (Status st = o.Check(); !st) return p.UsageError(st.message());

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
