// AnalysisFlags: the one list of engine and calibration flags that `analyze` (one video or a
// batch) and `mimic` share (--engine, --background, --shoulder, ..., --param). The flag values
// are kept apart from the options they apply to, so `analyze --params-from` can lay only the
// flags given over a recorded run; both commands check and apply them the same way, with the
// same messages. An error about a setting names its flag through FlagForKey (flag_for_key.h).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "args.h"
#include "armmimic/engines/analysis.h"

namespace armmimic::cli {

class AnalysisFlags {
 public:
  // Adds --engine and every engine flag to `p` (not the inputs or -o). `both_arms`: --side
  // offers both (analyze); mimic, where one robot follows one arm, names left or right only in
  // its help (it refuses both with a message).
  void Register(ArgParser& p, bool both_arms = true);

  const std::string& engine_name() const { return engine_name_; }
  // The values of the flags (the inputs they name: --background, --model, ...).
  const AnalysisOptions& values() const { return f_; }

  // After Parse: the engine named by --engine into *kind (left alone when none was given);
  // the exit code of a usage error when the name is unknown.
  std::optional<int> ParseEngine(const ArgParser& p, EngineKind* kind) const;
  // --elbow with --initial-upper/--initial-fore: the usage error text, or "".
  std::string CheckStartingDirections(const ArgParser& p) const;
  // Every flag given fits `o`'s engine (and `o`'s own calibration, e.g. a recorded
  // --auto-calibrate): the usage error text, or "".
  std::string CheckFor(const ArgParser& p, const AnalysisOptions& o) const;
  // Lays the flags given over `o` (the defaults, or a recorded run), --param last.
  void ApplyGiven(const ArgParser& p, AnalysisOptions* o) const;
  // All of the above for options starting from the defaults (mimic): --engine required, then
  // the checks, the flags applied and o->Check(). The exit code of a usage error.
  std::optional<int> Finish(const ArgParser& p, AnalysisOptions* o) const;

  // The --param keys with their defaults, indented, for a help text.
  static std::string ParamList();
  // The flags each engine uses; any other engine flag given is a usage error.
  static const std::map<std::string, std::set<EngineKind>>& EngineFlags();

 private:
  AnalysisOptions f_;
  std::vector<std::string> params_;
  std::string engine_name_, side_name_;
  bool thesis_ = false;
};

}  // namespace armmimic::cli
