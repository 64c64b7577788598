// The angle plot with a long analysis: the window hands it every result again on its 40 ms
// redraw timer while an analysis runs, so one redraw (rebuilding the curves and painting them)
// must stay well under 40 ms. Rows of a
// five-minute video at 30 fps (9000 frames), one in ten lost in runs of one to five frames.
#include <cmath>
#include <memory>

#include <benchmark/benchmark.h>
#include <QApplication>

#include "angle_plot.h"
#include "result_store.h"

namespace {

armmimic::gui::ResultStore LongAnalysis(int frames) {
  armmimic::gui::ResultStore store;
  for (int f = 0; f < frames; ++f) {
    armmimic::ArmMeasurement m;
    m.frame = f;
    m.time_s = f / 30.0;
    const bool lost = (f % 97) < 1 + (f / 97) % 5 && f % 10 < 5;
    m.phase = lost ? armmimic::MeasurementPhase::kLost : armmimic::MeasurementPhase::kOk;
    m.upper_deg = -90 + 60 * std::sin(f / 40.0);
    m.fore_deg = -60 + 80 * std::sin(f / 25.0);
    m.yaw_deg = f % 300 < 150 ? 20 + 10 * std::sin(f / 30.0) : NAN;
    store.add(m);
  }
  return store;
}

// A plot the size of the Angles dock on a wide screen, over `frames` frames of 30 fps.
std::unique_ptr<armmimic::gui::AnglePlot> ShownPlot(int frames) {
  auto plot = std::make_unique<armmimic::gui::AnglePlot>();
  plot->setFrameRange(frames, 30);
  plot->resize(1400, 260);
  plot->show();
  return plot;
}

// What the window's redraw costs: the curves rebuilt from every result, then painted.
void BM_PlotRedraw(benchmark::State& state) {
  const int frames = static_cast<int>(state.range(0));
  const armmimic::gui::ResultStore store = LongAnalysis(frames);
  const auto plot = ShownPlot(frames);
  for (auto _ : state) {
    plot->setResults(store);
    benchmark::DoNotOptimize(plot->grab());  // the paint the redraw leads to, done now
  }
  state.SetItemsProcessed(state.iterations() * frames);
}
BENCHMARK(BM_PlotRedraw)
    ->Arg(900)
    ->Arg(9000)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

// Its two halves for 9000 frames: painting alone, and rebuilding the curves alone.
void BM_PlotPaintOnly(benchmark::State& state) {
  const auto plot = ShownPlot(9000);
  plot->setResults(LongAnalysis(9000));
  for (auto _ : state) benchmark::DoNotOptimize(plot->grab());
}
BENCHMARK(BM_PlotPaintOnly)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

void BM_PlotSetOnly(benchmark::State& state) {
  const armmimic::gui::ResultStore store = LongAnalysis(9000);
  const auto plot = ShownPlot(9000);
  for (auto _ : state) plot->setResults(store);
}
BENCHMARK(BM_PlotSetOnly)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

// The same plot with nothing to draw: what painting the axes, grid and legend costs alone.
void BM_PlotEmptyPaint(benchmark::State& state) {
  const auto plot = ShownPlot(9000);
  for (auto _ : state) benchmark::DoNotOptimize(plot->grab());
}
BENCHMARK(BM_PlotEmptyPaint)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
