// The robot layer's option tables: one row per setting of the planner, the mapping, the joint
// limits, the link, a send's profile and timeouts, the live stream and the profile's overrides
// (option_tables.h). Defaults are the structs' own; the robot tests check each table against
// its struct.
#include "armmimic/robot/option_tables.h"

#include <sstream>

#include "armmimic/core/option_rows.h"
#include "armmimic/core/text.h"

namespace armmimic::robot {
namespace {

using namespace option_rows;  // NOLINT(google-build-using-namespace): the row builders

using P = PlannerOptions;
using M = MappingOptions;
using L = JointLimits;
using K = LinkSettings;
using S = SendSettings;
using LS = LiveStreamOptions;
using CP = ControllerProfile;

std::string JoinNumbers(const double* v, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += (i ? "," : "") + OptionExactNumberText(v[i]);
  return out;
}

// "A,B,C,...": exactly `n` finite numbers into `out`. Error text or "".
std::string ParseNumbers(const std::string& text, int n, double* out) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) {
    double d = 0;
    if (!ParseFiniteDouble(part, &d)) return "'" + part + "' is not a number";
    v.push_back(d);
  }
  if (static_cast<int>(v.size()) != n || (!text.empty() && text.back() == ',')) {
    return "expected " + std::to_string(n) + " comma-separated numbers";
  }
  for (int i = 0; i < n; ++i) out[i] = v[i];
  return "";
}

// A joint map row: "SIGN,OFFSET", written as "+1,0" / "-1,-90".
template <JointMap MappingOptions::*member>
Row<M> Map(const char* key, const char* def, const char* flag, const char* label,
           const char* help) {
  return Text<M>(
             key, def,
             [](const M& o) {
               const JointMap& m = o.*member;
               return std::string(m.sign < 0 ? "-1," : "+1,") + OptionExactNumberText(m.offset_deg);
             },
             [](const std::string& text, M* o) { return ParseJointMap(text, &(o->*member)); },
             label, help)
      .Flag(flag)
      .Unit("deg");
}

}  // namespace

const std::vector<OptionField<PlannerOptions>>& PlannerOptionFields() {
  static const std::vector<OptionField<P>> fields = {
      Real<P>("cutoff_hz", &P::cutoff_hz, 3.0, 0, kNoMax, 2, "Cutoff",
              "zero-phase low-pass cutoff; 0 = no filter")
          .Unit("Hz")
          .Flag("--cutoff")
          .Main(),
      Real<P>("max_gap_s", &P::max_gap_s, 0.5, 0, kNoMax, 2, "Max gap",
              "longest run of lost frames filled in; longer refuses")
          .Unit("s")
          .Flag("--max-gap-s"),
      Enum<P>("gap", &P::gap, GapMode::kInterpolate, {"hold", "interpolate"}, "Gap filling",
              "how lost frames are filled")
          .Flag("--gap"),
      Real<P>("max_jump_deg_s", &P::max_jump_deg_s, 1000, 0, kNoMax, 0, "Max jump speed",
              "faster changes are impossible and flagged as lost")
          .AboveMin()
          .Unit("deg/s")
          .Flag("--max-jump"),
      Real<P>("deadband_deg", &P::deadband_deg, 2.0, 0, kNoMax, 2, "Deadband",
              "a new keyframe when a joint moved more than this")
          .Unit("deg")
          .Flag("--deadband")
          .Main(),
      Real<P>("min_interval_s", &P::min_interval_s, 0.2, 0, kNoMax, 2, "Min interval",
              "no two motion keyframes closer than this; 0.2 s: at most 5 moves/s")
          .Unit("s")
          .Flag("--min-interval")
          .Below("max_interval_s"),
      Real<P>("max_interval_s", &P::max_interval_s, 1.0, 0, kNoMax, 2, "Max interval",
              "a keyframe at least this often")
          .AboveMin()
          .Unit("s")
          .Flag("--max-interval"),
      Bool<P>(
          "clamp", &P::clamp, false, "Clamp to the limits",
          "clamp targets outside the limits (reported) instead of refusing them (live: instead of "
          "holding the robot)")
          .Flag("--clamp")
          .Main(),
      Enum<P>("speed", &P::speed, SpeedPolicy::kStretch, {"stretch", "refuse"},
              "On a too fast step",
              "a step faster than the speed limit stretches the time or refuses")
          .Flag("--on-speed"),
      Real<P>("fallback_fps", &P::fallback_fps, 1.0, 0, kNoMax, 2, "Fallback fps",
              "rows per second when the file's times do not increase")
          .AboveMin()
          .Flag("--fallback-fps"),
  };
  return fields;
}

const std::vector<OptionField<MappingOptions>>& MappingOptionFields() {
  static const std::vector<OptionField<M>> fields = {
      Map<&M::j1>("j1", "+1,0", "--map-j1", "J1 from yaw", "J1 from yaw: sign (+1/-1) and offset")
          .Main(),
      Map<&M::j2>("j2", "-1,0", "--map-j2", "J2",
                  "J2 from elevation (arm) or bend (marker, there -1,-90 by default): sign,offset")
          .Main(),
      Map<&M::j3>("j3", "-1,0", "--map-j3", "J3",
                  "J3 from flexion (arm; marker: held at the offset): sign,offset")
          .Main(),
      Bool<M>("mirror", &M::mirror, false, "Mirror",
              "the person is seen mirrored: yaw turns J1 the other way (and signed sources flip)")
          .Flag("--mirror")
          .Main(),
      Choice<M>("j2_elevation", &M::j2_elevation, true, "upper", "elevation", "J2 source",
                "arm: J2 from the folded elevation or the continuous signed upper_deg")
          .Flag("--j2-source"),
      Choice<M>("j3_flexion", &M::j3_flexion, true, "bend", "flexion", "J3 source",
                "arm: J3 from the flexion |bend| or the signed bend_deg")
          .Flag("--j3-source"),
      Choice<M>("arm_3d", &M::arm_3d, true, "2d", "3d", "Arm source",
                "arm: J1, J2 and J3 from the 3-D columns (the upper arm's azimuth and elevation, "
                "elbow_deg) in rows that have them, or from the 2-D columns always")
          .Flag("--arm-source"),
      Text<M>(
          "hold_deg", "0,0,0", [](const M& o) { return JoinNumbers(o.hold_deg.data() + 3, 3); },
          [](const std::string& text, M* o) {
            return ParseNumbers(text, 3, o->hold_deg.data() + 3);
          },
          "J4..J6 held at", "the values J4, J5 and J6 are held at")
          .Unit("deg")
          .Flag("--hold"),
  };
  return fields;
}

const std::vector<OptionField<JointLimits>>& LimitsOptionFields() {
  static const std::vector<OptionField<L>> fields = {
      Text<L>(
          "min_deg", "-160,-200,-225,-266,-100,-266",
          [](const L& o) { return JoinNumbers(o.min_deg.data(), kJoints); },
          [](const std::string& text, L* o) {
            return ParseNumbers(text, kJoints, o->min_deg.data());
          },
          "Lower limits", "each joint's lowest position, J1..J6")
          .Unit("deg")
          .Flag("--limits")
          .Main(),
      Text<L>(
          "max_deg", "160,20,45,266,100,266",
          [](const L& o) { return JoinNumbers(o.max_deg.data(), kJoints); },
          [](const std::string& text, L* o) {
            return ParseNumbers(text, kJoints, o->max_deg.data());
          },
          "Upper limits", "each joint's highest position, J1..J6")
          .Unit("deg")
          .Flag("--limits")
          .Main(),
      Text<L>(
          "max_speed_deg_s", "45,45,45,90,90,90",
          [](const L& o) { return JoinNumbers(o.max_speed_deg_s.data(), kJoints); },
          [](const std::string& text, L* o) { return ParseSpeedLimits(text, o); }, "Speed limits",
          "fastest each joint may be asked to move, one value or six")
          .Unit("deg/s")
          .Flag("--speed-limit")
          .Main(),
  };
  return fields;
}

const std::vector<OptionField<LinkSettings>>& LinkOptionFields() {
  static const std::vector<OptionField<K>> fields = {
      Bool<K>("echo", &K::echo, true, "Echo", "the controller echoes every line it receives"),
      Int<K>("wake_attempts", &K::wake_attempts, 3, 1, 100, "Wake attempts",
             "terminators written to wake the controller before giving up"),
      Real<K>("wake_timeout_s", &K::wake_timeout_s, 1.5, 0, kNoMax, 2, "Wake timeout",
              "time between wake attempts")
          .AboveMin()
          .Unit("s"),
      Real<K>("prompt_settle_s", &K::prompt_settle_s, 0.1, 0, kNoMax, 2, "Prompt settle time",
              "a '*' prompt counts only after this long without more bytes (it may start an "
              "error line)")
          .Unit("s"),
  };
  return fields;
}

const std::vector<OptionField<SendSettings>>& SendOptionFields() {
  static const std::vector<OptionField<S>> fields = {
      Text<S>(
          "profile_path", "", [](const S& o) { return o.profile_path; },
          [](const std::string& text, S* o) {
            o->profile_path = text;
            return std::string();
          },
          "Controller profile",
          "controller profile file (docs/profiles/); none: the built-in profile")
          .Flag("--profile")
          .Main(),
      Real<S>("prompt_timeout_s", &S::prompt_timeout_s, 0, 0, kNoMax, 1, "Prompt timeout",
              "time to wait for the prompt after a non-motion line; 0: the profile's "
              "prompt_timeout_s")
          .Unit("s")
          .Flag("--timeout"),
      Real<S>("motion_timeout_s", &S::motion_timeout_s, 0, 0, kNoMax, 1, "Motion timeout",
              "time to wait for the prompt after a motion line; 0: the profile's "
              "motion_timeout_s")
          .Unit("s")
          .Flag("--motion-timeout"),
  };
  return fields;
}

const std::vector<OptionField<LiveStreamOptions>>& LiveStreamOptionFields() {
  static const std::vector<OptionField<LS>> fields = {
      Real<LS>("stale_after_s", &LS::stale_after_s, 0.2, 0, kNoMax, 2, "Stale-frame timeout",
               "hold the robot when no frame was measured for this long")
          .AboveMin()
          .Unit("s")
          .Flag("--stale-after"),
  };
  return fields;
}

const std::vector<OptionField<MappingOptions>>& SourceOptionFields() {
  static const std::vector<OptionField<M>> fields = {
      Text<M>(
          "kind", "auto",
          [](const M& o) {
            return o.follow_file_kind ? "auto" : std::string(SourceKindName(o.kind));
          },
          [](const std::string& text, M* o) {
            if (text == "auto") {
              o->follow_file_kind = true;
              return std::string();
            }
            if (text != SourceKindName(SourceKind::kArm) &&
                text != SourceKindName(SourceKind::kMarker)) {
              return "'" + text + "' is not auto, arm or marker";
            }
            o->kind =
                text == SourceKindName(SourceKind::kArm) ? SourceKind::kArm : SourceKind::kMarker;
            o->follow_file_kind = false;
            return std::string();
          },
          "Angles from", "which engine the angles come from: auto (from the file), arm or marker")
          .Flag("--source"),
  };
  return fields;
}

const std::vector<OptionField<ControllerProfile>>& ProfileOptionFields() {
  static const std::vector<OptionField<CP>> fields = {
      Enum<CP>("mode", &CP::mode, SendMode::kStream, {"stream", "program"}, "Send mode",
               "stream DO MOVE lines, or upload a program and EXECUTE it")
          .Flag("--mode"),
      Text<CP>(
          "program_name", "MIMIC", [](const CP& o) { return o.program_name; },
          [](const std::string& text, CP* o) {
            o->program_name = text;  // its rules (1..15 letters, digits, '_', '.') are Check()'s
            return std::string();
          },
          "Program name", "program name in program mode")
          .Flag("--program-name"),
  };
  return fields;
}

std::string DescribePlannerSettings(const PlannerOptions& o) {
  std::string line = "settings";
  auto add = [&line](const std::vector<std::pair<std::string, std::string>>& values) {
    for (const auto& [key, value] : values) line += " " + key + "=" + value;
  };
  add(OptionTableValues(PlannerOptionFields(), "planner", o));
  add(OptionTableValues(MappingOptionFields(), "mapping", o.mapping));
  add(OptionTableValues(LimitsOptionFields(), "limits", o.limits));
  return line;
}

Status SetPlannerSetting(const std::string& assignment, PlannerOptions* o) {
  const auto eq = assignment.find('=');
  const auto dot = assignment.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq) {
    return Status::Error("'" + assignment + "': expected TABLE.KEY=VALUE");
  }
  const std::string name = assignment.substr(0, eq);
  const std::string table = assignment.substr(0, dot);
  const std::string key = assignment.substr(dot + 1, eq - dot - 1);
  const std::string value = assignment.substr(eq + 1);
  if (table == "planner") {
    if (const auto* f = FindOptionField(PlannerOptionFields(), key)) {
      return SetOptionText(*f, name, value, o);
    }
  } else if (table == "mapping") {
    if (const auto* f = FindOptionField(MappingOptionFields(), key)) {
      return SetOptionText(*f, name, value, &o->mapping);
    }
  } else if (table == "limits") {
    if (const auto* f = FindOptionField(LimitsOptionFields(), key)) {
      return SetOptionText(*f, name, value, &o->limits);
    }
  }
  return Status::Error(name, "'" + name + "' is no planner, mapping or limits setting");
}

}  // namespace armmimic::robot
