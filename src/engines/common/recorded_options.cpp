#include "armmimic/engines/recorded_options.h"

#include <cstdlib>

#include "armmimic/engines/option_fields.h"
#include "armmimic/engines/removed_options.h"

namespace armmimic {

Status RecordedAnalysisOptions(const AngleFile& file, const std::string& source_name,
                               AnalysisOptions* options, std::vector<std::string>* skipped) {
  AnalysisOptions o;
  const std::string engine = file.Meta("engine");
  if (!ParseEngineKind(engine, &o.engine.kind)) {
    return Status::Error(source_name + ": the header names no engine this version knows (" +
                         (engine.empty() ? std::string("none") : "'" + engine + "'") + ")");
  }
  const std::string start = file.Meta("start");
  if (!start.empty()) {
    char* end = nullptr;
    const long v = std::strtol(start.c_str(), &end, 10);
    if (end && *end == '\0' && v >= 0 && v <= 1000000000) {
      o.start = static_cast<int>(v);
    } else if (skipped) {
      skipped->push_back("start=" + start + ": not a frame number");
    }
  }
  std::vector<std::string> removed;
  for (const auto& [key, value] : file.meta) {
    // Only ENGINE.KEY entries are parameters; "threshold=45" and the like describe the run.
    const auto dot = key.find('.');
    if (dot == std::string::npos || dot == 0) continue;
    if (FindRemovedEngineOption(key)) {
      removed.push_back(key);
      continue;
    }
    const Status st = SetEngineOption(key + "=" + value, &o.engine);
    if (!st && skipped) skipped->push_back(st.message());
  }
  // The settings this version removed, in one entry.
  if (!removed.empty() && skipped) skipped->push_back(DescribeIgnoredEngineOptions(removed));
  *options = o;
  return Status::Ok();
}

}  // namespace armmimic
