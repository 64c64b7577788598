// Marker engine speed per image at 320x240 after decoding (target: >= 1000 images/s on one
// core), on ray-cast views with yaw over +-110 degrees (both lower markers readable, or one)
// with and without dark clutter, the thesis' acos path, and for scale the PNG decoding of the
// same views, and views of the second renderer's rigs (medium and hard sets, yaw +-60). Run:
// taskset -c 0 build/bench/marker_bench
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/imgcodecs.hpp>

#include "armmimic/engines/engine.h"
#include "armmimic/synth/marker_rig.h"
#include "armmimic/synth/marker_scene.h"

namespace {

using namespace armmimic;

synth::MarkerSceneOptions Scene(const char* lighting, int clutter) {
  synth::MarkerSceneOptions o;
  o.seed = 21;
  o.views = 16;
  o.max_yaw_deg = 110;
  o.lighting = lighting;
  o.clutter = clutter;
  return o;
}

// The timed loop: one view after another, round the set; counts the ok views.
void RunViews(benchmark::State& state, Engine& engine, const std::vector<Frame>& frames) {
  std::size_t i = 0;
  int ok = 0;
  for (auto _ : state) {
    const ArmMeasurement m = engine.Process(frames[i++ % frames.size()]);
    ok += m.phase == MeasurementPhase::kOk;
    benchmark::DoNotOptimize(m.yaw_deg);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["images_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["ok_share"] = static_cast<double>(ok) / std::max<int64_t>(1, state.iterations());
}

void MarkerProcess(benchmark::State& state, const char* lighting, int clutter, bool thesis) {
  const synth::MarkerSceneOptions o = Scene(lighting, clutter);
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
  RunViews(state, *engine, frames);
}

// Views of the rig renderer (`synth marker --renderer rig`), told the rig's lens.
void MarkerProcessRig(benchmark::State& state, const char* set, uint64_t seed) {
  synth::MarkerRigOptions o;
  o.set = set;
  o.seed = seed;
  o.views = 16;
  const synth::MarkerRigRenderer rig(o);
  std::vector<Frame> frames(o.views);
  for (int i = 0; i < o.views; ++i) {
    frames[i].image = rig.Render(i);
    frames[i].index = i;
  }
  EngineOptions options;
  options.kind = EngineKind::kMarker;
  options.marker.fov_deg = rig.rig().fov_deg;
  const std::unique_ptr<Engine> engine = Engine::Create(options);
  EngineContext context;
  context.reference = rig.Reference();
  if (!engine->Begin(context).ok()) {
    state.SkipWithError("the rig's reference does not calibrate");
    return;
  }
  RunViews(state, *engine, frames);
}

// Decoding the same views from PNG, as `analyze` reads a folder of images.
void DecodePng(benchmark::State& state) {
  const synth::MarkerSceneOptions o = Scene("normal", 0);
  const synth::MarkerSceneRenderer scene(o);
  std::vector<std::vector<uchar>> files(o.views);
  for (int i = 0; i < o.views; ++i) cv::imencode(".png", scene.Render(i), files[i]);
  std::size_t i = 0;
  for (auto _ : state) {
    const cv::Mat image = cv::imdecode(files[i++ % files.size()], cv::IMREAD_COLOR);
    benchmark::DoNotOptimize(image.data);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["images_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(MarkerProcess, normal_320x240, "normal", 0, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(MarkerProcess, clutter8_320x240, "normal", 8, false)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(MarkerProcess, side_320x240, "side", 0, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(MarkerProcess, thesis_normal_320x240, "normal", 0, true)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(MarkerProcessRig, rig_medium_320x240, "medium", 501)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(MarkerProcessRig, rig_hard_320x240, "hard", 601)->Unit(benchmark::kMicrosecond);
// A camera tilted 6.4 degrees: every view is levelled before the model sees it.
BENCHMARK_CAPTURE(MarkerProcessRig, rig_medium_tilted_320x240, "medium", 503)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(DecodePng)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
