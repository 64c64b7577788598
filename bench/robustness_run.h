// The robustness benchmark's work on one scene: render it (through JPEG at the scene's
// quality, as a compressed video would deliver it), then run each engine in each calibration
// mode through the analysis pipeline and score the rows over the motion frames.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/engines/analysis.h"
#include "armmimic/synth/random_arm_scene.h"
#include "armmimic/synth/robustness_stats.h"

namespace armmimic::bench {

// What a calibration mode needs from the scene: the rendered scene and its arm-length image
// written as a file (the pipeline reads it like --arm-length).
struct SceneInputs {
  const synth::RandomArmScene* scene = nullptr;
  std::string arm_length_path;
};

// How an engine is told where the arm is. The table is the one place to add a mode; whether a
// mode applies to an engine is decided by the engine's own checks (AnalysisOptions::Check()).
struct CalibrationMode {
  std::string name;
  std::string help;
  std::function<Status(const SceneInputs&, EngineKind, AnalysisOptions*)> apply;
};
const std::vector<CalibrationMode>& CalibrationModes();

// One engine in one mode; `params` are ENGINE.KEY=VALUE settings applied first.
struct RunSpec {
  EngineKind engine = EngineKind::kBgsub;
  const CalibrationMode* mode = nullptr;
  std::vector<std::string> params;
  std::string Name() const;  // "bgsub/thesis"
};

// Builds the analysis options of `spec` for `inputs`; an error when the engine rejects them.
Status BuildOptions(const RunSpec& spec, const SceneInputs& inputs, AnalysisOptions* out);

// One motion frame of a run, for studying the frames behind the figures (OUT/frames.tsv).
struct FrameRecord {
  int frame = 0;
  bool ok = false;
  double confidence = kNaN;  // the row's confidence column (nan: not written)
  double err_upper = kNaN, err_fore = kNaN;
  std::string note;  // the engine's note for the frame
};

struct RunResult {
  synth::MotionScore score;
  std::vector<FrameRecord> frames;  // the motion frames, in order
  std::string error;                // the pipeline's error when it could not run (coverage 0)
  std::string lost_reason;          // the most frequent reason of the lost rows, digits as '#'
  double seconds = 0;               // wall time of the analysis
};

struct SceneResult {
  uint64_t seed = 0;
  synth::SceneTier tier = synth::SceneTier::kEasy;
  AngleMeta knobs;              // RandomSceneParams::Describe()
  std::vector<RunResult> runs;  // one per RunSpec, in order
  double render_seconds = 0;
};

// Renders the scene and runs every spec on it. `work_dir` holds the arm-length image while
// the scene runs. `max_frames` > 0 keeps only the scene's first frames (a quick probe).
SceneResult RunScene(const synth::RandomArmSceneOptions& options, const std::vector<RunSpec>& specs,
                     const std::string& work_dir, int max_frames = 0);

}  // namespace armmimic::bench
