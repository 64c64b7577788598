#include "planner_flags.h"
#include "flag_for_key.h"

#include <cctype>
#include <vector>

#include "armmimic/robot/option_tables.h"

namespace armmimic::cli {
void PlannerFlags::RegisterMapping(ArgParser& p, const std::function<void()>& more) {
  for (int j = 0; j < 3; ++j) {
    const std::string joint = "j" + std::to_string(j + 1);
    static const char* kHelp[3] = {
        "J1 from yaw: sign (+1/-1) and offset in deg (default +1,0)",
        "J2 from elevation (arm) or bend (marker): sign,offset (default -1,0; marker -1,-90)",
        "J3 from flexion (arm; marker: held at the offset): sign,offset (default -1,0)"};
    p.Custom("--map-" + joint, "SIGN,OFFSET", kHelp[j], [this, j](const std::string& v) {
      map_[j].given = true;
      return robot::ParseJointMap(v, &map_[j].map);
    });
  }
  p.String("--hold", &hold_text_, "J4,J5,J6", "values J4..J6 are held at, deg (default 0,0,0)");
  p.Flag("--mirror", &o_->mapping.mirror,
         "the person is seen mirrored: yaw turns J1 the other way (and signed sources flip)");
  if (more) more();
  p.String("--j2-source", &j2_source_, "elevation|upper",
           "arm: J2 from the folded elevation (default) or the continuous signed upper_deg");
  p.String("--j3-source", &j3_source_, "flexion|bend",
           "arm: J3 from the flexion |bend| (default) or the signed bend_deg");
}

void PlannerFlags::RegisterFilter(ArgParser& p, const std::function<void()>& more) {
  NumberFlag(p, "cutoff_hz", "causal low-pass cutoff; lags sqrt(2)/(2 pi HZ) s; 0 = no filter");
  NumberFlag(p, "max_gap_s", "after a longer run of lost frames the filter restarts");
  if (more) more();
  NumberFlag(p, "max_jump_deg_s", nullptr);
  NumberFlag(p, "deadband_deg", "a new command when a joint moved more than this");
  NumberFlag(p, "min_interval_s", "no two commands closer than this; 0.2 s: at most 5 moves/s");
  NumberFlag(p, "max_interval_s", "a command at least this often while the target changes");
}

void PlannerFlags::NumberFlag(ArgParser& p, const char* key, const char* live_help) {
  const OptionField<robot::PlannerOptions>& f = *FindOptionField(robot::PlannerOptionFields(), key);
  std::string metavar;
  for (char c : f.unit) metavar += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::string help = std::string(live_ && live_help ? live_help : f.help.c_str()) +
                           " (default " + OptionDefaultText(f) + ")";
  robot::PlannerOptions* o = o_;
  // Parsed as any number: the range is checked with the others in Finish (PlannerOptions::Check).
  p.Custom(f.flag, metavar, help, [o, &f](const std::string& v) {
    double d = 0;
    if (!ParseDoubleArg(v, &d)) return "'" + v + "' is not a number (use '.' decimals)";
    f.set(*o, d);
    return std::string();
  });
}

void PlannerFlags::RegisterLimits(ArgParser& p) {
  p.String("--limits", &limits_text_, "J<n>=MIN:MAX,...",
           "override joint limits (defaults J1 -160:160 J2 -200:20 J3 -225:45 J4 -266:266 J5 "
           "-100:100 J6 -266:266)");
  p.String("--speed-limit", &speed_text_, "DEG/S[,...]",
           "joint speed limits, one value or six (default 45,45,45,90,90,90)");
  p.Flag("--clamp", &o_->clamp,
         live_ ? "clamp targets outside the limits instead of holding the robot"
               : "clamp targets outside the limits (reported) instead of refusing");
}

std::optional<int> PlannerFlags::ParseTexts(const ArgParser& p) {
  std::string err;
  if (!limits_text_.empty() &&
      !(err = robot::ParseLimitsOverride(limits_text_, &o_->limits)).empty()) {
    return p.UsageError("--limits: " + err);
  }
  if (!speed_text_.empty() && !(err = robot::ParseSpeedLimits(speed_text_, &o_->limits)).empty()) {
    return p.UsageError("--speed-limit: " + err);
  }
  if (!j2_source_.empty() && j2_source_ != "elevation" && j2_source_ != "upper") {
    return p.UsageError("--j2-source: '" + j2_source_ + "' is not elevation or upper");
  }
  if (!j3_source_.empty() && j3_source_ != "flexion" && j3_source_ != "bend") {
    return p.UsageError("--j3-source: '" + j3_source_ + "' is not flexion or bend");
  }
  if (!hold_text_.empty()) {
    std::vector<double> v;
    std::string part;
    std::size_t start = 0;
    while (start <= hold_text_.size()) {
      const auto comma = hold_text_.find(',', start);
      part =
          hold_text_.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      double d = 0;
      if (!ParseDoubleArg(part, &d)) {
        return p.UsageError("--hold: '" + hold_text_ + "' is not three numbers J4,J5,J6");
      }
      v.push_back(d);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (v.size() != 3)
      return p.UsageError("--hold: '" + hold_text_ + "' is not three numbers J4,J5,J6");
    for (int j = 0; j < 3; ++j) hold_[3 + j] = v[j];
  }

  return std::nullopt;
}

std::optional<int> PlannerFlags::Finish(const ArgParser& p, robot::SourceKind kind,
                                        bool follow_file_kind) {
  const bool mirror = o_->mapping.mirror;
  o_->mapping = robot::MappingOptions::Default(kind);
  o_->mapping.mirror = mirror;
  o_->mapping.follow_file_kind = follow_file_kind;
  o_->mapping.hold_deg = hold_;
  if (map_[0].given) o_->mapping.j1 = map_[0].map;
  if (map_[1].given) o_->mapping.j2 = map_[1].map;
  if (map_[2].given) o_->mapping.j3 = map_[2].map;
  o_->mapping.j2_elevation = j2_source_ != "upper";
  o_->mapping.j3_flexion = j3_source_ != "bend";
  if (Status s = o_->Check(); !s.ok()) return p.UsageError(Worded(s));

  return std::nullopt;
}

}  // namespace armmimic::cli
