// armmimic-cli plan ANGLES.tsv -o PROGRAM.val: angle series -> PUMA joint keyframes -> VAL text.
#include <cmath>
#include <iostream>

#include "args.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/core/atomic_file.h"
#include "armmimic/core/same_file.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/val_program.h"
#include "command.h"
#include "interrupt.h"

namespace armmimic::cli {
namespace {

using robot::kJoints;

std::string Num(double v, int decimals) { return FormatNumber(v, decimals); }

struct MapFlag {
  bool given = false;
  robot::JointMap map;
};

int RunPlan(const std::vector<std::string>& args, const GlobalOptions& global) {
  robot::PlannerOptions o;
  std::vector<std::string> input;
  std::string output, profile_path, source_kind = "auto", j2_source, j3_source;
  std::string mode, program_name, gap = "interpolate", on_speed = "stretch";
  MapFlag map[3];
  std::string limits_text, speed_text, hold_text;

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
  for (int j = 0; j < 3; ++j) {
    const std::string joint = "j" + std::to_string(j + 1);
    static const char* kHelp[3] = {
        "J1 from yaw: sign (+1/-1) and offset in deg (default +1,0)",
        "J2 from elevation (arm) or bend (marker): sign,offset (default -1,0; marker -1,-90)",
        "J3 from flexion (arm; marker: held at the offset): sign,offset (default -1,0)"};
    p.Custom("--map-" + joint, "SIGN,OFFSET", kHelp[j], [&map, j](const std::string& v) {
      map[j].given = true;
      return robot::ParseJointMap(v, &map[j].map);
    });
  }
  p.String("--hold", &hold_text, "J4,J5,J6", "values J4..J6 are held at, deg (default 0,0,0)");
  p.Flag("--mirror", &o.mapping.mirror,
         "the person is seen mirrored: yaw turns J1 the other way (and signed sources flip)");
  p.String("--source", &source_kind, "auto|arm|marker",
           "which engine the angles come from (default auto: from the file)");
  p.String("--j2-source", &j2_source, "elevation|upper",
           "arm: J2 from the folded elevation (default) or the continuous signed upper_deg");
  p.String("--j3-source", &j3_source, "flexion|bend",
           "arm: J3 from the flexion |bend| (default) or the signed bend_deg");
  p.Double("--cutoff", &o.cutoff_hz, "HZ", "zero-phase low-pass cutoff; 0 = no filter (default 3)");
  p.Double("--max-gap-s", &o.max_gap_s, "S",
           "longest run of lost frames filled in; longer refuses (default 0.5)");
  p.String("--gap", &gap, "hold|interpolate", "how lost frames are filled (default interpolate)");
  p.Double("--max-jump", &o.max_jump_deg_s, "DEG/S",
           "faster changes are impossible and flagged as lost (default 1000)");
  p.Double("--deadband", &o.deadband_deg, "DEG",
           "a new keyframe when a joint moved more than this (default 2)");
  p.Double("--min-interval", &o.min_interval_s, "S",
           "no two motion keyframes closer than this (default 0.2: at most 5 moves/s)");
  p.Double("--max-interval", &o.max_interval_s, "S", "a keyframe at least this often (default 1)");
  p.String("--limits", &limits_text, "J<n>=MIN:MAX,...",
           "override joint limits (defaults J1 -160:160 J2 -200:20 J3 -225:45 J4 -266:266 J5 "
           "-100:100 J6 -266:266)");
  p.String("--speed-limit", &speed_text, "DEG/S[,...]",
           "joint speed limits, one value or six (default 45,45,45,90,90,90)");
  p.Flag("--clamp", &o.clamp, "clamp targets outside the limits (reported) instead of refusing");
  p.String("--on-speed", &on_speed, "stretch|refuse",
           "a step faster than the speed limit stretches the time (default) or refuses");
  p.Double("--fallback-fps", &o.fallback_fps, "F",
           "rows per second when the file's times do not increase (default 1)");
  p.String("--profile", &profile_path, "FILE",
           "controller profile (docs/profiles/default.profile); default: built in");
  p.String("--mode", &mode, "stream|program",
           "stream DO MOVE lines, or upload a program and EXECUTE it (default: the profile's)");
  p.String("--program-name", &program_name, "NAME", "program name in program mode");
  if (auto code = p.Parse(args)) return *code;

  if (output.empty()) return p.UsageError("-o/--output: the VAL program to write is required");
  {
    std::vector<NamedPath> inputs = {{"ANGLES.tsv", input[0]}};
    if (!profile_path.empty()) inputs.push_back({"--profile", profile_path});
    if (Status s = CheckOutputsAreNotInputs(inputs, {{"-o", output}}); !s.ok()) {
      return p.UsageError(s.message());
    }
  }
  InterruptGuard guard;
  std::string err;
  if (!limits_text.empty() && !(err = robot::ParseLimitsOverride(limits_text, &o.limits)).empty()) {
    return p.UsageError("--limits: " + err);
  }
  if (!speed_text.empty() && !(err = robot::ParseSpeedLimits(speed_text, &o.limits)).empty()) {
    return p.UsageError("--speed-limit: " + err);
  }
  if (gap == "hold") {
    o.gap = robot::GapMode::kHold;
  } else if (gap != "interpolate") {
    return p.UsageError("--gap: '" + gap + "' is not hold or interpolate");
  }
  if (on_speed == "refuse") {
    o.speed = robot::SpeedPolicy::kRefuse;
  } else if (on_speed != "stretch") {
    return p.UsageError("--on-speed: '" + on_speed + "' is not stretch or refuse");
  }
  if (source_kind != "auto" && source_kind != "arm" && source_kind != "marker") {
    return p.UsageError("--source: '" + source_kind + "' is not auto, arm or marker");
  }
  if (!j2_source.empty() && j2_source != "elevation" && j2_source != "upper") {
    return p.UsageError("--j2-source: '" + j2_source + "' is not elevation or upper");
  }
  if (!j3_source.empty() && j3_source != "flexion" && j3_source != "bend") {
    return p.UsageError("--j3-source: '" + j3_source + "' is not flexion or bend");
  }
  robot::JointArray hold{};
  if (!hold_text.empty()) {
    std::vector<double> v;
    std::string part;
    std::size_t start = 0;
    while (start <= hold_text.size()) {
      const auto comma = hold_text.find(',', start);
      part =
          hold_text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      double d = 0;
      if (!ParseDoubleArg(part, &d)) {
        return p.UsageError("--hold: '" + hold_text + "' is not three numbers J4,J5,J6");
      }
      v.push_back(d);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (v.size() != 3)
      return p.UsageError("--hold: '" + hold_text + "' is not three numbers J4,J5,J6");
    for (int j = 0; j < 3; ++j) hold[3 + j] = v[j];
  }

  robot::ControllerProfile profile;
  if (!profile_path.empty()) {
    const Status s = robot::ReadProfile(profile_path, &profile);
    if (!s.ok()) {
      std::cerr << "armmimic-cli plan: " << s.message() << "\n";
      return kExitFailure;
    }
  }
  if (!mode.empty() && !robot::ParseSendMode(mode, &profile.mode)) {
    return p.UsageError("--mode: '" + mode + "' is not stream or program");
  }
  if (!program_name.empty()) profile.program_name = program_name;
  if (Status s = profile.Check(); !s.ok()) {
    return p.UsageError((program_name.empty() ? "--profile: " : "--program-name: ") + s.message());
  }

  AngleFile angles;
  if (Status s = ReadAngleFile(input[0], &angles); !s.ok()) {
    std::cerr << "armmimic-cli plan: " << s.message() << "\n";
    return kExitFailure;
  }
  const robot::SourceKind kind =
      source_kind == "auto"
          ? robot::DetectSourceKind(angles)
          : (source_kind == "marker" ? robot::SourceKind::kMarker : robot::SourceKind::kArm);
  const bool mirror = o.mapping.mirror;
  o.mapping = robot::MappingOptions::Default(kind);
  o.mapping.mirror = mirror;
  o.mapping.follow_file_kind = source_kind == "auto";
  o.mapping.hold_deg = hold;
  if (map[0].given) o.mapping.j1 = map[0].map;
  if (map[1].given) o.mapping.j2 = map[1].map;
  if (map[2].given) o.mapping.j3 = map[2].map;
  o.mapping.j2_elevation = j2_source != "upper";
  o.mapping.j3_flexion = j3_source != "bend";
  if (Status s = o.Check(); !s.ok()) {
    const std::string& m = s.message();
    std::string flag = "--limits";
    if (m.find("mapping") != std::string::npos || m.find("hold") != std::string::npos) {
      flag = "--map-j*/--hold";
    } else if (m.find("speed limit") != std::string::npos) {
      flag = "--speed-limit";
    } else if (m.rfind("cutoff", 0) == 0) {
      flag = "--cutoff";
    } else if (m.rfind("max gap", 0) == 0) {
      flag = "--max-gap-s";
    } else if (m.rfind("max jump", 0) == 0) {
      flag = "--max-jump";
    } else if (m.rfind("deadband", 0) == 0) {
      flag = "--deadband";
    } else if (m.rfind("min interval", 0) == 0) {
      flag = "--min-interval";
    } else if (m.rfind("max interval", 0) == 0) {
      flag = "--max-interval";
    } else if (m.rfind("fallback", 0) == 0) {
      flag = "--fallback-fps";
    }
    return p.UsageError(flag + ": " + m);
  }

  robot::Trajectory trajectory;
  robot::PlanReport report;
  if (Status s = robot::PlanTrajectory(angles, o, &trajectory, &report); !s.ok()) {
    if (s.message().rfind("cutoff", 0) == 0) return p.UsageError("--cutoff: " + s.message());
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
  if (Status s = WriteFileAtomically(output, text); !s.ok()) {
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
