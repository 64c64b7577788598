// The engines' parameter tables (armmimic/core/option_table.h): one table per engine options
// struct, defined in the engine's folder (src/engines/ENGINE/option_table.cpp); a new option is
// one row there. Here too: "ENGINE.KEY=VALUE" assignments (--param, the GUI's saved settings)
// and the values a file header records.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "armmimic/core/option_table.h"
#include "armmimic/core/status.h"
#include "armmimic/engines/bgsub_options.h"
#include "armmimic/engines/engine_options.h"
#include "armmimic/engines/hybrid_options.h"
#include "armmimic/engines/lk_options.h"
#include "armmimic/engines/marker_options.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic {

const std::vector<OptionField<BgsubOptions>>& BgsubOptionFields();
const std::vector<OptionField<LkOptions>>& LkOptionFields();
const std::vector<OptionField<MarkerOptions>>& MarkerOptionFields();
const std::vector<OptionField<PoseOptions>>& PoseOptionFields();
const std::vector<OptionField<HybridOptions>>& HybridOptionFields();

// Sets one field of `o` from "ENGINE.KEY=VALUE" ("lk.max_corners=200", the name the GUI's
// editors carry). Ints take whole numbers, bools true/false/on/off/1/0, enums a choice name;
// the value must lie in the field's range. Messages name the key and say what it accepts.
Status SetEngineOption(const std::string& assignment, EngineOptions* o);

// The parameters of `o`'s engine that differ from their defaults, as ("ENGINE.KEY", "VALUE")
// pairs that SetEngineOption reads back exactly (the angle file's header records them).
std::vector<std::pair<std::string, std::string>> ChangedEngineOptions(const EngineOptions& o);

// Every parameter of `o`'s engine, changed or not, in table order, the same way: the angle
// file's header records them all, so `analyze --params-from` repeats a run exactly even if a
// default changes later.
std::vector<std::pair<std::string, std::string>> EngineOptionValues(const EngineOptions& o);

// Every ENGINE.KEY=DEFAULT, one engine per paragraph, wrapped to `width` columns.
std::string DescribeEngineOptions(int width = 78);

}  // namespace armmimic
