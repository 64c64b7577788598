#include "armmimic/engines/run_record.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <set>

#include "armmimic/core/text.h"
#include "armmimic/engines/option_fields.h"
#include "armmimic/engines/removed_options.h"
#include "common/engine_internal.h"

namespace armmimic {
namespace {

// The shortest text that reads back as the same double.
std::string Exact(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

std::string PointText(const cv::Point2d& p) { return Exact(p.x) + "," + Exact(p.y); }

// "X,Y" or "X,Y,W,H" as numbers; false when malformed.
bool Numbers(const std::string& text, std::size_t count, std::vector<double>* out) {
  out->clear();
  std::size_t start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    double v = 0;
    if (!ParseFiniteDouble(text.substr(start, comma - start), &v)) return false;
    out->push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out->size() == count;
}

namespace fs = std::filesystem;

// The recorded paths: header key and option. The folder of the pose model was recorded as
// `model` before the pose engine's own `model` (the network) made that key appear twice.
struct PathKey {
  const char* key;
  std::string AnalysisOptions::*member;
};
constexpr PathKey kPathKeys[] = {{"background", &AnalysisOptions::background_path},
                                 {"arm_length", &AnalysisOptions::arm_length_path},
                                 {"reference", &AnalysisOptions::reference_path},
                                 {"model_dir", &AnalysisOptions::model_dir}};

constexpr const char* kAbsSuffix = "_abs";

// The plain keys a header of this or an earlier version holds besides the recorded inputs: what
// the run found or how it ran (analysis: source ... complete, incomplete; the engines'
// Describe(), under their older short names). Read back, they are skipped.
constexpr const char* kResultKeys[] = {
    "source", "fps", "width", "height", "complete", "incomplete",
    // bgsub
    "threshold", "standstill_frames", "straight_ratio", "closing", "mode",
    // lk
    "initial_upper", "initial_fore", "calibration", "side", "quality", "min_distance", "window",
    "levels", "motion_threshold", "still_frames_drop",
    // marker
    "median", "low", "high", "flood_range", "area", "N_px", "e_px", "fov_deg", "radius_px",
    "alpha_deg", "e_radii", "camera_pitch_deg", "channel",
    // hybrid (and its lk's and bgsub's, prefixed: kEnginePrefixes)
    "second_opinion", "max_disagreement", "joint_px", "restart_frames", "confirm_frames"};

// The hybrid engine records the two engines it runs under these prefixes ("lk_window").
constexpr const char* kEnginePrefixes[] = {"lk_", "bgsub_"};

// The plain keys RunFromMeta reads.
constexpr const char* kInputKeys[] = {
    "engine", "start", "background_frames", "shoulder",       "elbow",
    "wrist",  "model", "auto_calibrate",    "calibrate_side", "roi"};

bool IsKnownPlainKey(const std::string& key) {
  auto in = [](const std::string& name, const auto& list) {
    return std::any_of(std::begin(list), std::end(list),
                       [&name](const char* k) { return name == k; });
  };
  if (in(key, kResultKeys) || in(key, kInputKeys)) return true;
  for (const std::string prefix : kEnginePrefixes) {
    if (key.size() > prefix.size() && key.rfind(prefix, 0) == 0 &&
        in(key.substr(prefix.size()), kResultKeys)) {
      return true;
    }
  }
  for (const PathKey& p : kPathKeys) {
    if (key == p.key || key == std::string(p.key) + kAbsSuffix) return true;
  }
  return false;
}

// The pose engine's own model=... (the network it runs), as opposed to an older header's
// model=DIR (the folder, now model_dir).
bool IsPoseModelName(const std::string& key, const std::string& value) {
  return key == "model" &&
         (value == internal::kPoseModelName || value == internal::kBlazePoseModelName);
}

std::string Absolute(const std::string& path) {
  std::error_code ec;
  const fs::path abs = fs::absolute(path, ec);
  return ec ? path : abs.lexically_normal().string();
}

}  // namespace

AngleMeta RunRecordMeta(const AnalysisOptions& o) {
  AngleMeta meta;
  // A path as typed, and where it was when typed relative: the run repeats from any folder.
  auto path = [&meta](const char* key, const std::string& typed) {
    if (typed.empty()) return;
    meta.emplace_back(key, typed);
    if (!fs::path(typed).is_absolute()) {
      meta.emplace_back(std::string(key) + kAbsSuffix, Absolute(typed));
    }
  };
  path("background", o.background_path);
  if (o.background_frames > 0) {
    meta.emplace_back("background_frames", std::to_string(o.background_frames));
  }
  path("arm_length", o.arm_length_path);
  path("reference", o.reference_path);
  if (o.shoulder_px) meta.emplace_back("shoulder", PointText(*o.shoulder_px));
  if (o.elbow_px) meta.emplace_back("elbow", PointText(*o.elbow_px));
  if (o.wrist_px) meta.emplace_back("wrist", PointText(*o.wrist_px));
  path("model_dir", o.model_dir);
  if (o.auto_calibrate) meta.emplace_back("auto_calibrate", "yes");
  if (o.calibrate_side != PoseSide::kAuto) {
    meta.emplace_back("calibrate_side", PoseSideName(o.calibrate_side));
  }
  if (o.roi) {
    meta.emplace_back("roi", std::to_string(o.roi->x) + "," + std::to_string(o.roi->y) + "," +
                                 std::to_string(o.roi->width) + "," +
                                 std::to_string(o.roi->height));
  }
  for (auto& kv : EngineOptionValues(o.engine)) meta.push_back(std::move(kv));
  return meta;
}

Status RunFromMeta(const AngleMeta& meta, const std::string& source_name, AnalysisOptions* o,
                   std::vector<std::string>* ignored) {
  auto err = [&](const std::string& what) { return Status::Error(source_name + ": " + what); };
  std::string engine;
  for (const auto& [k, v] : meta) {
    if (k == "engine") engine = v;
  }
  if (engine.empty()) return err("the header records no engine (engine=...): no run to repeat");
  AnalysisOptions run;
  run.inputs = o->inputs;
  if (!ParseEngineKind(engine, &run.engine.kind)) {
    return err("engine=" + Excerpt(engine) +
               " is not an engine this version knows (bgsub, lk, marker, pose or hybrid)");
  }
  std::vector<double> n;
  std::vector<std::string> removed;
  for (const auto& [k, v] : meta) {
    if (k.find('.') != std::string::npos) {
      // The hybrid engine records the settings of the lk and bgsub engines it runs too.
      const bool part = run.engine.kind == EngineKind::kHybrid &&
                        (k.rfind("lk.", 0) == 0 || k.rfind("bgsub.", 0) == 0);
      if (k.rfind(engine + ".", 0) != 0 && !part) {
        return err(k + "=" + Excerpt(v) + " is not a setting of the recorded engine " + engine);
      }
      if (FindRemovedEngineOption(k)) {
        removed.push_back(k);
        continue;
      }
      const Status st = SetEngineOption(k + "=" + v, &run.engine);
      // The setting's own message quotes the value: a long or many-line one only by its start.
      if (!st && Excerpt(v) != v) return err(k + "=" + Excerpt(v) + " is not a value of " + k);
      if (!st) return err(st.message());
    } else if (k == "background") {
      run.background_path = v;
    } else if (k == "arm_length") {
      run.arm_length_path = v;
    } else if (k == "reference") {
      run.reference_path = v;
    } else if (k == "model_dir" || (k == "model" && !IsPoseModelName(k, v))) {
      run.model_dir = v;
    } else if (k == "auto_calibrate") {
      if (v != "yes" && v != "no") return err("auto_calibrate=" + Excerpt(v) + " is not yes or no");
      run.auto_calibrate = v == "yes";
    } else if (k == "calibrate_side") {
      if (!ParsePoseSide(v, &run.calibrate_side)) {
        return err("calibrate_side=" + Excerpt(v) + " is not left, right or auto");
      }
    } else if (k == "background_frames" || k == "start") {
      int value = 0;
      if (!ParseFrameIndex(v, &value)) return err(k + "=" + Excerpt(v) + " is not a frame count");
      (k == "start" ? run.start : run.background_frames) = value;
    } else if (k == "shoulder" || k == "elbow" || k == "wrist") {
      if (!Numbers(v, 2, &n)) return err(k + "=" + Excerpt(v) + " is not a point X,Y");
      (k == "shoulder" ? run.shoulder_px
       : k == "elbow"  ? run.elbow_px
                       : run.wrist_px) = cv::Point2d(n[0], n[1]);
    } else if (k == "roi") {
      if (!Numbers(v, 4, &n)) return err("roi=" + Excerpt(v) + " is not a rectangle X,Y,W,H");
      run.roi = cv::Rect(static_cast<int>(n[0]), static_cast<int>(n[1]), static_cast<int>(n[2]),
                         static_cast<int>(n[3]));
    }
    // Other keys describe the result (fps, width, ...), repeat a setting under its old name or
    // give a path's absolute form (KEY_abs, for ReadRunRecord).
  }
  *o = run;
  if (ignored) *ignored = std::move(removed);
  return Status::Ok();
}

Status CheckRunRecordKeys(const AngleMeta& meta, const std::string& source_name, int line) {
  const std::string where = source_name + ":" + std::to_string(line) + ": ";
  std::map<std::string, std::string> seen;
  std::string engine;
  for (const auto& [k, v] : meta) {
    if (IsPoseModelName(k, v)) continue;  // beside an older header's model=DIR, not a repeat
    const auto [it, first] = seen.emplace(k, v);
    if (!first) {
      return Status::Error(where + "the key " + Excerpt(k) + " appears twice (" + Excerpt(k) + "=" +
                           Excerpt(it->second) + " and " + Excerpt(k) + "=" + Excerpt(v) +
                           "); a header names each key once");
    }
    if (k == "engine") engine = v;
  }
  EngineOptions recorded;
  const bool known_engine = ParseEngineKind(engine, &recorded.kind);
  std::set<std::string> settings;
  if (known_engine) {
    for (const auto& [k, v] : EngineOptionValues(recorded)) settings.insert(k);
  }
  for (const auto& [k, v] : meta) {
    const bool dotted = k.find('.') != std::string::npos;
    if (!dotted && IsKnownPlainKey(k)) continue;
    // An ENGINE.KEY is checked once the engine is known (RunFromMeta names a missing one).
    if (dotted && (!known_engine || settings.count(k) > 0 || FindRemovedEngineOption(k))) {
      continue;
    }
    std::string why = "no version of armmimic writes it";
    if (dotted && k.rfind(engine + ".", 0) != 0) {
      why = "not a setting of the recorded engine " + engine;
    } else if (dotted) {
      why = "no " + engine + " setting has this name";
    }
    return Status::Error(where + "unknown key " + Excerpt(k) + "=" + Excerpt(v) + " (" + why + ")");
  }
  return Status::Ok();
}

Status ReadRunRecord(const std::string& path, AnalysisOptions* options, RunRecordNotes* notes) {
  RunRecordNotes local;
  RunRecordNotes& n = notes ? *notes : local;
  n = RunRecordNotes();
  AngleFile file;
  if (Status st = ReadAngleFile(path, &file); !st) return st;
  if (Status st = CheckRunRecordKeys(file.meta, path, file.meta_line); !st) {
    n.bad_keys = true;
    return st;
  }
  AnalysisOptions run = *options;
  if (Status st = RunFromMeta(file.meta, path, &run, &n.ignored); !st) return st;
  const fs::path beside = fs::path(Absolute(path)).parent_path();
  for (const PathKey& p : kPathKeys) {
    std::string& typed = run.*p.member;
    if (typed.empty()) continue;
    std::vector<std::string> tried;
    if (fs::path(typed).is_absolute()) {
      tried.push_back(typed);  // where it was, and nowhere else
    } else {
      const std::string abs = file.Meta(std::string(p.key) + kAbsSuffix);
      for (const std::string& candidate :
           {abs, (beside / typed).lexically_normal().string(), Absolute(typed)}) {
        if (!candidate.empty() && std::find(tried.begin(), tried.end(), candidate) == tried.end()) {
          tried.push_back(candidate);
        }
      }
    }
    const auto found = std::find_if(tried.begin(), tried.end(), [](const std::string& c) {
      std::error_code ec;
      return fs::exists(c, ec);
    });
    if (found != tried.end()) {
      // Found where the path as typed leads from here: it stays as typed, so the header of the
      // repeated run says what the first one said.
      if (*found != Absolute(typed)) typed = *found;
    } else {
      n.missing.push_back({p.key, typed, tried});
    }
  }
  *options = run;
  return Status::Ok();
}

Status CheckRecordedPathsFound(const AnalysisOptions& options,
                               const std::vector<MissingRecordedPath>& missing,
                               const std::string& source_name) {
  for (const MissingRecordedPath& m : missing) {
    for (const PathKey& p : kPathKeys) {
      if (m.key != p.key || options.*p.member != m.typed) continue;
      std::string tried;
      // Paths are quoted whole (PATH_MAX bounds them), on one line whatever they hold.
      for (const std::string& t : m.tried) tried += (tried.empty() ? "" : ", ") + Excerpt(t, 4096);
      return Status::Error(source_name + ": the recorded " + m.key + "=" + Excerpt(m.typed, 4096) +
                           " was found nowhere (tried " + tried + ")");
    }
  }
  return Status::Ok();
}

}  // namespace armmimic
