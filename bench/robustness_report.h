// The robustness benchmark's outputs: the per-scene TSV, the summary table per engine, mode and
// tier, and the breakdown by scene feature (docs/accuracy.md explains every column).
#pragma once

#include <string>
#include <vector>

#include "robustness_run.h"

namespace armmimic::bench {

// One row per scene and run: seed, tier, engine, mode, coverage, errors, then every knob.
std::string SceneTsv(const std::vector<SceneResult>& scenes, const std::vector<RunSpec>& specs);

// One row per motion frame of every scene and run: seed, tier, engine, mode, frame, status,
// confidence, the two direction errors and the engine's note (what a frame's figures came from).
std::string FrameTsv(const std::vector<SceneResult>& scenes, const std::vector<RunSpec>& specs);

// Markdown: per run spec and tier (and all tiers together) the per-scene error distribution,
// coverage, the worst scene's coverage, the confidently wrong rate and the zero-coverage scenes.
std::string SummaryTable(const std::vector<SceneResult>& scenes, const std::vector<RunSpec>& specs,
                         const std::vector<synth::SceneTier>& tiers);

// Markdown: per scene feature (short sleeves, camouflage, hand above the head, ...) and run spec
// the pooled coverage, the confidently wrong rate, the median scene error and the scenes.
std::string FeatureTable(const std::vector<SceneResult>& scenes, const std::vector<RunSpec>& specs);

}  // namespace armmimic::bench
