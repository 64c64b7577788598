// OptionField: one engine parameter described for editors (the GUI's parameter forms and its
// saved settings): key, label, help, kind, range, documented default and how to read and write
// it in its options struct. One table per options struct; a new option is one line in
// src/engines/common/option_fields.cpp.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "armmimic/core/status.h"
#include "armmimic/engines/bgsub_options.h"
#include "armmimic/engines/engine_options.h"
#include "armmimic/engines/lk_options.h"
#include "armmimic/engines/marker_options.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic {

enum class OptionKind { kInt, kDouble, kBool, kEnum };

// kMain: shown with the engine; kAdvanced: in the engine's "Advanced" section; kInput: set from
// the analysis inputs (e.g. --background-frames), so not edited as an engine parameter.
enum class OptionGroup { kMain, kAdvanced, kInput };

template <typename Options>
struct OptionField {
  std::string key;    // the struct member's name ("max_corners"): settings key, widget name
  std::string label;  // short, for a form row
  std::string help;   // one line, in the library's words (the shells add a flag or field)
  OptionKind kind = OptionKind::kDouble;
  OptionGroup group = OptionGroup::kAdvanced;
  double min = 0;  // inclusive; bool 0..1; enum 0..choices-1
  double max = 0;
  double default_value = 0;  // the documented (thesis) default
  int decimals = 0;          // kDouble: digits shown
  double step = 1;           // editor step (2 for odd-only windows)
  // Relations Check() enforces between two fields: this one must be <= (or <) field `below`.
  std::string below;
  bool strictly_below = false;
  std::vector<std::string> choices;  // kEnum: value names in enum order (value = index)
  // Values cross as double: ints are rounded, bools are 0/1, enums are the choice index.
  std::function<double(const Options&)> get;
  std::function<void(Options&, double)> set;
};

const std::vector<OptionField<BgsubOptions>>& BgsubOptionFields();
const std::vector<OptionField<LkOptions>>& LkOptionFields();
const std::vector<OptionField<MarkerOptions>>& MarkerOptionFields();
const std::vector<OptionField<PoseOptions>>& PoseOptionFields();

// The field named `key` in `fields`, or nullptr.
template <typename Options>
const OptionField<Options>* FindOptionField(const std::vector<OptionField<Options>>& fields,
                                            const std::string& key) {
  for (const auto& f : fields) {
    if (f.key == key) return &f;
  }
  return nullptr;
}

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
