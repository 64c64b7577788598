#include "bench_scene.h"

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include <unistd.h>

#include "armmimic/core/video_source.h"

namespace armmimic::bench {
namespace {

std::string g_dir;

void RemoveSceneDir() {
  std::error_code ec;
  std::filesystem::remove_all(g_dir, ec);
}

}  // namespace

const std::string& SceneDir(const synth::ArmSceneOptions& options) {
  static const std::string dir = [&options] {
    const char* base = std::getenv("TMPDIR");
    std::string templ = std::string(base && *base ? base : "/tmp") + "/armmimic-bench-XXXXXX";
    std::vector<char> buf(templ.begin(), templ.end());
    buf.push_back('\0');
    if (!mkdtemp(buf.data())) std::abort();
    g_dir = buf.data();
    std::atexit(RemoveSceneDir);
    if (!synth::WriteArmScene(options, g_dir, {}).ok()) std::abort();
    return g_dir;
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
