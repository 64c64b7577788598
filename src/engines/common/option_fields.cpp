// What the engines' parameter tables (option_fields.h; one table per engine, in each engine's
// folder) are used for: "ENGINE.KEY=VALUE" assignments, the values a file header records, and
// the list of every key with its default.
#include "armmimic/engines/option_fields.h"

#include "armmimic/core/text.h"
#include "armmimic/engines/removed_options.h"

namespace armmimic {
namespace {

template <typename O>
Status SetField(const std::vector<OptionField<O>>& fields, const std::string& engine,
                const std::string& key, const std::string& text, O* o) {
  const OptionField<O>* f = FindOptionField(fields, key);
  if (!f) {
    std::string keys;
    for (const auto& g : fields) keys += (keys.empty() ? "" : ", ") + g.key;
    return Status::Error("'" + engine + "." + key + "' is no " + engine + " parameter (" + keys +
                         ")");
  }
  return SetOptionText(*f, engine + "." + key, text, o);
}

template <typename O>
void Describe(const std::vector<OptionField<O>>& fields, const std::string& engine, int width,
              std::string* out) {
  const O defaults;
  std::string line;
  for (const auto& f : fields) {
    const std::string item = engine + "." + f.key + "=" + OptionValueText(f, f.get(defaults));
    if (!line.empty() && static_cast<int>(line.size() + 1 + item.size()) > width) {
      *out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + item;
  }
  if (!line.empty()) *out += line + "\n";
}

// The exact text of each value (doubles in their shortest round-trip form), as
// SetEngineOption reads it back.
template <typename O>
void AppendValues(const std::vector<OptionField<O>>& fields, const std::string& engine, const O& o,
                  bool changed_only, std::vector<std::pair<std::string, std::string>>* out) {
  const O defaults;
  for (const auto& f : fields) {
    if (changed_only && f.get(o) == f.get(defaults)) continue;
    out->emplace_back(engine + "." + f.key, OptionExactText(f, o));
  }
}

std::vector<std::pair<std::string, std::string>> EngineValues(const EngineOptions& o,
                                                              bool changed_only) {
  std::vector<std::pair<std::string, std::string>> out;
  switch (o.kind) {
    case EngineKind::kBgsub:
      AppendValues(BgsubOptionFields(), "bgsub", o.bgsub, changed_only, &out);
      break;
    case EngineKind::kLk:
      AppendValues(LkOptionFields(), "lk", o.lk, changed_only, &out);
      break;
    case EngineKind::kMarker:
      AppendValues(MarkerOptionFields(), "marker", o.marker, changed_only, &out);
      break;
    case EngineKind::kPose:
      AppendValues(PoseOptionFields(), "pose", o.pose, changed_only, &out);
      break;
    case EngineKind::kHybrid:  // its own, then the two engines' it runs
      AppendValues(HybridOptionFields(), "hybrid", o.hybrid, changed_only, &out);
      AppendValues(LkOptionFields(), "lk", o.lk, changed_only, &out);
      AppendValues(BgsubOptionFields(), "bgsub", o.bgsub, changed_only, &out);
      break;
  }
  return out;
}

}  // namespace

Status SetEngineOption(const std::string& assignment, EngineOptions* o) {
  const auto eq = assignment.find('=');
  const auto dot = assignment.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq) {
    return Status::Error("'" + assignment +
                         "': expected ENGINE.KEY=VALUE, e.g. lk.max_corners=200");
  }
  const std::string engine = assignment.substr(0, dot);
  const std::string key = assignment.substr(dot + 1, eq - dot - 1);
  const std::string value = Trim(assignment.substr(eq + 1));
  if (const RemovedEngineOption* r = FindRemovedEngineOption(engine + "." + key)) {
    return RemovedEngineOptionError(*r);
  }
  if (engine == "bgsub") return SetField(BgsubOptionFields(), engine, key, value, &o->bgsub);
  if (engine == "lk") return SetField(LkOptionFields(), engine, key, value, &o->lk);
  if (engine == "marker") return SetField(MarkerOptionFields(), engine, key, value, &o->marker);
  if (engine == "pose") return SetField(PoseOptionFields(), engine, key, value, &o->pose);
  if (engine == "hybrid") return SetField(HybridOptionFields(), engine, key, value, &o->hybrid);
  return Status::Error("'" + assignment + "': unknown engine '" + engine +
                       "' (bgsub, lk, marker, pose or hybrid)");
}

std::vector<std::pair<std::string, std::string>> ChangedEngineOptions(const EngineOptions& o) {
  return EngineValues(o, true);
}

std::vector<std::pair<std::string, std::string>> EngineOptionValues(const EngineOptions& o) {
  return EngineValues(o, false);
}

std::string DescribeEngineOptions(int width) {
  std::string out;
  Describe(BgsubOptionFields(), "bgsub", width, &out);
  out += "\n";
  Describe(LkOptionFields(), "lk", width, &out);
  out += "\n";
  Describe(MarkerOptionFields(), "marker", width, &out);
  out += "\n";
  Describe(PoseOptionFields(), "pose", width, &out);
  out += "\n";
  Describe(HybridOptionFields(), "hybrid", width, &out);
  return out;
}

}  // namespace armmimic
