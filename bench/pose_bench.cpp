// Speed of the pose engine at 320x240 (issue target, reported, not asserted: >= 25 frames/s end
// to end on one core; run it under `taskset -c 0`). Needs the model (scripts/deps.sh
// --with-model). Rates are per CPU second. Run: build/bench/pose_bench
//   BM_PoseNetwork         one inference (192x192 input) plus the decoder;
//   BM_PoseAnalyzeEndToEnd what `analyze --engine pose --side left` does minus the file write:
//                          model load and checks, decoding, crop tracking, every frame a row;
//                          /1: one look a frame (pose.arm_crop=0), /2: the body and arm looks
//                          (the default), /3: with the mirrored look too (pose.flip=true).
//   BM_BlazePoseAnalyzeEndToEnd  the same with --network blazepose (one BlazePose inference a
//                          frame in its tracked crop; the first frame seeds it from MoveNet).
//   BM_PoseArmsEndToEnd    --side left (/1) against --side both (/2), both arms from the same
//                          inferences; network/0 MoveNet, network/1 BlazePose (docs/pose.md,
//                          "Both arms": at most 1.2 times one arm).
#include <string>

#include <benchmark/benchmark.h>

#include "armmimic/engines/analysis.h"
#include "armmimic/engines/pose.h"
#include "armmimic/synth/arm_scene.h"
#include "bench_scene.h"

namespace {

using namespace armmimic;

synth::ArmSceneOptions SceneOptions() {
  synth::ArmSceneOptions so;
  so.seed = 1;
  so.motion_frames = 150;
  return so;
}

void BM_PoseNetwork(benchmark::State& state) {
  Status st;
  std::unique_ptr<PoseNetwork> net = PoseNetwork::Load("", &st);
  if (!net) {
    state.SkipWithError(st.message().c_str());
    return;
  }
  synth::ArmSceneRenderer renderer(SceneOptions());
  const cv::Mat input = PoseNetwork::MakeInput(renderer.Render(150), WholeImageCrop({320, 240}));
  for (auto _ : state) benchmark::DoNotOptimize(net->RunInput(input));
  state.counters["inferences/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PoseNetwork)->Unit(benchmark::kMillisecond);

void BM_PoseAnalyzeEndToEnd(benchmark::State& state) {
  const synth::ArmSceneOptions so = SceneOptions();
  AnalysisOptions o;
  o.inputs = {bench::SceneDir(so) + "/scene.avi"};
  o.engine.kind = EngineKind::kPose;
  o.engine.pose.side = PoseSide::kLeft;
  o.start = so.first_motion_frame();
  o.engine.pose.arm_crop = state.range(0) >= 2 ? PoseOptions().arm_crop : 0;
  o.engine.pose.flip = state.range(0) >= 3;
  bench::AnalyzeFile(state, o);
}
BENCHMARK(BM_PoseAnalyzeEndToEnd)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);

void BM_BlazePoseAnalyzeEndToEnd(benchmark::State& state) {
  const synth::ArmSceneOptions so = SceneOptions();
  AnalysisOptions o;
  o.inputs = {bench::SceneDir(so) + "/scene.avi"};
  o.engine.kind = EngineKind::kPose;
  o.engine.pose.network = PoseNetworkKind::kBlazePose;
  o.engine.pose.side = PoseSide::kLeft;
  o.start = so.first_motion_frame();
  bench::AnalyzeFile(state, o);
}
BENCHMARK(BM_BlazePoseAnalyzeEndToEnd)->Unit(benchmark::kMillisecond);

void BM_PoseArmsEndToEnd(benchmark::State& state) {
  const synth::ArmSceneOptions so = SceneOptions();
  AnalysisOptions o;
  o.inputs = {bench::SceneDir(so) + "/scene.avi"};
  o.engine.kind = EngineKind::kPose;
  o.engine.pose.network =
      state.range(0) == 1 ? PoseNetworkKind::kBlazePose : PoseNetworkKind::kMoveNet;
  o.engine.pose.side = state.range(1) == 2 ? PoseSide::kBoth : PoseSide::kLeft;
  o.start = so.first_motion_frame();
  bench::AnalyzeFile(state, o);
}
BENCHMARK(BM_PoseArmsEndToEnd)
    ->ArgNames({"network", "arms"})
    ->ArgsProduct({{0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
