// Planner and VAL text timings: a long recording must plan in well under a second.
#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>

#include "armmimic/core/angles.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/stream_planner.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::robot {
namespace {

AngleFile Recording(int rows) {
  AngleFile f;
  f.meta = {{"engine", "bgsub"}, {"fps", "30"}};
  for (int i = 0; i < rows; ++i) {
    const double t = i / 30.0;
    AngleRow r;
    r.frame = i;
    r.time_s = t;
    r.status = i % 97 == 3 ? RowStatus::kLost : RowStatus::kOk;
    if (r.ok()) {
      r.upper_deg = Wrap180(-90 + 70 * (1 - std::cos(2 * kPi * 0.05 * t)));
      r.bend_deg = 60 * (1 - std::cos(2 * kPi * 0.07 * t));
      r.fore_deg = Wrap180(r.upper_deg + r.bend_deg);
      r.yaw_deg = 10;
    }
    f.rows.push_back(r);
  }
  return f;
}

// Rows of a 30 fps recording: 1800 = one minute.
void BM_PlanTrajectory(benchmark::State& state) {
  const AngleFile f = Recording(static_cast<int>(state.range(0)));
  PlannerOptions o;
  for (auto _ : state) {
    Trajectory tr;
    PlanReport rep;
    const Status s = PlanTrajectory(f, o, &tr, &rep);
    benchmark::DoNotOptimize(tr.keyframes.data());
    if (!s.ok()) state.SkipWithError(s.message().c_str());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_PlanTrajectory)->Arg(1800)->Arg(18000)->Unit(benchmark::kMillisecond);

void BM_FormatAndCheckValProgram(benchmark::State& state) {
  const AngleFile f = Recording(18000);
  Trajectory tr;
  PlanReport rep;
  if (!PlanTrajectory(f, PlannerOptions(), &tr, &rep).ok()) state.SkipWithError("plan failed");
  const ControllerProfile profile;
  for (auto _ : state) {
    std::string text;
    (void)FormatValProgram(tr, profile, JointLimits(), {"source=bench"}, &text);
    SafetyState safety = SafetyState::For(JointLimits(), profile);
    std::istringstream in(text);
    ValProgram program;
    (void)ParseValProgram(in, "bench.val", 80, &program);
    benchmark::DoNotOptimize(CheckProgram(program, safety).ok());
  }
  state.counters["keyframes"] = static_cast<double>(tr.keyframes.size());
}
BENCHMARK(BM_FormatAndCheckValProgram)->Unit(benchmark::kMillisecond);

// Live mimicking's planning per frame (docs/live.md's "planning" stage): one row pushed, then
// the command decision and its line, as the live stream does for every analysed frame.
void BM_StreamPlannerPerFrame(benchmark::State& state) {
  const AngleFile f = Recording(1800);
  StreamPlanner p;
  if (!p.Begin(PlannerOptions(), SourceKind::kArm, 30).ok()) state.SkipWithError("begin failed");
  const ControllerProfile profile;
  std::size_t i = 0;
  double now = 0;
  for (auto _ : state) {
    const AngleRow& r = f.rows[i++ % f.rows.size()];
    now += 1 / 30.0;
    p.Push(r, now);
    StreamCommand c;
    if (p.Next(now, &c)) {
      benchmark::DoNotOptimize(FormatMoveLine(c.joint_deg, profile));
      p.Sent(c);
    }
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StreamPlannerPerFrame);

}  // namespace
}  // namespace armmimic::robot

BENCHMARK_MAIN();
