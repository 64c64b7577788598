// The run an angle file records: its header names the engine, every engine setting under the
// ENGINE.KEY name `analyze --param` takes, and the analysis inputs besides the video (background,
// arm-length and reference images, model folder, start frame, clicked joints, region of
// interest). Reading the header back gives the options of the same run
// (`analyze --params-from OLD.tsv`), from any folder: a path typed relative is recorded absolute
// as well (KEY_abs), and looked for there, beside OLD.tsv and in the current folder.
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/engines/analysis.h"

namespace armmimic {

// The recorded inputs (each only when used: background, background_frames, arm_length,
// reference, shoulder, elbow, wrist, model_dir, auto_calibrate, calibrate_side, roi; each path
// typed relative followed by its absolute form as KEY_abs) followed by every ENGINE.KEY=VALUE
// of the engine.
AngleMeta RunRecordMeta(const AnalysisOptions& options);

// Reads a recorded run from `meta` into `options`: the engine, each ENGINE.KEY setting over the
// defaults (a file written before every setting was recorded lists only the changed ones), start
// and the recorded inputs, with their paths as typed. options->inputs is left as it is. Messages
// begin with `source_name` and name the key. Settings this version removed (removed_options.h)
// are skipped: their keys go to `ignored` (when given) for the caller to report once.
Status RunFromMeta(const AngleMeta& meta, const std::string& source_name, AnalysisOptions* options,
                   std::vector<std::string>* ignored = nullptr);

// Refuses a header that names a key twice, or a key no version of armmimic wrote (an ENGINE.KEY
// that is neither a setting of the recorded engine nor a removed one, or a plain key that is
// neither an input nor a result of the run): "SOURCE:LINE: ..." with `line` the header's line.
Status CheckRunRecordKeys(const AngleMeta& meta, const std::string& source_name, int line);

// A path the recorded run names that was found nowhere.
struct MissingRecordedPath {
  std::string key;                 // "background", "arm_length", "reference" or "model_dir"
  std::string typed;               // the path as the header records it (the option holds it)
  std::vector<std::string> tried;  // every place looked, absolute, in the order tried
};

// What ReadRunRecord noticed besides the options.
struct RunRecordNotes {
  std::vector<std::string> ignored;          // removed settings the header records
  std::vector<MissingRecordedPath> missing;  // recorded paths found nowhere
  bool bad_keys = false;  // the refusal is CheckRunRecordKeys's (a duplicate or unknown key)
};

// RunFromMeta on the header of the angle file at `path`, after CheckRunRecordKeys. Each recorded
// path is looked for, in this order: as recorded when absolute; else where it was when the run
// was made (KEY_abs), beside `path` (a relative path taken from the angle file's folder), and
// in the current folder. The first that exists goes into `options`; when none does, the typed
// path stays and the places tried go to notes->missing (see CheckRecordedPathsFound).
Status ReadRunRecord(const std::string& path, AnalysisOptions* options,
                     RunRecordNotes* notes = nullptr);

// The error for the first of `missing` that `options` still uses (a flag given over the
// recorded run may have replaced it), naming `source_name`, the key and every place tried; Ok
// when none is used.
Status CheckRecordedPathsFound(const AnalysisOptions& options,
                               const std::vector<MissingRecordedPath>& missing,
                               const std::string& source_name);

}  // namespace armmimic
