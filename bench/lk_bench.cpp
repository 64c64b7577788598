// Per-frame time of the LK engine at 320x240 on a rendered scene (frames rendered beforehand, so
// only the engine is timed). Reported, not asserted: the target is >= 400 frames/s end to end.
#include <vector>

#include <benchmark/benchmark.h>

#include "armmimic/engines/engine.h"
#include "armmimic/synth/arm_scene.h"

namespace {

using namespace armmimic;

void BM_LkEngine(benchmark::State& state) {
  synth::ArmSceneOptions scene;
  scene.seed = 1;
  scene.motion = synth::ArmMotion::kMixed;
  scene.motion_frames = 200;
  synth::ArmSceneRenderer renderer(scene);
  std::vector<Frame> frames;
  for (int i = scene.first_motion_frame() - 1; i < renderer.frame_count(); ++i) {
    Frame f;
    f.image = renderer.Render(i);
    f.index = i;
    frames.push_back(f);
  }
  EngineOptions options;
  options.kind = EngineKind::kLk;
  options.lk.thesis_mode = state.range(0) != 0;
  int64_t processed = 0;
  for (auto _ : state) {
    std::unique_ptr<Engine> engine = Engine::Create(options);
    EngineContext context;
    context.frame_size = scene.size;
    context.shoulder_px = renderer.shoulder_px();
    if (!engine->Begin(context).ok()) state.SkipWithError("Begin failed");
    for (const Frame& f : frames) benchmark::DoNotOptimize(engine->Process(f));
    processed += static_cast<int64_t>(frames.size());
  }
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(processed), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LkEngine)->Arg(0)->Arg(1)->ArgName("thesis")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
