// PlannerFlags: the mapping, filter, keyframe and limit flags `plan` and `mimic` share, parsed
// into one robot::PlannerOptions with the same checks and messages ("the same mapping, limits,
// speed limit, filter and deadband as plan"). Each flag comes from its row of the robot tables
// (table_flags.h): flag, help, default and range.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "args.h"
#include "armmimic/robot/planner.h"

namespace armmimic::cli {

// The help of --limits, which sets both limits rows in its own J<n>=MIN:MAX form: the rows'
// labels and defaults in that form.
std::string LimitsFlagHelp();

class PlannerFlags {
 public:
  // `live`: the help texts describe the causal planner of `mimic` (docs/live.md).
  PlannerFlags(robot::PlannerOptions* options, bool live) : o_(options), live_(live) {}

  // --map-j1..3, --hold, --mirror, then `more` (plan's --source), then --j2-source, --j3-source.
  void RegisterMapping(ArgParser& p, const std::function<void()>& more = {});
  // --cutoff, --max-gap-s, then `more` (plan's --gap), then --max-jump, --deadband,
  // --min-interval, --max-interval: each from its row of the planner's table (flag, unit as
  // the metavar, help and default; mimic's causal planner words the help its own way).
  void RegisterFilter(ArgParser& p, const std::function<void()>& more = {});
  // --limits, --speed-limit, --clamp.
  void RegisterLimits(ArgParser& p);

  // After Parse: the text of --limits. Exit code of a usage error, naming the flag.
  std::optional<int> ParseTexts(const ArgParser& p);
  // Sets the mapping for `kind` (its defaults, then the flags given) and checks every option.
  std::optional<int> Finish(const ArgParser& p, robot::SourceKind kind, bool follow_file_kind);

 private:
  // Registers the flag of the planner table's number row `key`; `live_help` replaces the row's
  // help for the causal planner.
  void NumberFlag(ArgParser& p, const char* key, const char* live_help);

  robot::PlannerOptions* o_;
  bool live_;
  robot::MappingOptions given_mapping_;  // the mapping flags' values; Finish applies those given
  std::string limits_text_;
};

}  // namespace armmimic::cli
