// Recorded options: the analysis settings an angle file's header records, read back. The header
// names the engine, the start frame and every engine parameter changed from its default as
// ENGINE.KEY=VALUE (see ChangedEngineOptions); read back over the defaults they give the options
// the file was made with. Input images (background, arm-length, reference) are not recorded.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/engines/analysis.h"

namespace armmimic {

// Fills `options` (engine, start, parameters; inputs left empty) from `file`'s header. A header
// without a known engine is an error naming `source_name`. An ENGINE.KEY entry this version
// does not know, or whose value it refuses, is skipped and described in `skipped`; the settings
// this version removed (removed_options.h) are skipped and described together in one entry.
Status RecordedAnalysisOptions(const AngleFile& file, const std::string& source_name,
                               AnalysisOptions* options, std::vector<std::string>* skipped);

}  // namespace armmimic
