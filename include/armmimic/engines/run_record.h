// The run an angle file records: its header names the engine, every engine setting under the
// ENGINE.KEY name `analyze --param` takes, and the analysis inputs besides the video (background,
// arm-length and reference images, start frame, clicked joints, region of interest). Reading
// the header back gives the options of the same run (`analyze --params-from OLD.tsv`).
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/engines/analysis.h"

namespace armmimic {

// The recorded inputs (each only when used: background, background_frames, arm_length,
// reference, shoulder, elbow, wrist, model, auto_calibrate, calibrate_side, roi) followed by
// every ENGINE.KEY=VALUE of the engine.
AngleMeta RunRecordMeta(const AnalysisOptions& options);

// Reads a recorded run from `meta` into `options`: the engine, each ENGINE.KEY setting over the
// defaults (a file written before every setting was recorded lists only the changed ones), start
// and the recorded inputs. options->inputs is left as it is. Messages begin with `source_name`
// and name the key. Settings this version removed (removed_options.h) are skipped: their keys
// go to `ignored` (when given) for the caller to report once.
Status RunFromMeta(const AngleMeta& meta, const std::string& source_name, AnalysisOptions* options,
                   std::vector<std::string>* ignored = nullptr);

// RunFromMeta on the header of the angle file at `path`.
Status ReadRunRecord(const std::string& path, AnalysisOptions* options,
                     std::vector<std::string>* ignored = nullptr);

}  // namespace armmimic
