#include "bench_scene.h"

#include <cstdlib>
#include <memory>

#include <unistd.h>

#include "armmimic/core/video_source.h"

namespace armmimic::bench {
namespace {

char g_dir[] = "/tmp/armmimic-bench-XXXXXX";

void RemoveSceneDir() {
  const std::string cmd = std::string("rm -rf ") + g_dir;
  if (std::system(cmd.c_str()) != 0) return;
}

}  // namespace

const std::string& SceneDir(const synth::ArmSceneOptions& options) {
  static const std::string dir = [&options] {
    if (!mkdtemp(g_dir)) std::abort();
    std::atexit(RemoveSceneDir);
    if (!synth::WriteArmScene(options, g_dir, {}).ok()) std::abort();
    return std::string(g_dir);
  }();
  return dir;
}

void DecodeOnly(benchmark::State& state, const std::string& video) {
  int64_t frames = 0;
  for (auto _ : state) {
    Status st;
    auto source = VideoSource::Open(video, &st);
    if (!source) {
      state.SkipWithError(st.message().c_str());
      return;
    }
    Frame f;
    while (source->Read(&f, &st)) ++frames;
    benchmark::DoNotOptimize(f.image.data);
  }
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
}

void AnalyzeFile(benchmark::State& state, const AnalysisOptions& options) {
  int64_t frames = 0;
  for (auto _ : state) {
    AnalysisSummary summary;
    const Status st = RunAnalysis(options, {}, &summary);
    if (!st.ok()) {
      state.SkipWithError(st.message().c_str());
      return;
    }
    frames += summary.last_frame + 1 - options.start;  // the frames read, from --start on
  }
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
}

}  // namespace armmimic::bench
