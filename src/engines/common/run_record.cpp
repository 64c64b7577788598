#include "armmimic/engines/run_record.h"

#include <charconv>
#include <fstream>

#include "armmimic/core/text.h"
#include "armmimic/engines/option_fields.h"
#include "armmimic/engines/removed_options.h"

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

}  // namespace

AngleMeta RunRecordMeta(const AnalysisOptions& o) {
  AngleMeta meta;
  if (!o.background_path.empty()) meta.emplace_back("background", o.background_path);
  if (o.background_frames > 0) {
    meta.emplace_back("background_frames", std::to_string(o.background_frames));
  }
  if (!o.arm_length_path.empty()) meta.emplace_back("arm_length", o.arm_length_path);
  if (!o.reference_path.empty()) meta.emplace_back("reference", o.reference_path);
  if (o.shoulder_px) meta.emplace_back("shoulder", PointText(*o.shoulder_px));
  if (o.elbow_px) meta.emplace_back("elbow", PointText(*o.elbow_px));
  if (o.wrist_px) meta.emplace_back("wrist", PointText(*o.wrist_px));
  if (!o.model_dir.empty()) meta.emplace_back("model", o.model_dir);
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
    return err("engine=" + engine +
               " is not an engine this version knows (bgsub, lk, marker or pose)");
  }
  std::vector<double> n;
  std::vector<std::string> removed;
  for (const auto& [k, v] : meta) {
    if (k.find('.') != std::string::npos) {
      if (k.rfind(engine + ".", 0) != 0) {
        return err(k + "=" + v + " is not a setting of the recorded engine " + engine);
      }
      if (FindRemovedEngineOption(k)) {
        removed.push_back(k);
        continue;
      }
      const Status st = SetEngineOption(k + "=" + v, &run.engine);
      if (!st) return err(st.message());
    } else if (k == "background") {
      run.background_path = v;
    } else if (k == "arm_length") {
      run.arm_length_path = v;
    } else if (k == "reference") {
      run.reference_path = v;
    } else if (k == "model") {
      run.model_dir = v;
    } else if (k == "auto_calibrate") {
      if (v != "yes" && v != "no") return err("auto_calibrate=" + v + " is not yes or no");
      run.auto_calibrate = v == "yes";
    } else if (k == "calibrate_side") {
      if (!ParsePoseSide(v, &run.calibrate_side)) {
        return err("calibrate_side=" + v + " is not left, right or auto");
      }
    } else if (k == "background_frames" || k == "start") {
      int value = 0;
      if (!ParseFrameIndex(v, &value)) return err(k + "=" + v + " is not a frame count");
      (k == "start" ? run.start : run.background_frames) = value;
    } else if (k == "shoulder" || k == "elbow" || k == "wrist") {
      if (!Numbers(v, 2, &n)) return err(k + "=" + v + " is not a point X,Y");
      (k == "shoulder" ? run.shoulder_px
       : k == "elbow"  ? run.elbow_px
                       : run.wrist_px) = cv::Point2d(n[0], n[1]);
    } else if (k == "roi") {
      if (!Numbers(v, 4, &n)) return err("roi=" + v + " is not a rectangle X,Y,W,H");
      run.roi = cv::Rect(static_cast<int>(n[0]), static_cast<int>(n[1]), static_cast<int>(n[2]),
                         static_cast<int>(n[3]));
    }
    // Other keys describe the result (fps, width, ...) or repeat a setting under its old name.
  }
  *o = run;
  if (ignored) *ignored = std::move(removed);
  return Status::Ok();
}

Status ReadRunRecord(const std::string& path, AnalysisOptions* options,
                     std::vector<std::string>* ignored) {
  AngleFile file;
  const Status st = ReadAngleFile(path, &file);
  if (!st) return st;
  return RunFromMeta(file.meta, path, options, ignored);
}

}  // namespace armmimic
