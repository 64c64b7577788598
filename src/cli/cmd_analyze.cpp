// armmimic-cli analyze INPUT... -o ANGLES.tsv --engine bgsub|lk|marker|pose: video or images in,
// an angle file v1 out (docs/cli.md); or many videos into a folder (--output-dir, --list); or the
// run recorded in an earlier angle file again (--params-from). Ctrl-C, SIGTERM and SIGHUP keep
// the rows so far in a file marked complete=no.
#include <filesystem>
#include <iostream>
#include <optional>

#include "analysis_flags.h"
#include "analyze_run.h"
#include "args.h"
#include "armmimic/core/output_file.h"
#include "armmimic/engines/analysis.h"
#include "armmimic/engines/removed_options.h"
#include "armmimic/engines/run_record.h"
#include "command.h"
#include "flag_for_key.h"
#include "interrupt.h"

namespace armmimic::cli {
namespace {

// Everything the command line gives; engine settings are applied over the recorded run (with
// --params-from) or the defaults only where their flag was given.
struct AnalyzeFlags {
  AnalysisFlags analysis;  // the engine and calibration flags, shared with mimic
  std::vector<std::string> inputs;
  std::string output, output_dir, list, summary, params_from;
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
    "  armmimic-cli analyze VIDEO -o ANGLES.tsv --engine pose [--side left|right|both]\n"
    "          [--start F] [--model DIR]\n"
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
    "hybrid: lk's tracker checked by a second opinion in every frame, bgsub's background\n"
    "difference; with no background (joints clicked on real footage) the pose network, found\n"
    "as for pose or in --model DIR (docs/hybrid.md).\n"
    "marker: one row per input image, in input order, with the image's name and the signed\n"
    "yaw (yaw_signed_deg) after the listed columns; --thesis reads yaw as acos(n/N), unsigned.\n"
    "bgsub (not --thesis) follows the angles with a confidence column (0-1), as pose does.\n"
    "pose: a pose network (MoveNet) finds the person's arm in every frame from F on, with no\n"
    "background or calibration; a row is lost where the arm is not seen or a segment points at\n"
    "the camera, and a confidence column (0-1) follows the angles. --side names the person's\n"
    "own arm (default: the better seen over the first second); --side both follows both arms\n"
    "from the same inferences into one file per arm: -o A.tsv writes A.left.tsv and\n"
    "A.right.tsv (with --output-dir, NAME.left.tsv and NAME.right.tsv, a summary line each).\n"
    "The model, found without flags, comes with the armmimic-models package or\n"
    "scripts/deps.sh --with-model (docs/pose.md).\n"
    "The header records the run: the engine, every ENGINE.KEY setting and the input images.\n"
    "--params-from OLD.tsv repeats that run on VIDEO; flags given as well override it. A\n"
    "recorded image is looked for where it was, beside OLD.tsv, then in the current folder; a\n"
    "key OLD.tsv names twice, or one no version writes, is a usage error naming the line.\n"
    "Batch: with --output-dir, each VIDEO (or each line of the --list file) is analysed on its\n"
    "own into DIR/NAME.tsv (NAME: the video's name without its extension), and DIR/summary.tsv\n"
    "gets one line per video: video, angles, frames, ok, lost, coverage (ok/frames), seconds,\n"
    "status (ok, failed, incomplete, interrupted, skipped) and error; a TAB, line end or\n"
    "backslash in a name is written \\t, \\n, \\r or \\\\, and angles is empty when no file was\n"
    "written. A failing video does not stop the others; exit 0 only when every video was\n"
    "analysed whole.\n"
    "A video that stops more than max(2 frames, 1 %) short of the frame count it announces, or\n"
    "whose read fails, keeps its rows in a file marked complete=no with the reason\n"
    "(incomplete=...) and exits 1; a smaller shortfall (an estimated count) is a warning.\n"
    "No output may be one of the inputs (same file, also through a link): exit 2.\n"
    "Ctrl-C, SIGTERM or SIGHUP keeps the rows so far in a valid file marked complete=no\n"
    "(exit 1); a batch then writes its summary and starts no further video.\n";

void DefineFlags(ArgParser& p, AnalyzeFlags& a) {
  p.Positionals(&a.inputs, "INPUT", 0, -1);
  p.String("-o,--output", &a.output, "ANGLES.tsv", "the angle file to write");
  p.String("--output-dir", &a.output_dir, "DIR",
           "batch: one angle file per video in DIR (created if missing)");
  p.String("--list", &a.list, "FILE", "batch: the videos, one per line (with --output-dir)");
  p.String("--summary", &a.summary, "FILE", "batch: the summary table (default DIR/summary.tsv)");
  p.String("--params-from", &a.params_from, "OLD.tsv",
           "repeat the run recorded in OLD.tsv's header (engine, settings, input images)");
  a.analysis.Register(p);
}

// Every file the run reads, named by its flag.
std::vector<NamedPath> InputsOf(const AnalysisOptions& o, const AnalyzeFlags& a,
                                const std::vector<std::string>& videos) {
  std::vector<NamedPath> in;
  in.reserve(videos.size() + 6);  // the videos and at most the six files below
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
  if (a.inputs.empty() && a.list.empty()) return "missing INPUT (a video, images or a folder)";
  if (!a.list.empty() && !a.inputs.empty()) return "give the videos either as INPUT or in --list";
  return a.analysis.CheckStartingDirections(p);
}

// The run --params-from records, into *o (before the flags given are applied); an exit code when
// it cannot be repeated.
std::optional<int> ReadParamsFrom(const ArgParser& p, const AnalyzeFlags& a, AnalysisOptions* o,
                                  RunRecordNotes* recorded) {
  if (Status st = ReadRunRecord(a.params_from, o, recorded); !st) {
    // A key the header must not hold is refused like an unknown flag; a file that cannot be
    // read, or a value out of range, is a failure of the file.
    if (recorded->bad_keys) return p.UsageError("--params-from " + st.message());
    std::cerr << "armmimic-cli analyze: --params-from " << st.message() << "\n";
    return kExitFailure;
  }
  const std::string& engine = a.analysis.engine_name();
  if (!recorded->ignored.empty()) {
    std::cerr << "armmimic-cli analyze: " << a.params_from << ": "
              << DescribeIgnoredEngineOptions(recorded->ignored) << "\n";
  }
  EngineKind given;
  if (p.Given("--engine") && ParseEngineKind(engine, &given) && given != o->engine.kind) {
    return p.UsageError("--engine " + engine + ": " + a.params_from + " records a " +
                        EngineName(o->engine.kind) + " run; drop --engine or --params-from");
  }
  return std::nullopt;
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
  if (Status st = CheckOutputs(InputsOf(a.analysis.values(), a, a.inputs), outputs); !st) {
    return p.UsageError(st.message());
  }
  AnalysisOptions o;
  RunRecordNotes recorded;
  if (!a.params_from.empty()) {
    if (auto code = ReadParamsFrom(p, a, &o, &recorded)) return *code;
  } else if (a.analysis.engine_name().empty()) {
    return p.UsageError("missing --engine (bgsub, lk, marker or pose)");
  }
  if (auto code = a.analysis.ParseEngine(p, &o.engine.kind)) return *code;
  if (const std::string e = a.analysis.CheckFor(p, o); !e.empty()) return p.UsageError(e);
  a.analysis.ApplyGiven(p, &o);
  o.inputs = a.inputs;
  // A recorded image found nowhere, unless a flag given replaced it.
  if (Status st = CheckRecordedPathsFound(o, recorded.missing, a.params_from); !st) {
    std::cerr << "armmimic-cli analyze: --params-from " << st.message() << "\n";
    return kExitFailure;
  }

  std::vector<std::string> videos = a.inputs;
  if (!a.list.empty()) {
    if (Status st = ReadVideoList(a.list, &videos); !st) {
      std::cerr << "armmimic-cli analyze: " << st.message() << "\n";
      return kExitFailure;
    }
    if (videos.empty()) return p.UsageError("--list " + a.list + ": names no video");
    o.inputs = {videos.front()};
  }
  if (Status st = o.Check(); !st) return p.UsageError(Worded(st));
  BatchPlan plan;
  if (!batch && AnalysedArms(o).size() > 1 && std::filesystem::exists(a.output) &&
      !std::filesystem::is_regular_file(a.output)) {
    // A device or a pipe holds one stream; the arms' files are named after a file's name.
    return p.UsageError("-o " + a.output +
                        " is not a file: --side both writes a file per arm beside a file name "
                        "(A.tsv gives A.left.tsv and A.right.tsv)");
  }
  if (!batch) {
    outputs.clear();  // with --side both: A.left.tsv and A.right.tsv
    for (const std::string& path : ArmOutputPaths(o, a.output)) outputs.push_back({"-o", path});
  } else {
    plan = PlanBatch(videos, a.output_dir, a.summary);
    outputs.clear();
    for (std::size_t i = 0; i < videos.size(); ++i) {
      for (const std::string& path : ArmOutputPaths(o, plan.outputs[i])) {
        outputs.push_back({"the angle file of " + videos[i], path});
      }
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
