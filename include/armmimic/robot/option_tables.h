// The robot layer's option tables (armmimic/core/option_table.h): the planner ("planner.*"),
// the joint mapping ("mapping.*"), the joint limits ("limits.*"), the link's timing ("link.*"),
// what a send reads besides the program ("send.*": the profile file and the timeouts), the live
// stream's own setting ("live.*") and the two profile settings `plan` can override
// ("profile.*": the mode and the program name). The structs' Check() uses them, the CLI
// registers its flags from their rows, and a planned program's header records every planner,
// mapping and limits value (OptionTableValues) so that it can be read back.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "armmimic/core/option_table.h"
#include "armmimic/robot/limits.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/robot/live_stream.h"
#include "armmimic/robot/mapping.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/send_setup.h"

namespace armmimic::robot {

const std::vector<OptionField<PlannerOptions>>& PlannerOptionFields();
const std::vector<OptionField<MappingOptions>>& MappingOptionFields();
const std::vector<OptionField<JointLimits>>& LimitsOptionFields();
const std::vector<OptionField<LinkSettings>>& LinkOptionFields();
const std::vector<OptionField<SendSettings>>& SendOptionFields();
const std::vector<OptionField<LiveStreamOptions>>& LiveStreamOptionFields();
// Which engine a plan's angles come from (`source.kind`: auto, arm or marker), kept apart from
// the mapping's table because only `plan` chooses it: mimic knows its own engine.
const std::vector<OptionField<MappingOptions>>& SourceOptionFields();
// Only the profile's settings a shell sets besides the profile file (the mode and the program
// name); the file's other keys are the profile's own format (docs/profiles/default.profile).
const std::vector<OptionField<ControllerProfile>>& ProfileOptionFields();

// Every value of `o` in table order as ("TABLE.KEY", "VALUE") pairs that SetOptionText reads
// back exactly.
template <typename O>
std::vector<std::pair<std::string, std::string>> OptionTableValues(
    const std::vector<OptionField<O>>& fields, const std::string& table, const O& o) {
  std::vector<std::pair<std::string, std::string>> out;
  out.reserve(fields.size());
  for (const auto& f : fields) out.emplace_back(table + "." + f.key, OptionExactText(f, o));
  return out;
}

// The planner's settings (its own, the mapping's and the limits') as one header line:
// "settings planner.cutoff_hz=3 ... mapping.j1=+1,0 ... limits.max_speed_deg_s=45,...".
std::string DescribePlannerSettings(const PlannerOptions& o);
// Reads "TABLE.KEY=VALUE" (a planner, mapping or limits key) into `o`; the error names the key.
Status SetPlannerSetting(const std::string& assignment, PlannerOptions* o);

}  // namespace armmimic::robot
