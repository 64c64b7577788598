// armmimic-cli plan ANGLES.tsv -o PROGRAM.val: angle series -> PUMA joint keyframes -> VAL text.
// Length: RunPlan is the subcommand's flag table, its checks and the run, read top to bottom in
// --help order.
#include <cmath>
#include <iostream>

#include "args.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/core/output_file.h"
#include "armmimic/robot/option_tables.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/val_program.h"
#include "command.h"
#include "flag_for_key.h"
#include "incomplete_input.h"
#include "interrupt.h"
#include "planner_flags.h"
#include "table_flags.h"

namespace armmimic::cli {
namespace {

using robot::kJoints;

std::string Num(double v, int decimals) { return FormatNumber(v, decimals); }

int RunPlan(const std::vector<std::string>& args, const GlobalOptions& global) {
  robot::PlannerOptions o;
  std::vector<std::string> input;
  std::string output;
  robot::MappingOptions source;    // --source: only its kind and follow_file_kind
  robot::SendSettings send;        // --profile
  robot::ControllerProfile given;  // --mode, --program-name (over the profile's)
  PlannerFlags flags(&o, false);
  const auto planner_row = [](const char* key) -> const OptionField<robot::PlannerOptions>& {
    return *FindOptionField(robot::PlannerOptionFields(), key);
  };

  ArgParser p(
      "plan",
      "  armmimic-cli plan ANGLES.tsv -o PROGRAM.val [--map-j1 S,O] [--map-j2 S,O] [--map-j3 S,O]\n"
      "      [--mirror] [--cutoff HZ] [--max-gap-s S] [--gap hold|interpolate] [--deadband DEG]\n"
      "      [--min-interval S] [--max-interval S] [--limits J2=MIN:MAX,...]\n"
      "      [--speed-limit DEG/S[,...]] [--clamp] [--on-speed stretch|refuse]\n"
      "      [--profile FILE] [--mode stream|program] [--program-name NAME]",
      "Turns an angle file into PUMA joint keyframes and writes them as VAL text (docs/robot.md).\n"
      "Mapping (each joint = sign * source + offset): arm engines J1 = +yaw, J2 = -elevation\n"
      "(upper arm's angle from hanging, 0..180 on either side), J3 = -flexion (|bend|); marker\n"
      "engine J1 = +yaw, J2 = -bend - 90, J3 held at 0 (aligned). J4..J6 held at 0. Every human\n"
      "arm pose fits the default limits, so an ordinary recording needs no mapping flags.\n"
      "Steps: unwrap and flag impossible jumps, fill short gaps, map, zero-phase low-pass, joint\n"
      "limits (refused, or clamped with --clamp), keyframes (deadband / interval), speed limits\n"
      "(time stretched, or refused with --on-speed refuse). Refusals list the offending frames\n"
      "and exit 1. The output is written atomically; a summary goes to stdout.");
  p.Positionals(&input, "ANGLES.tsv", 1, 1);
  p.String("-o,--output", &output, "PROGRAM.val", "the VAL program to write (required)");
  flags.RegisterMapping(p, [&] {
    AddRowFlag(p, robot::SourceOptionFields()[0], &source, WithMetavar("auto|arm|marker"));
  });
  flags.RegisterFilter(p, [&] { AddRowFlag(p, planner_row("gap"), &o); });
  flags.RegisterLimits(p);
  AddRowFlag(p, planner_row("speed"), &o);
  AddRowFlag(p, planner_row("fallback_fps"), &o, WithMetavar("FPS"));
  AddRowFlag(p, *FindOptionField(robot::SendOptionFields(), "profile_path"), &send,
             WithMetavar("FILE"));
  RowFlagWords profile_words;
  profile_words.default_note = ", or the --profile file's";
  for (const OptionField<robot::ControllerProfile>& row : robot::ProfileOptionFields()) {
    profile_words.metavar = row.kind == OptionKind::kText ? "NAME" : "";
    AddRowFlag(p, row, &given, profile_words);
  }
  bool strict = false;
  p.Flag("--strict", &strict,
         "refuse an angle file marked complete=no (exit 1; without it: a warning)");
  if (auto code = p.Parse(args)) return *code;

  if (output.empty()) return p.UsageError("-o/--output: the VAL program to write is required");
  {
    std::vector<NamedPath> inputs = {{"ANGLES.tsv", input[0]}};
    if (!send.profile_path.empty()) inputs.push_back({"--profile", send.profile_path});
    if (Status s = CheckOutputs(inputs, {{"-o", output}}); !s.ok()) {
      return p.UsageError(s.message());
    }
  }
  InterruptGuard guard;
  if (auto code = flags.ParseTexts(p)) return *code;
  robot::ControllerProfile profile;
  if (!send.profile_path.empty()) {
    const Status s = robot::ReadProfile(send.profile_path, &profile);
    if (!s.ok()) {
      std::cerr << "armmimic-cli plan: " << s.message() << "\n";
      return kExitFailure;
    }
  }
  if (p.Given("--mode")) profile.mode = given.mode;
  if (p.Given("--program-name")) profile.program_name = given.program_name;
  if (Status s = profile.Check(); !s.ok()) {
    return p.UsageError((p.Given("--program-name") ? "--program-name: " : "--profile: ") +
                        s.message());
  }

  AngleFile angles;
  if (Status s = ReadAngleFile(input[0], &angles); !s.ok()) {
    std::cerr << "armmimic-cli plan: " << s.message() << "\n";
    return kExitFailure;
  }
  if (auto code = CheckCompleteInput("plan", input[0], angles, strict)) return *code;
  const robot::SourceKind kind =
      source.follow_file_kind ? robot::DetectSourceKind(angles) : source.kind;
  if (auto code = flags.Finish(p, kind, source.follow_file_kind)) return *code;

  robot::Trajectory trajectory;
  robot::PlanReport report;
  if (Status s = robot::PlanTrajectory(angles, o, &trajectory, &report); !s.ok()) {
    if (s.key() == "planner.cutoff_hz") return p.UsageError(Worded(s));
    std::cerr << "armmimic-cli plan: " << input[0] << ": refused: " << s.message() << "\n";
    return kExitFailure;
  }
  for (const robot::PlanIssue& w : report.warnings) {
    if (!global.quiet)
      std::cerr << "armmimic-cli plan: " << input[0] << ": frame " << w.frame << ": " << w.text
                << "\n";
  }

  const std::vector<std::string> header =
      robot::DescribePlan(input[0], angles, o, report, trajectory);
  std::string text;
  if (Status s = robot::FormatValProgram(trajectory, profile, o.limits, header, &text); !s.ok()) {
    std::cerr << "armmimic-cli plan: " << output << ": " << s.message() << "\n";
    return kExitFailure;
  }
  if (InterruptGuard::interrupted()) {
    std::cerr << "plan: " << InterruptGuard::Message() << "; " << output << " not written\n";
    return kExitFailure;
  }
  if (Status s = WriteOutputFile(output, text); !s.ok()) {
    std::cerr << "armmimic-cli plan: " << s.message() << "\n";
    return kExitFailure;
  }
  if (!global.quiet) {
    std::cout << "plan: " << output << ": " << trajectory.keyframes.size() << " keyframes from "
              << report.used_rows << " of " << report.rows << " rows ("
              << robot::SourceKindName(kind) << ", " << robot::SendModeName(profile.mode)
              << " mode, SPEED " << robot::SpeedSettingFor(o.limits, profile) << ")\n"
              << "  duration " << Num(trajectory.duration_s(), 3) << " s (video "
              << Num(report.source_duration_s, 3) << " s, +" << Num(report.stretch_s, 3)
              << " s for speed limits in " << report.stretched_steps << " steps)\n"
              << "  filled " << report.filled_rows << " rows, flagged " << report.flagged_jumps
              << " jumps, clamped " << report.clamped_rows << " rows\n";
    for (int j = 0; j < kJoints; ++j) {
      std::cout << "  J" << j + 1 << " used [" << Num(report.min_deg[j], 2) << ", "
                << Num(report.max_deg[j], 2) << "] of limits [" << Num(o.limits.min_deg[j], 2)
                << ", " << Num(o.limits.max_deg[j], 2) << "]\n";
    }
  }
  return kExitOk;
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(plan, "plan", "angle file -> PUMA joint keyframes as a VAL program", 70,
                          RunPlan);

}  // namespace armmimic::cli
