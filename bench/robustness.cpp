// robustness: every arm engine in every calibration mode over randomised scenes (docs/accuracy.md).
// Scenes are rendered in memory, compressed like a video, and analysed through the same pipeline
// as `armmimic-cli analyze`, on worker threads. scripts/robustness.sh builds and runs it.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include <sys/resource.h>

#include <opencv2/core/utility.hpp>

#include "armmimic/engines/option_fields.h"
#include "robustness_report.h"
#include "robustness_run.h"

namespace armmimic::bench {
namespace {

constexpr int kExitUsage = 2;

const char* const kUsage = R"(Usage: robustness [options]

Renders randomised arm scenes (synth arm --random) in memory, runs every arm engine in every
calibration mode that engine accepts, and scores the rows over each scene's motion frames.
Prints a table per engine, mode and tier; writes OUT/scenes.tsv (one row per scene and run,
with the scene's knobs), OUT/frames.tsv (one row per motion frame and run: status,
confidence, errors and the engine's note), OUT/table.md, OUT/features.md and OUT/summary.md.

  --set heldout|tuning|unit  the seed range: held-out (default; measure only), tuning, or the
                           unit tests' scenes (7000-7999, also open for tuning)
  --scenes-per-tier N      scenes of each tier (default 70 held-out, 20 tuning)
  --first-seed S           first seed (default: the set's first); seeds S..S+N-1 must lie in
                           the set's range, and every tier uses the same seed numbers
  --tiers LIST             easy,medium,hard (default all)
  --engines LIST           arm engines to run (default every arm engine)
  --modes LIST             calibration modes (default all: thesis, joints, auto, none)
  --param ENGINE.KEY=VAL   an engine setting, as analyze --param (repeatable)
  --size WxH               frame size (default 320x240)
  --threads N              worker threads (default 2)
  --out DIR                output folder (default robustness-out)
  --quiet                  no per-scene progress
)";

struct Args {
  std::string set = "heldout";
  int per_tier = -1;
  long long first_seed = -1;
  std::vector<synth::SceneTier> tiers = {synth::SceneTier::kEasy, synth::SceneTier::kMedium,
                                         synth::SceneTier::kHard};
  std::vector<EngineKind> engines;
  std::vector<std::string> modes;
  std::vector<std::string> params;
  cv::Size size{320, 240};
  int threads = 2;
  std::string out = "robustness-out";
  bool quiet = false;
};

std::vector<std::string> Split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

int Usage(const std::string& message) {
  std::cerr << "robustness: " << message << "\nTry 'robustness --help'.\n";
  return kExitUsage;
}

// The seeds must lie in the chosen set's range; fills the set's defaults.
int CheckRange(Args* a) {
  if (a->tiers.empty()) return Usage("--tiers: no tier given");
  const bool heldout = a->set == "heldout";
  const bool unit = a->set == "unit";
  const uint64_t lo = heldout ? synth::kHeldOutSeedFirst
                      : unit  ? synth::kUnitSeedFirst
                              : synth::kTuningSeedFirst;
  const uint64_t hi = heldout ? synth::kHeldOutSeedLast
                      : unit  ? synth::kUnitSeedLast
                              : synth::kTuningSeedLast;
  if (a->per_tier < 0) a->per_tier = heldout ? 70 : 20;
  if (a->first_seed < 0) a->first_seed = static_cast<long long>(lo);
  if (static_cast<uint64_t>(a->first_seed) < lo ||
      static_cast<uint64_t>(a->first_seed) + a->per_tier - 1 > hi) {
    return Usage("--first-seed/--scenes-per-tier: seeds " + std::to_string(a->first_seed) + ".." +
                 std::to_string(a->first_seed + a->per_tier - 1) + " leave the " + a->set +
                 " range " + std::to_string(lo) + ".." + std::to_string(hi));
  }
  synth::RandomArmSceneOptions probe;
  probe.size = a->size;
  if (const Status st = probe.Check(); !st) return Usage("--size: " + st.message());
  return -1;
}

// Parses the command line; returns -1 to go on, or the exit code.
int Parse(int argc, char** argv, Args* a) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "-h" || flag == "--help") {
      std::cout << kUsage;
      return 0;
    }
    if (flag == "--quiet") {
      a->quiet = true;
      continue;
    }
    if (i + 1 >= argc) return Usage(flag + " needs a value (or is unknown)");
    const std::string v = argv[++i];
    char* end = nullptr;
    if (flag == "--set") {
      if (v != "heldout" && v != "tuning" && v != "unit")
        return Usage("--set: '" + v + "' is not heldout, tuning or unit");
      a->set = v;
    } else if (flag == "--scenes-per-tier" || flag == "--threads") {
      const long n = std::strtol(v.c_str(), &end, 10);
      if (*end || n < 1 || n > 1000) return Usage(flag + ": '" + v + "' is not a number 1..1000");
      (flag == "--threads" ? a->threads : a->per_tier) = static_cast<int>(n);
    } else if (flag == "--first-seed") {
      a->first_seed = std::strtoll(v.c_str(), &end, 10);
      if (*end || a->first_seed < 0) return Usage("--first-seed: '" + v + "' is not a seed");
    } else if (flag == "--tiers") {
      a->tiers.clear();
      for (const std::string& t : Split(v)) {
        synth::SceneTier tier;
        if (!synth::ParseSceneTier(t, &tier)) return Usage("--tiers: '" + t + "' is not a tier");
        a->tiers.push_back(tier);
      }
    } else if (flag == "--engines") {
      for (const std::string& e : Split(v)) {
        EngineKind k;
        if (!ParseEngineKind(e, &k) || !IsArmEngine(k)) {
          return Usage("--engines: '" + e + "' is not an arm engine");
        }
        a->engines.push_back(k);
      }
    } else if (flag == "--modes") {
      for (const std::string& m : Split(v)) {
        bool known = false;
        for (const CalibrationMode& mode : CalibrationModes()) known |= mode.name == m;
        if (!known) return Usage("--modes: '" + m + "' is not a calibration mode");
        a->modes.push_back(m);
      }
    } else if (flag == "--param") {
      EngineOptions probe;
      const Status st = SetEngineOption(v, &probe);
      if (!st) return Usage("--param " + v + ": " + st.message());
      a->params.push_back(v);
    } else if (flag == "--size") {
      int w = 0, h = 0;
      if (std::sscanf(v.c_str(), "%dx%d", &w, &h) != 2)
        return Usage("--size: '" + v + "' is not WxH");
      a->size = {w, h};
    } else if (flag == "--out") {
      a->out = v;
    } else {
      return Usage("unknown option " + flag);
    }
  }
  return CheckRange(a);
}

// Every requested engine in every requested mode it accepts (its own checks decide).
std::vector<RunSpec> Plan(const Args& a, const synth::RandomArmSceneOptions& first,
                          const std::string& work_dir) {
  std::vector<EngineKind> engines = a.engines;
  if (engines.empty()) {
    for (EngineKind k : AllEngineKinds()) {
      if (IsArmEngine(k)) engines.push_back(k);
    }
  }
  const synth::RandomArmScene scene(first);
  const SceneInputs inputs{&scene, work_dir + "/probe.png"};
  std::vector<RunSpec> candidates;
  for (EngineKind k : engines) {
    for (const CalibrationMode& mode : CalibrationModes()) {
      if (!a.modes.empty() &&
          std::find(a.modes.begin(), a.modes.end(), mode.name) == a.modes.end()) {
        continue;
      }
      RunSpec spec{k, &mode, a.params};
      AnalysisOptions o;
      const Status st = BuildOptions(spec, inputs, &o);
      if (st) {
        candidates.push_back(spec);
      } else if (!a.modes.empty() && !a.quiet) {
        std::cerr << "robustness: " << spec.Name() << " not run: " << st.message() << "\n";
      }
    }
  }
  // A run that cannot start at all (a missing model) is reported once instead of failing on
  // every scene: each candidate runs on the first motion frames of the first seed's scene of
  // every tier, and is dropped only when it fails on all of them (one scene may refuse, e.g. an
  // arm the pose network does not see well enough to calibrate from).
  std::vector<std::string> errors(candidates.size());
  std::vector<int> failed(candidates.size(), 0);
  for (synth::SceneTier tier : a.tiers) {
    synth::RandomArmSceneOptions o = first;
    o.tier = tier;
    const synth::RandomArmScene probe_scene(o);
    const SceneResult probe =
        RunScene(o, candidates, work_dir, probe_scene.first_motion_frame() + 2);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (probe.runs[i].error.empty()) continue;
      ++failed[i];
      errors[i] = probe.runs[i].error;
    }
  }
  std::vector<RunSpec> specs;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (failed[i] < static_cast<int>(a.tiers.size())) {
      specs.push_back(candidates[i]);
    } else {
      std::cerr << "robustness: " << candidates[i].Name() << " not run: " << errors[i] << "\n";
    }
  }
  return specs;
}

Status WriteText(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  f.close();
  return f ? Status::Ok() : Status::Error(path + ": cannot write");
}

void PrintProgress(std::size_t i, std::size_t n, const SceneResult& r,
                   const std::vector<RunSpec>& specs) {
  std::fprintf(stderr, "[%zu/%zu] %s-%llu:", i + 1, n, synth::SceneTierName(r.tier),
               static_cast<unsigned long long>(r.seed));
  for (std::size_t s = 0; s < specs.size(); ++s) {
    const RunResult& run = r.runs[s];
    std::fprintf(stderr, "  %s %3.0f%% %5.1f°%s", specs[s].Name().c_str(),
                 100 * run.score.coverage(), run.score.mean_error_deg,
                 run.score.confidently_wrong_frames ? " CW" : "");
  }
  std::fprintf(stderr, "\n");
}

// Runs the scenes on a.threads workers; results in the order of `todo`.
std::vector<SceneResult> RunAll(const Args& a,
                                const std::vector<synth::RandomArmSceneOptions>& todo,
                                const std::vector<RunSpec>& specs, const std::string& work) {
  std::vector<SceneResult> results(todo.size());
  std::atomic<std::size_t> next{0};
  std::mutex print;
  auto worker = [&] {
    for (std::size_t i = next++; i < todo.size(); i = next++) {
      results[i] = RunScene(todo[i], specs, work);
      if (a.quiet) continue;
      std::lock_guard<std::mutex> lock(print);
      PrintProgress(i, todo.size(), results[i], specs);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < a.threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  return results;
}

// User and system time of the whole process so far.
double ProcessorSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// The run in one line: scenes, frames, wall and processor time, where the threads' time went.
std::string HeadLine(const Args& a, const std::vector<SceneResult>& results,
                     const std::vector<RunSpec>& specs, double seconds) {
  long motion = 0, total = 0;
  double render_s = 0;
  std::vector<double> spec_s(specs.size(), 0.0);
  for (const SceneResult& s : results) {
    render_s += s.render_seconds;
    for (std::size_t i = 0; i < s.runs.size(); ++i) spec_s[i] += s.runs[i].seconds;
    if (!s.runs.empty()) motion += s.runs.front().score.motion_frames;
    for (const auto& [k, v] : s.knobs) {
      if (k == "background_frames" || k == "standstill_frames" || k == "motion_frames") {
        total += std::atol(v.c_str());
      }
    }
  }
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "%zu %s scenes (seeds %lld..%lld per tier, %dx%d), %ld frames (%ld motion), %zu "
                "runs each, %.0f s on %d threads (processor time %.0f s); thread time: rendering "
                "%.0f s",
                results.size(), a.set.c_str(), a.first_seed, a.first_seed + a.per_tier - 1,
                a.size.width, a.size.height, total, motion, specs.size(), seconds, a.threads,
                ProcessorSeconds(), render_s);
  std::string head = buf;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    std::snprintf(buf, sizeof(buf), ", %s %.0f s", specs[i].Name().c_str(), spec_s[i]);
    head += buf;
  }
  return head + "\n";
}

int Run(const Args& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string work = a.out + "/tmp";
  std::error_code ec;
  std::filesystem::create_directories(work, ec);
  if (ec) {
    std::cerr << "robustness: " << work << ": cannot create the folder (" << ec.message() << ")\n";
    return 1;
  }
  cv::setNumThreads(1);  // the workers use the cores; no nested threads
  std::vector<synth::RandomArmSceneOptions> todo;
  for (int i = 0; i < a.per_tier; ++i) {
    for (synth::SceneTier t : a.tiers) {
      synth::RandomArmSceneOptions o;
      o.seed = static_cast<uint64_t>(a.first_seed + i);
      o.tier = t;
      o.size = a.size;
      todo.push_back(o);
    }
  }
  const std::vector<RunSpec> specs = Plan(a, todo.front(), work);
  if (specs.empty()) {
    std::cerr << "robustness: no engine accepts the requested modes\n";
    return kExitUsage;
  }
  const std::vector<SceneResult> results = RunAll(a, todo, specs, work);
  std::filesystem::remove_all(work, ec);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string head = HeadLine(a, results, specs, seconds);
  const std::string table = SummaryTable(results, specs, a.tiers);
  const std::string features = FeatureTable(results, specs);
  std::cout << head << "\n" << table;
  Status st = WriteText(a.out + "/scenes.tsv", SceneTsv(results, specs));
  if (st) st = WriteText(a.out + "/frames.tsv", FrameTsv(results, specs));
  if (st) st = WriteText(a.out + "/table.md", head + "\n" + table);
  if (st) st = WriteText(a.out + "/features.md", features);
  if (st) {
    st = WriteText(a.out + "/summary.md",
                   "# Robustness, " + a.set + " set\n\n" + head + "\n" + table +
                       "\n## By scene feature\n\n" +
                       "coverage · confidently wrong · median scene error\n\n" + features);
  }
  if (!st) {
    std::cerr << "robustness: " << st.message() << "\n";
    return 1;
  }
  if (!a.quiet) {
    std::cerr << "robustness: wrote " << a.out
              << "/{scenes.tsv,frames.tsv,table.md,features.md,summary.md}\n";
  }
  return 0;
}

}  // namespace
}  // namespace armmimic::bench

int main(int argc, char** argv) {
  armmimic::bench::Args args;
  const int code = armmimic::bench::Parse(argc, argv, &args);
  if (code >= 0) return code;
  return armmimic::bench::Run(args);
}
