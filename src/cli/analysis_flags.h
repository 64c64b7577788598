// AnalysisFlags: the engine and calibration flags `analyze` and `mimic` share (--engine,
// --background, --shoulder, ..., --param), parsed into one AnalysisOptions with the same checks
// and the same messages, so both commands analyse a video the same way.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <opencv2/core/types.hpp>

#include "args.h"
#include "armmimic/engines/analysis.h"

namespace armmimic::cli {

class AnalysisFlags {
 public:
  explicit AnalysisFlags(AnalysisOptions* options)
      : o_(options), threshold_(options->engine.bgsub.threshold) {}

  // Adds --engine and every engine flag to `p` (not the inputs or -o).
  void Register(ArgParser& p);
  // After Parse: the engine given and known. Returns the exit code of a usage error.
  std::optional<int> CheckEngine(const ArgParser& p) const;
  // Then: every flag fits the engine, and the options are filled in and checked.
  std::optional<int> Finish(const ArgParser& p);
  const std::string& engine_name() const { return engine_name_; }

  // The --param keys with their defaults, indented, for a help text.
  static std::string ParamList();
  // The flags each engine uses; any other engine flag given is a usage error.
  static const std::map<std::string, std::set<EngineKind>>& EngineFlags();

 private:
  AnalysisOptions* o_;
  std::vector<std::string> params_;
  std::string engine_name_;
  int standstill_ = 60;
  int threshold_;
  bool thesis_ = false;
  cv::Point2d shoulder_, elbow_, wrist_;
  cv::Rect roi_;
  std::string side_name_;
};

}  // namespace armmimic::cli
