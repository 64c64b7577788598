// Arm scene rendering speed: engine accuracy tests render scenes in memory, so a frame must cost
// milliseconds (target: a 1000-frame scene in a few seconds). Reported, not asserted.
#include <benchmark/benchmark.h>

#include "armmimic/synth/arm_scene.h"

namespace {

using armmimic::synth::ArmSceneOptions;
using armmimic::synth::ArmSceneRenderer;

void BM_RenderArmFrame(benchmark::State& state) {
  ArmSceneOptions o;
  o.size = {static_cast<int>(state.range(0)), static_cast<int>(state.range(0)) * 3 / 4};
  o.shadow = state.range(1) != 0;
  o.head_motion = state.range(1) != 0;
  const ArmSceneRenderer scene(o);
  int f = o.first_motion_frame();
  for (auto _ : state) {
    benchmark::DoNotOptimize(scene.Render(f));
    if (++f == scene.frame_count()) f = o.first_motion_frame();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RenderArmFrame)
    ->Args({320, 0})
    ->Args({320, 1})
    ->Args({640, 0})
    ->Unit(benchmark::kMillisecond);

void BM_BuildArmScene(benchmark::State& state) {
  ArmSceneOptions o;
  for (auto _ : state) {
    ArmSceneRenderer scene(o);
    benchmark::DoNotOptimize(&scene);
  }
}
BENCHMARK(BM_BuildArmScene)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
