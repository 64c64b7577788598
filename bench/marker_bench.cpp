// Marker engine speed per image at 320x240 after decoding (target: >= 1000 images/s), on
// rendered views with and without clutter. Run: build/bench/marker_bench
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "armmimic/engines/engine.h"
#include "armmimic/synth/marker_scene.h"

namespace {

using namespace armmimic;

void MarkerProcess(benchmark::State& state, const char* lighting, int clutter, bool thesis) {
  synth::MarkerSceneOptions o;
  o.seed = 21;
  o.views = 16;
  o.max_yaw_deg = 30;
  o.lighting = lighting;
  o.clutter = clutter;
  const synth::MarkerSceneRenderer scene(o);
  std::vector<Frame> frames(o.views);
  for (int i = 0; i < o.views; ++i) {
    frames[i].image = scene.Render(i);
    frames[i].index = i;
  }
  EngineOptions options;
  options.kind = EngineKind::kMarker;
  options.marker.thesis_mode = thesis;
  const std::unique_ptr<Engine> engine = Engine::Create(options);
  EngineContext context;
  context.reference = scene.Reference();
  if (!engine->Begin(context).ok()) {
    state.SkipWithError("the reference has no markers");
    return;
  }
  std::size_t i = 0;
  int ok = 0;
  for (auto _ : state) {
    const ArmMeasurement m = engine->Process(frames[i++ % frames.size()]);
    ok += m.phase == MeasurementPhase::kOk;
    benchmark::DoNotOptimize(m.yaw_deg);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["images_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["ok_share"] = static_cast<double>(ok) / std::max<int64_t>(1, state.iterations());
}

BENCHMARK_CAPTURE(MarkerProcess, normal_320x240, "normal", 0, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(MarkerProcess, clutter6_320x240, "normal", 6, false)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(MarkerProcess, dim_320x240, "dim", 0, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(MarkerProcess, thesis_normal_320x240, "normal", 0, true)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
