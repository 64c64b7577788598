// Shared by the benchmarks that time whole files: an arm scene written to a temporary folder
// once per run (removed at exit), the decode-only rate of a video (the ceiling for any engine
// reading it) and the end-to-end analysis rate.
#pragma once

#include <string>

#include <benchmark/benchmark.h>

#include "armmimic/engines/analysis.h"
#include "armmimic/synth/arm_scene.h"

namespace armmimic::bench {

// Writes `options` as a scene into a new folder under $TMPDIR (or /tmp) the first time it is called
// (later calls return the same folder, whatever their options); aborts if the scene cannot be
// written.
const std::string& SceneDir(const synth::ArmSceneOptions& options);

// Reads every frame of `video` per iteration; counter "frames/s" per CPU second.
void DecodeOnly(benchmark::State& state, const std::string& video);

// Runs the whole analysis (what `armmimic-cli analyze` does minus the file write) per
// iteration; counter "frames/s": frames read (from options.start on) per CPU second.
void AnalyzeFile(benchmark::State& state, const AnalysisOptions& options);

}  // namespace armmimic::bench
