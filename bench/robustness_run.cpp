#include "robustness_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "armmimic/core/image_io.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic::bench {
namespace {

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// The reason of a lost row without its numbers, so that rows lost for one reason group.
std::string Reason(const std::string& note) {
  std::string out;
  for (char c : note.substr(0, note.find('('))) {
    if (c == '\t' || c == '\n') c = ' ';
    if (c >= '0' && c <= '9') {
      if (out.empty() || out.back() != '#') out += '#';
    } else if (c != '.' || out.empty() || out.back() != '#') {
      out += c;
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out.empty() ? "(no note)" : out;
}

Status ThesisMode(const SceneInputs& in, EngineKind engine, AnalysisOptions* o) {
  // Thesis 5.2: the background from the empty frames, the standstill, the arm-length image.
  const synth::RandomArmScene& s = *in.scene;
  o->background_frames = s.background_frames();
  o->start = s.background_frames();
  o->arm_length_path = in.arm_length_path;
  return SetEngineOption(std::string(EngineName(engine)) +
                             ".standstill_frames=" + std::to_string(s.standstill_frames()),
                         &o->engine);
}

Status JointsMode(const SceneInputs& in, EngineKind, AnalysisOptions* o) {
  // What an operator clicks on the first motion frame: the joints, to whole pixels.
  const synth::RandomArmScene& s = *in.scene;
  const synth::ArmTruth t = s.Truth(s.first_motion_frame());
  auto px = [](const cv::Point2d& p) { return cv::Point2d(std::round(p.x), std::round(p.y)); };
  o->start = s.first_motion_frame();
  o->shoulder_px = px(t.shoulder_px);
  o->elbow_px = px(t.elbow_px);
  o->wrist_px = px(t.wrist_px);
  return Status::Ok();
}

// What `analyze --side` says: the person's own moving arm (facing the camera, their left arm is
// on the image's right).
void NameTheArm(const SceneInputs& in, AnalysisOptions* o) {
  const PoseSide side =
      in.scene->params().side == synth::ArmSide::kRight ? PoseSide::kLeft : PoseSide::kRight;
  o->engine.pose.side = side;
  o->calibrate_side = side;
}

Status NoneMode(const SceneInputs& in, EngineKind, AnalysisOptions* o) {
  // Nothing but where the motion starts and which arm moves.
  o->start = in.scene->first_motion_frame();
  NameTheArm(in, o);
  return Status::Ok();
}

Status AutoMode(const SceneInputs& in, EngineKind, AnalysisOptions* o) {
  // The joints on the first motion frame from the pose network (--auto-calibrate).
  o->start = in.scene->first_motion_frame();
  o->auto_calibrate = true;
  NameTheArm(in, o);
  return Status::Ok();
}

}  // namespace

const std::vector<CalibrationMode>& CalibrationModes() {
  static const std::vector<CalibrationMode> modes = {
      {"thesis",
       "background from the empty frames [0, K), standstill [K, K+M), the arm-length image",
       ThesisMode},
      {"joints",
       "shoulder, elbow and wrist clicked on the first motion frame (the truth, rounded to whole "
       "pixels)",
       JointsMode},
      {"auto",
       "the joints on the first motion frame from the pose network (--auto-calibrate), the "
       "moving arm named (--side)",
       AutoMode},
      {"none", "nothing but the first motion frame (--start) and the moving arm (--side)",
       NoneMode},
  };
  return modes;
}

std::string RunSpec::Name() const { return std::string(EngineName(engine)) + "/" + mode->name; }

Status BuildOptions(const RunSpec& spec, const SceneInputs& inputs, AnalysisOptions* out) {
  AnalysisOptions o;
  o.inputs = {"scene"};
  o.engine.kind = spec.engine;
  for (const std::string& p : spec.params) {
    const std::string prefix = std::string(EngineName(spec.engine)) + ".";
    if (p.compare(0, prefix.size(), prefix) != 0) continue;  // another engine's setting
    Status st = SetEngineOption(p, &o.engine);
    if (!st) return st;
  }
  Status st = spec.mode->apply(inputs, spec.engine, &o);
  if (!st) return st;
  st = o.Check();
  if (!st) return st;
  *out = std::move(o);
  return Status::Ok();
}

SceneResult RunScene(const synth::RandomArmSceneOptions& options, const std::vector<RunSpec>& specs,
                     const std::string& work_dir, int max_frames) {
  const auto t0 = std::chrono::steady_clock::now();
  SceneResult result;
  result.seed = options.seed;
  result.tier = options.tier;
  const synth::RandomArmScene scene(options);
  result.knobs = scene.params().Describe();
  auto frames = std::make_shared<std::vector<cv::Mat>>();
  const int count =
      max_frames > 0 ? std::min(max_frames, scene.frame_count()) : scene.frame_count();
  frames->reserve(static_cast<std::size_t>(count));
  const int quality = scene.params().jpeg_quality;
  for (int f = 0; f < count; ++f) frames->push_back(synth::JpegRoundTrip(scene.Render(f), quality));
  synth::TruthFile truth;
  for (int f = 0; f < count; ++f) truth.rows.push_back(scene.Truth(f).ToRow());
  const std::string name =
      std::string(synth::SceneTierName(options.tier)) + "-" + std::to_string(options.seed);
  SceneInputs inputs{&scene, work_dir + "/armlength-" + name + ".png"};
  const Status written = WriteImageAtomically(inputs.arm_length_path, scene.ArmLengthImage());
  result.render_seconds = Seconds(t0);

  const double fps = scene.fps();
  for (const RunSpec& spec : specs) {
    RunResult run;
    const auto t1 = std::chrono::steady_clock::now();
    AnalysisOptions o;
    Status st = written;
    if (st) st = BuildOptions(spec, inputs, &o);
    std::vector<AngleRow> rows;
    std::map<std::string, int> reasons;
    std::map<int, std::string> notes;
    if (st) {
      o.inputs = {name};
      o.open_source = [frames, fps, name](Status* status) {
        return VideoSource::FromFrames(frames, fps, name, status);
      };
      AnalysisCallbacks cb;
      cb.on_measurement = [&](const Frame&, const ArmMeasurement& m) {
        if (!m.row()) return;
        rows.push_back(m.ToRow());
        if (m.frame >= scene.first_motion_frame()) notes[m.frame] = m.note;
        if (m.phase == MeasurementPhase::kLost) ++reasons[Reason(m.note)];
      };
      AnalysisSummary summary;
      st = RunAnalysis(o, cb, &summary);
    }
    if (!st) run.error = st.message();
    AngleFile angles;
    angles.rows = std::move(rows);
    const synth::ScoreReport report = synth::ScoreAngles(truth, angles);
    run.score = synth::ScoreMotion(report, scene.first_motion_frame());
    std::map<int, double> confidence;
    for (const AngleRow& r : angles.rows) confidence[r.frame] = r.confidence;
    for (const synth::ScoreRow& r : report.rows) {
      if (r.frame < scene.first_motion_frame()) continue;
      FrameRecord f;
      f.frame = r.frame;
      f.ok = r.ok;
      f.err_upper = r.err_upper;
      f.err_fore = r.err_fore;
      if (auto c = confidence.find(r.frame); c != confidence.end()) f.confidence = c->second;
      if (auto n = notes.find(r.frame); n != notes.end()) f.note = n->second;
      run.frames.push_back(std::move(f));
    }
    int most = 0;
    for (const auto& [reason, count] : reasons) {
      if (count > most) most = count, run.lost_reason = reason;
    }
    run.seconds = Seconds(t1);
    result.runs.push_back(std::move(run));
  }
  std::remove(inputs.arm_length_path.c_str());
  return result;
}

}  // namespace armmimic::bench
