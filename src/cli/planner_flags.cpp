#include "planner_flags.h"
#include "flag_for_key.h"
#include "table_flags.h"

#include <vector>

#include "armmimic/robot/option_tables.h"

namespace armmimic::cli {
namespace {

const OptionField<robot::MappingOptions>& MappingRow(const char* key) {
  return *FindOptionField(robot::MappingOptionFields(), key);
}

const OptionField<robot::JointLimits>& LimitsRow(const char* key) {
  return *FindOptionField(robot::LimitsOptionFields(), key);
}

}  // namespace

std::string LimitsFlagHelp() {
  // The two limits rows' defaults in the flag's own J<n>=MIN:MAX form.
  robot::JointLimits d;
  const auto& lower = LimitsRow("min_deg");
  const auto& upper = LimitsRow("max_deg");
  lower.parse(lower.default_text, &d);
  upper.parse(upper.default_text, &d);
  std::string defaults;
  for (int j = 0; j < robot::kJoints; ++j) {
    defaults += std::string(j ? " " : "") + "J" + std::to_string(j + 1) + " " +
                OptionNumberText(d.min_deg[j]) + ":" + OptionNumberText(d.max_deg[j]);
  }
  return "override " + OptionNoun(lower.label) + " and " + OptionNoun(upper.label) +
         " of the joints named (defaults " + defaults + ")";
}

void PlannerFlags::RegisterMapping(ArgParser& p, const std::function<void()>& more) {
  // Read into given_mapping_: Finish lays the flags given over the defaults of the source kind.
  for (const char* key : {"j1", "j2", "j3"}) {
    AddRowFlag(p, MappingRow(key), &given_mapping_, WithMetavar("SIGN,OFFSET"));
  }
  AddRowFlag(p, MappingRow("hold_deg"), &given_mapping_, WithMetavar("J4,J5,J6"));
  AddRowFlag(p, MappingRow("mirror"), &given_mapping_);
  if (more) more();
  AddRowFlag(p, MappingRow("j2_elevation"), &given_mapping_);
  AddRowFlag(p, MappingRow("j3_flexion"), &given_mapping_);
  AddRowFlag(p, MappingRow("arm_3d"), &given_mapping_);
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
  // Parsed as any number: the range is checked with the others in Finish (PlannerOptions::Check).
  RowFlagWords words;
  words.help = live_ ? live_help : nullptr;
  AddRowFlag(p, *FindOptionField(robot::PlannerOptionFields(), key), o_, words);
}

void PlannerFlags::RegisterLimits(ArgParser& p) {
  // One flag for both limits rows, in its own J<n>=MIN:MAX form: read in ParseTexts.
  p.String(LimitsRow("min_deg").flag, &limits_text_, "J<n>=MIN:MAX,...", LimitsFlagHelp());
  AddRowFlag(p, LimitsRow("max_speed_deg_s"), &o_->limits, WithMetavar("DEG/S[,...]"));
  AddRowFlag(p, *FindOptionField(robot::PlannerOptionFields(), "clamp"), o_);
}

std::optional<int> PlannerFlags::ParseTexts(const ArgParser& p) {
  std::string err;
  if (!limits_text_.empty() &&
      !(err = robot::ParseLimitsOverride(limits_text_, &o_->limits)).empty()) {
    return p.UsageError("--limits: " + err);
  }
  return std::nullopt;
}

std::optional<int> PlannerFlags::Finish(const ArgParser& p, robot::SourceKind kind,
                                        bool follow_file_kind) {
  o_->mapping = robot::MappingOptions::Default(kind);
  o_->mapping.follow_file_kind = follow_file_kind;
  for (const OptionField<robot::MappingOptions>& row : robot::MappingOptionFields()) {
    if (!p.Given(row.flag)) continue;
    if (row.kind == OptionKind::kText) {
      row.parse(row.format(given_mapping_), &o_->mapping);  // read back exactly
    } else {
      row.set(o_->mapping, row.get(given_mapping_));
    }
  }
  if (Status s = o_->Check(); !s.ok()) return p.UsageError(Worded(s));

  return std::nullopt;
}

}  // namespace armmimic::cli
