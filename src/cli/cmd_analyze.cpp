// armmimic-cli analyze INPUT... -o ANGLES.tsv --engine bgsub|lk|marker|pose: video or images in,
// an angle file v1 out (docs/cli.md); or many videos into a folder (--output-dir, --list); or the
// run recorded in an earlier angle file again (--params-from). Ctrl-C, SIGTERM and SIGHUP keep
// the rows so far in a file marked complete=no.
#include <filesystem>
#include <iostream>

#include "analysis_flags.h"
#include "analyze_run.h"
#include "args.h"
#include "armmimic/core/output_file.h"
#include "armmimic/engines/analysis.h"
#include "armmimic/engines/option_fields.h"
#include "armmimic/engines/run_record.h"
#include "command.h"
#include "interrupt.h"

namespace armmimic::cli {
namespace {

// Everything the command line gives; engine settings are applied over the recorded run (with
// --params-from) or the defaults only where their flag was given.
struct AnalyzeFlags {
  AnalysisOptions f;  // flag values (inputs, images, points, engine fields with their own flag)
  std::vector<std::string> params;
  std::string output, output_dir, list, summary, params_from, engine_name, side_name;
  int standstill = 60;
  int threshold = BgsubOptions().threshold;
  bool thesis = false;
};

constexpr const char* kSynopsis =
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
    "          [--low 20] [--high 80] [--fov 60]\n"
    "  armmimic-cli analyze VIDEO -o ANGLES.tsv --engine pose [--side left|right] [--start F]\n"
    "          [--model DIR]\n"
    "  armmimic-cli analyze VIDEO -o NEW.tsv --params-from OLD.tsv [flags]\n"
    "  armmimic-cli analyze (VIDEO... | --list FILE) --output-dir DIR [--summary FILE]\n"
    "          (--engine E [engine flags] | --params-from OLD.tsv [flags])\n"
    "  Arm engines also take [--roi X,Y,W,H] [--shoulder X,Y] [--thesis].";

constexpr const char* kDescription =
    "Turns a video (or images) into an angle file v1, one row per analysed frame.\n"
    "bgsub, and lk without --shoulder: frames [F, F+standstill) are the standstill (no rows);\n"
    "every later frame is a row. lk with --shoulder has no standstill: frame F is the known\n"
    "starting posture and already gets a row (--standstill-frames is then refused). With\n"
    "--elbow and --wrist too, the three clicked joints give the starting directions and the\n"
    "segment lengths; otherwise the arm length is estimated and the estimate is printed.\n"
    "lk --auto-calibrate: the pose network finds the shoulder, elbow and wrist in frame F, as\n"
    "if clicked (--side names the person's own arm; default: the better seen).\n"
    "marker: one row per input image, in input order, with the image's name and the signed\n"
    "yaw (yaw_signed_deg) after the listed columns; --thesis reads yaw as acos(n/N), unsigned.\n"
    "bgsub (not --thesis) follows the angles with a confidence column (0-1), as pose does.\n"
    "pose: a pose network (MoveNet) finds the person's arm in every frame from F on, with no\n"
    "background or calibration; a row is lost where the arm is not seen or a segment points at\n"
    "the camera, and a confidence column (0-1) follows the angles. --side names the person's\n"
    "own arm (default: the better seen over the first second). The model is fetched by\n"
    "scripts/deps.sh --with-model and found without flags (docs/pose.md).\n"
    "The header records the run: the engine, every ENGINE.KEY setting and the input images.\n"
    "--params-from OLD.tsv repeats that run on VIDEO; flags given as well override it.\n"
    "Batch: with --output-dir, each VIDEO (or each line of the --list file) is analysed on its\n"
    "own into DIR/NAME.tsv (NAME: the video's name without its extension), and DIR/summary.tsv\n"
    "gets one line per video: video, angles, frames, ok, lost, coverage (ok/frames), seconds,\n"
    "status (ok, failed, interrupted, skipped) and error. A failing video does not stop the\n"
    "others; exit 0 only when every video was analysed.\n"
    "No output may be one of the inputs (same file, also through a link): exit 2.\n"
    "Ctrl-C, SIGTERM or SIGHUP keeps the rows so far in a valid file marked complete=no\n"
    "(exit 1); a batch then writes its summary and starts no further video.\n";

void DefineFlags(ArgParser& p, AnalyzeFlags& a) {
  AnalysisOptions& f = a.f;
  p.Positionals(&f.inputs, "INPUT", 0, -1);
  p.String("-o,--output", &a.output, "ANGLES.tsv", "the angle file to write");
  p.String("--output-dir", &a.output_dir, "DIR",
           "batch: one angle file per video in DIR (created if missing)");
  p.String("--list", &a.list, "FILE", "batch: the videos, one per line (with --output-dir)");
  p.String("--summary", &a.summary, "FILE", "batch: the summary table (default DIR/summary.tsv)");
  p.String("--params-from", &a.params_from, "OLD.tsv",
           "repeat the run recorded in OLD.tsv's header (engine, settings, input images)");
  p.String("--engine", &a.engine_name, "NAME", "bgsub, lk, marker or pose (required)");
  p.String("--background", &f.background_path, "BG.png", "bgsub/lk: the empty scene image");
  p.Int("--background-frames", &f.background_frames, "K",
        "bgsub/lk: estimate the background from frames [0, K) of the video", 1, 1000000);
  p.String("--arm-length", &f.arm_length_path, "ARM.png",
           "bgsub: straight horizontal arm at zero yaw (gives b)");
  p.Int("--start", &f.start, "F",
        "bgsub/lk: first standstill frame; pose: first frame (default 0; a camera or stream "
        "drops F frames)",
        0);
  p.Int("--standstill-frames", &a.standstill, "N", "bgsub/lk: standstill length (default 60)", 1,
        100000);
  p.Int("--threshold", &a.threshold, "T", "bgsub: grey-level difference threshold (default 45)", 1,
        254);
  auto point = [](std::optional<cv::Point2d>* out) {
    return [out](const std::string& v) {
      cv::Point2d pt;
      const std::string e = ParsePointArg(v, &pt);
      if (e.empty()) *out = pt;
      return e;
    };
  };
  p.Custom("--shoulder", "X,Y", "bgsub/lk: fixed shoulder position in pixels",
           point(&f.shoulder_px));
  p.Custom("--elbow", "X,Y", "lk: the elbow in frame F (with --shoulder and --wrist)",
           point(&f.elbow_px));
  p.Custom("--wrist", "X,Y", "lk: the wrist in frame F (with --shoulder and --elbow)",
           point(&f.wrist_px));
  p.Custom("--roi", "X,Y,W,H", "bgsub/lk: analyse only this rectangle", [&f](const std::string& v) {
    cv::Rect roi;
    const std::string e = ParseRectArg(v, &roi);
    if (e.empty()) f.roi = roi;
    return e;
  });
  p.Double("--initial-upper", &f.engine.lk.initial_upper_deg, "DEG",
           "lk: upper-arm direction at the start (default -90)");
  p.Double("--initial-fore", &f.engine.lk.initial_fore_deg, "DEG",
           "lk: forearm direction at the start (default -90)");
  p.String("--reference", &f.reference_path, "REF.png",
           "marker: the joint at zero yaw and zero bend");
  p.Int("--low", &f.engine.marker.low, "L", "marker: lower grey level of the markers (default 20)",
        0, 255);
  p.Int("--high", &f.engine.marker.high, "H",
        "marker: upper grey level of the markers (default 80)", 0, 255);
  p.Double("--fov", &f.engine.marker.fov_deg, "D",
           "marker: the camera's horizontal field of view, degrees (default 60; 0: a distant "
           "camera)");
  p.String("--side", &a.side_name, "left|right",
           "pose, lk --auto-calibrate: the person's own arm (default: the better seen)");
  p.String("--model", &f.model_dir, "DIR",
           "pose, lk --auto-calibrate: the folder holding movenet-lightning.json and .bin");
  p.Flag("--auto-calibrate", &f.auto_calibrate,
         "lk: the shoulder, elbow and wrist in frame F from the pose network");
  p.Flag("--thesis", &a.thesis, "run the thesis method only, without the improvements");
  p.Custom("--param", "ENGINE.KEY=VALUE",
           "any engine parameter listed below; repeatable, applied after the other flags",
           [&a](const std::string& v) {
             EngineOptions probe;
             const Status st = SetEngineOption(v, &probe);
             if (st) a.params.push_back(v);
             return st ? std::string() : st.message();
           });
}

// Copies the flags that were given over `o` (the defaults, or the run read with --params-from).
void ApplyGivenFlags(const ArgParser& p, const AnalyzeFlags& a, AnalysisOptions* o) {
  const AnalysisOptions& f = a.f;
  if (p.Given("--background")) {
    o->background_path = f.background_path;
    o->background_frames = 0;
  }
  if (p.Given("--background-frames")) {
    o->background_frames = f.background_frames;
    o->background_path.clear();
    o->engine.bgsub.background_frames = f.background_frames;
  }
  if (p.Given("--arm-length")) o->arm_length_path = f.arm_length_path;
  if (p.Given("--reference")) o->reference_path = f.reference_path;
  if (p.Given("--start")) o->start = f.start;
  if (p.Given("--shoulder")) o->shoulder_px = f.shoulder_px;
  if (p.Given("--elbow")) o->elbow_px = f.elbow_px;
  if (p.Given("--wrist")) o->wrist_px = f.wrist_px;
  if (p.Given("--roi")) o->roi = f.roi;
  if (p.Given("--model")) o->model_dir = f.model_dir;
  if (f.auto_calibrate) o->auto_calibrate = true;
  if (p.Given("--side")) {
    ParsePoseSide(a.side_name, &o->engine.pose.side);  // checked in CheckEngine
    o->calibrate_side = o->engine.pose.side;
  }
  if (p.Given("--standstill-frames")) {
    o->engine.bgsub.standstill_frames = a.standstill;
    o->engine.lk.standstill_frames = a.standstill;
  }
  if (p.Given("--threshold")) o->engine.bgsub.threshold = a.threshold;
  if (p.Given("--initial-upper")) o->engine.lk.initial_upper_deg = f.engine.lk.initial_upper_deg;
  if (p.Given("--initial-fore")) o->engine.lk.initial_fore_deg = f.engine.lk.initial_fore_deg;
  // An explicit grey window is used as given; otherwise the marker engine may shift it when the
  // reference's markers do not show in 20..80 (other illumination).
  if (p.Given("--low")) o->engine.marker.low = f.engine.marker.low;
  if (p.Given("--high")) o->engine.marker.high = f.engine.marker.high;
  if (p.Given("--low") || p.Given("--high")) o->engine.marker.auto_window = false;
  if (p.Given("--fov")) o->engine.marker.fov_deg = f.engine.marker.fov_deg;
  if (a.thesis) {
    o->engine.bgsub.thesis_mode = true;
    o->engine.lk.thesis_mode = true;
    o->engine.marker.thesis_mode = true;
  }
  for (const std::string& assignment : a.params) SetEngineOption(assignment, &o->engine);
}

// Every file the run reads, named by its flag.
std::vector<NamedPath> InputsOf(const AnalysisOptions& o, const AnalyzeFlags& a,
                                const std::vector<std::string>& videos) {
  std::vector<NamedPath> in;
  for (const std::string& v : videos) in.push_back({"INPUT", v});
  for (const auto& [flag, path] :
       {std::pair<const char*, const std::string*>{"--background", &o.background_path},
        {"--arm-length", &o.arm_length_path},
        {"--reference", &o.reference_path},
        {"--model", &o.model_dir},
        {"--params-from", &a.params_from},
        {"--list", &a.list}}) {
    if (!path->empty()) in.push_back({flag, *path});
  }
  return in;
}

// Checks the flags that need no file; returns the usage error text or "".
std::string CheckFlags(const ArgParser& p, const AnalyzeFlags& a) {
  const bool batch = !a.output_dir.empty();
  if (!a.output.empty() && batch) return "-o and --output-dir exclude each other";
  if (!batch && !a.list.empty()) return "--list needs --output-dir DIR (where the files go)";
  if (!batch && !a.summary.empty()) return "--summary needs --output-dir DIR";
  if (!batch && a.output.empty()) return "missing -o ANGLES.tsv (the angle file to write)";
  if (a.f.inputs.empty() && a.list.empty()) return "missing INPUT (a video, images or a folder)";
  if (!a.list.empty() && !a.f.inputs.empty()) return "give the videos either as INPUT or in --list";
  if (p.Given("--elbow") && (p.Given("--initial-upper") || p.Given("--initial-fore"))) {
    return std::string(p.Given("--initial-upper") ? "--initial-upper" : "--initial-fore") +
           " cannot be given with --elbow and --wrist: the clicked joints give the starting "
           "directions";
  }
  return "";
}

// The engine and the flags that suit it; returns the usage error text or "".
std::string CheckEngine(const ArgParser& p, const AnalyzeFlags& a, const AnalysisOptions& o) {
  const std::string engine = EngineName(o.engine.kind);
  for (const auto& [flag, engines] : AnalysisFlags::EngineFlags()) {
    if (p.Given(flag) && !engines.count(o.engine.kind)) {
      return flag + " is not used by --engine " + engine;
    }
  }
  for (const std::string& assignment : a.params) {
    if (assignment.rfind(engine + ".", 0) != 0) {
      return "--param " + assignment + " is not used by --engine " + engine;
    }
  }
  PoseSide side = PoseSide::kAuto;
  if (p.Given("--side") && !ParsePoseSide(a.side_name, &side)) {
    return "--side '" + a.side_name + "': expected left or right (the person's own)";
  }
  const bool auto_calibrate = o.auto_calibrate || a.f.auto_calibrate;
  if (o.engine.kind != EngineKind::kPose && !auto_calibrate &&
      (p.Given("--side") || p.Given("--model"))) {
    return std::string(p.Given("--side") ? "--side" : "--model") + " is used by --engine " +
           engine + " only with --auto-calibrate";
  }
  if (o.engine.kind == EngineKind::kLk && (p.Given("--shoulder") || auto_calibrate) &&
      p.Given("--standstill-frames")) {
    return "--standstill-frames is not used by --engine lk with --shoulder: frame F is the "
           "starting posture and gets a row";
  }
  return "";
}

int RunAnalyze(const std::vector<std::string>& args, const GlobalOptions& global) {
  AnalyzeFlags a;
  ArgParser p("analyze", kSynopsis, kDescription + AnalysisFlags::ParamList());
  DefineFlags(p, a);
  if (auto code = p.Parse(args)) return *code;
  if (const std::string e = CheckFlags(p, a); !e.empty()) return p.UsageError(e);
  const bool batch = !a.output_dir.empty();
  std::vector<NamedPath> outputs;
  if (!batch) outputs.push_back({"-o", a.output});
  if (!a.summary.empty()) outputs.push_back({"--summary", a.summary});
  // Nothing is read before the outputs are known not to be inputs.
  if (Status st = CheckOutputs(InputsOf(a.f, a, a.f.inputs), outputs); !st) {
    return p.UsageError(st.message());
  }
  AnalysisOptions o;
  if (!a.params_from.empty()) {
    if (Status st = ReadRunRecord(a.params_from, &o); !st) {
      std::cerr << "armmimic-cli analyze: --params-from " << st.message() << "\n";
      return kExitFailure;
    }
    EngineKind given;
    if (p.Given("--engine") && ParseEngineKind(a.engine_name, &given) && given != o.engine.kind) {
      return p.UsageError("--engine " + a.engine_name + ": " + a.params_from + " records a " +
                          EngineName(o.engine.kind) + " run; drop --engine or --params-from");
    }
  } else if (a.engine_name.empty()) {
    return p.UsageError("missing --engine (bgsub, lk, marker or pose)");
  }
  if (!a.engine_name.empty() && !ParseEngineKind(a.engine_name, &o.engine.kind)) {
    return p.UsageError("--engine: unknown engine '" + a.engine_name +
                        "' (bgsub, lk, marker or pose)");
  }
  if (const std::string e = CheckEngine(p, a, o); !e.empty()) return p.UsageError(e);
  ApplyGivenFlags(p, a, &o);
  o.inputs = a.f.inputs;

  std::vector<std::string> videos = a.f.inputs;
  if (!a.list.empty()) {
    if (Status st = ReadVideoList(a.list, &videos); !st) {
      std::cerr << "armmimic-cli analyze: " << st.message() << "\n";
      return kExitFailure;
    }
    if (videos.empty()) return p.UsageError("--list " + a.list + ": names no video");
    o.inputs = {videos.front()};
  }
  if (Status st = o.Check(); !st) return p.UsageError(st.message());
  BatchPlan plan;
  if (batch) {
    plan = PlanBatch(videos, a.output_dir, a.summary);
    outputs.clear();
    for (std::size_t i = 0; i < videos.size(); ++i) {
      outputs.push_back({"the angle file of " + videos[i], plan.outputs[i]});
    }
    outputs.push_back({"--summary", plan.summary});
    if (Status st = CheckOutputsAreDistinct(outputs); !st) return p.UsageError(st.message());
  }
  // Again with the images the recorded run names, and every video of a list.
  if (Status st = CheckOutputs(InputsOf(o, a, videos), outputs); !st) {
    return p.UsageError(st.message());
  }
  InterruptGuard guard;
  if (!batch) return AnalyzeOne(o, a.output, global);
  std::error_code ec;
  std::filesystem::create_directories(a.output_dir, ec);
  if (ec || !std::filesystem::is_directory(a.output_dir)) {
    std::cerr << "armmimic-cli analyze: --output-dir " << a.output_dir
              << ": cannot create the folder" << (ec ? " (" + ec.message() + ")" : "") << "\n";
    return kExitFailure;
  }
  return AnalyzeBatch(o, plan, global);
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(analyze, "analyze", "turn a video or images into an angle file", 20,
                          RunAnalyze);

}  // namespace armmimic::cli
