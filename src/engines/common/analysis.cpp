// The analysis pipeline behind `armmimic-cli analyze` and the GUI's Analyze task: engine
// agnostic, streaming (one frame in memory at a time).
// Length: the pipeline's run is one loop from open to commit; Run's checks, engine start and frame
// loop share its state, and every input error it reports is keyed by its setting here (the
// options' own rules, AnalysisOptions::Check(), are in analysis_options.cpp).

#include "armmimic/engines/analysis.h"

#include <chrono>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/frame_pacer.h"
#include "armmimic/core/image_io.h"
#include "armmimic/engines/engine.h"
#include "armmimic/engines/option_fields.h"
#include "armmimic/engines/pose.h"
#include "armmimic/engines/run_record.h"
#include "common/analysis_inputs.h"
#include "common/engine_internal.h"

namespace armmimic {
namespace {

using internal::LoadSized;
using internal::OpenInput;
using internal::SizeText;

std::string BaseName(const std::string& path) {
  std::string p = path;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  const auto slash = p.find_last_of('/');
  return slash == std::string::npos ? p : p.substr(slash + 1);
}

std::string ShortNumber(double v) {
  std::string s = FormatNumber(v, 3);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  return s;
}

bool Cancelled(const AnalysisCallbacks& cb) {
  return cb.cancel != nullptr && cb.cancel->load(std::memory_order_relaxed);
}

void Phase(const AnalysisCallbacks& cb, const std::string& phase) {
  if (cb.on_phase) cb.on_phase(phase);
}

// The pose network's part before the engine starts: --auto-calibrate's joints, and the pose
// engine's arm when --side is auto. Decisions go to on_estimate.
Status PreparePose(const AnalysisOptions& options, const VideoInfo& info,
                   const AnalysisCallbacks& callbacks, AnalysisOptions* resolved) {
  auto tell = [&](const std::string& text) {
    if (callbacks.on_estimate && !text.empty()) callbacks.on_estimate(text);
  };
  if (options.auto_calibrate) {
    Phase(callbacks, "auto-calibrate");
    PoseArm arm;
    PoseSide side = options.calibrate_side;
    Status st = internal::DetectArmJointsFrom(
        [&options](Status* s) { return OpenInput(options, s); }, options.start,
        options.calibrate_side, options.model_dir, options.engine.pose, &arm, &side);
    if (!st) return st.key().empty() ? st.WithKey("analysis.auto_calibrate") : st;
    resolved->shoulder_px = arm.shoulder;
    resolved->elbow_px = arm.elbow;
    resolved->wrist_px = arm.wrist;
    auto xy = [](const cv::Point2d& p) {
      return ShortNumber(std::round(p.x)) + "," + ShortNumber(std::round(p.y));
    };
    tell("auto-calibrate: the person's " + std::string(PoseSideName(side)) + " arm in frame " +
         std::to_string(options.start) + ": shoulder " + xy(arm.shoulder) + ", elbow " +
         xy(arm.elbow) + ", wrist " + xy(arm.wrist));
  }
  if (options.engine.kind == EngineKind::kPose && options.engine.pose.side == PoseSide::kAuto) {
    std::string why;
    Status st = internal::ChoosePoseSide([&options](Status* s) { return OpenInput(options, s); },
                                         options.start, info.fps, options.model_dir,
                                         &resolved->engine.pose.side, &why);
    if (!st) return st;
    tell(why);
  }
  return Status::Ok();
}

// The angle file's meta line for a run with `options` (one arm's, with side both).
AngleMeta MetaOf(const AnalysisOptions& options, const VideoInfo& info, const Engine& engine) {
  const bool arm_engine = options.engine.kind != EngineKind::kMarker;
  AngleMeta meta = {{"engine", EngineName(options.engine.kind)},
                    {"source", BaseName(info.path.empty() ? options.inputs.front() : info.path)},
                    {"fps", ShortNumber(info.fps)},
                    {"width", std::to_string(info.size.width)},
                    {"height", std::to_string(info.size.height)}};
  if (arm_engine) meta.emplace_back("start", std::to_string(options.start));
  for (auto& kv : engine.Describe()) meta.push_back(std::move(kv));
  // The inputs besides the video and every engine parameter, under the name `analyze --param`
  // takes, so the file says how to make it again (`analyze --params-from`).
  for (auto& kv : RunRecordMeta(options)) meta.push_back(std::move(kv));
  std::set<std::string> keys;
  for (const auto& kv : meta) {
    // Each key once: --params-from refuses a header that names one twice.
    if (!keys.insert(kv.first).second) {
      throw std::logic_error("the angle file's header would name " + kv.first + " twice");
    }
  }
  return meta;
}

// Counts the rows of `m`, one per arm, into `summary` (whose arms are set).
void CountRows(const ArmMeasurement& m, AnalysisSummary* summary) {
  const std::vector<const ArmMeasurement*> arms = m.Arms();
  if (arms.size() != summary->arms.size()) {
    throw std::logic_error("the engine measured " + std::to_string(arms.size()) +
                           " arms, the analysis reports " + std::to_string(summary->arms.size()));
  }
  for (std::size_t i = 0; i < arms.size(); ++i) {
    const bool ok = arms[i]->phase == MeasurementPhase::kOk;
    AnalysisSummary::ArmRows& rows = summary->arms[i];
    ++rows.frames;
    ++summary->frames;
    (ok ? rows.ok : rows.lost)++;
    (ok ? summary->ok : summary->lost)++;
  }
  summary->lost_reasons.Add(m);
}

using RowSink = std::function<Status(const ArmMeasurement&)>;
using ReadySink = std::function<Status(const std::vector<AngleMeta>&)>;

Status Run(const AnalysisOptions& given, const AnalysisCallbacks& callbacks,
           const ReadySink& on_ready, const RowSink& on_row, AnalysisSummary* summary) {
  const auto t0 = std::chrono::steady_clock::now();
  *summary = AnalysisSummary();
  auto finish = [&](Status st) {
    summary->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return st;
  };
  Status st = given.Check();
  if (!st) return finish(st);

  Status open_status;
  std::unique_ptr<VideoSource> source = OpenInput(given, &open_status);
  if (!source) return finish(open_status);
  const VideoInfo info = source->info();
  summary->video = info;
  if (callbacks.on_open) callbacks.on_open(info);
  const EngineKind kind = given.engine.kind;
  const bool arm_engine = kind != EngineKind::kMarker;

  if (arm_engine && info.frame_count >= 0 && given.start >= info.frame_count) {
    return finish(Status::Error("analysis.start", "the start frame " + std::to_string(given.start) +
                                                      " is past the end of " + info.path + " (" +
                                                      std::to_string(info.frame_count) +
                                                      " frames)"));
  }

  AnalysisOptions options = given;  // with what the pose network decided
  if (arm_engine) {
    st = PreparePose(given, info, callbacks, &options);
    if (!st) return finish(st);
  }

  EngineContext context;
  context.model_dir = options.model_dir;
  context.frame_size = info.size;
  context.fps = info.fps;
  context.shoulder_px = options.shoulder_px;
  context.roi = options.roi;
  if (options.roi) {
    const cv::Rect inside = *options.roi & cv::Rect(0, 0, info.size.width, info.size.height);
    if (inside != *options.roi) {
      return finish(Status::Error("analysis.roi",
                                  "the region of interest " + std::to_string(options.roi->x) + "," +
                                      std::to_string(options.roi->y) + "," +
                                      std::to_string(options.roi->width) + "," +
                                      std::to_string(options.roi->height) + " does not fit in " +
                                      info.path + " (" + SizeText(info.size) + ")"));
    }
  }
  const struct {
    const char* key;
    const char* name;
    const std::optional<cv::Point2d>* px;
  } joints[] = {{"analysis.shoulder", "shoulder", &options.shoulder_px},
                {"analysis.elbow", "elbow", &options.elbow_px},
                {"analysis.wrist", "wrist", &options.wrist_px}};
  for (const auto& joint : joints) {
    if (!*joint.px) continue;
    const cv::Point2d& s = **joint.px;
    if (s.x < 0 || s.y < 0 || s.x >= info.size.width || s.y >= info.size.height) {
      return finish(Status::Error(joint.key, std::string("the ") + joint.name + " is outside " +
                                                 info.path + " (" + SizeText(info.size) + ")"));
    }
  }
  context.elbow_px = options.elbow_px;
  context.wrist_px = options.wrist_px;
  if (arm_engine) {
    if (!options.background_path.empty()) {
      st = LoadSized(options.background_path, "analysis.background", "the background image", info,
                     &context.background);
      if (!st) return finish(st);
    } else if (options.background_frames > 0) {
      // A first pass over frames [0, K) of the input itself (thesis 5.2.1).
      Phase(callbacks, "background");
      Status bg_open;
      std::unique_ptr<VideoSource> bg_source = OpenInput(options, &bg_open);
      st = internal::MeanOfFrames(std::move(bg_source), bg_open, 0, options.background_frames,
                                  "the background", &context.background, callbacks);
      if (!st) return finish(st.WithKey("analysis.background_frames"));
      if (Cancelled(callbacks)) {
        summary->cancelled = true;
        return finish(Status::Ok());
      }
    }
    if (!options.arm_length_path.empty()) {
      st = LoadSized(options.arm_length_path, "analysis.arm_length", "the arm-length image", info,
                     &context.arm_length);
      if (!st) return finish(st);
    }
  } else if (!options.reference_path.empty()) {
    st = ReadImage(options.reference_path, &context.reference);
    if (!st) return finish(st.WithKey("analysis.reference"));
  }

  std::unique_ptr<Engine> engine = Engine::Create(options.engine);
  st = engine->Begin(context);
  if (!st) return finish(st);
  std::vector<AngleMeta> metas;  // one per angle file

  for (PoseSide side : AnalysedArms(options)) {
    AnalysisOptions arm = options;
    if (kind == EngineKind::kPose) {  // each file names its arm, as a run of that side would
      arm.engine.pose.side = side;
      if (arm.calibrate_side == PoseSide::kBoth) arm.calibrate_side = side;
    }
    metas.push_back(MetaOf(arm, info, *engine));
    summary->arms.push_back({side});
  }
  summary->meta = metas.front();
  if (on_ready) {
    st = on_ready(metas);
    if (!st) return finish(st);
  }

  if (arm_engine && options.start > 0 && info.kind == SourceKind::kCamera) {
    // A live camera or stream cannot seek: its first `start` frames are read and dropped, so
    // frame numbers still count from the first frame it delivered.
    Frame skipped;
    for (int i = 0; i < options.start; ++i) {
      if (Cancelled(callbacks)) {
        summary->cancelled = true;
        return finish(Status::Ok());
      }
      if (!source->Read(&skipped, &st)) {
        return finish(Status::Error(
            "analysis.start", "the start frame " + std::to_string(options.start) + ": " +
                                  info.path + " ended after " + std::to_string(i) + " frames" +
                                  (st ? std::string() : " (" + st.message() + ")")));
      }
    }
  } else if (arm_engine && options.start > 0) {
    st = source->Seek(options.start);
    if (!st)
      return finish(
          Status::Error("analysis.start",
                        "the start frame " + std::to_string(options.start) + ": " + st.message()));
  }
  const int total =
      info.frame_count >= 0 ? info.frame_count - (arm_engine ? options.start : 0) : -1;
  Phase(callbacks, "analysis");
  FramePacer pacer(options.realtime && info.kind == SourceKind::kVideo ? info.fps : 0);
  Frame frame;
  int done = 0;
  int setup = 0;
  while (true) {
    if (Cancelled(callbacks)) {
      summary->cancelled = true;
      break;
    }
    Status read_status;
    if (!source->Read(&frame, &read_status)) {
      if (!read_status && done == 0) return finish(read_status);
      // A read that fails after frames were analysed keeps their rows, marked incomplete.
      if (!read_status) summary->incomplete = "a read failed: " + read_status.message();
      break;
    }
    const auto captured = pacer.Wait(frame, callbacks.cancel);
    if (callbacks.on_frame) callbacks.on_frame(frame, captured);
    const ArmMeasurement m = engine->Process(frame);
    summary->last_frame = frame.index;
    ++done;
    if (!m.estimate.empty() && callbacks.on_estimate) callbacks.on_estimate(m.estimate);
    if (callbacks.on_measurement) callbacks.on_measurement(frame, m);
    if (m.row()) {
      CountRows(m, summary);
      if (on_row) {
        st = on_row(m);
        if (!st) return finish(st);
      }
    } else {
      ++setup;
    }
    if (callbacks.on_progress) callbacks.on_progress(done, total);
  }
  if (summary->incomplete.empty() && summary->ShortOfAnnounced()) {
    summary->incomplete = "the video announces " + std::to_string(info.frame_count) +
                          " frames, only " + std::to_string(summary->last_frame + 1) +
                          " could be read (truncated or damaged)";
  }
  if (!summary->cancelled && summary->frames == 0 && setup > 0) {
    return finish(Status::Error(
        "analysis.start",
        info.path + " ended during the standstill: frames [" + std::to_string(options.start) +
            ", " + std::to_string(options.start + setup) + ") were read, " +
            "no frame was left to analyse (see the start frame and the standstill length)"));
  }
  return finish(Status::Ok());
}

}  // namespace

Status EstimateBackground(const std::vector<std::string>& inputs, int start, int count,
                          cv::Mat* background, const AnalysisCallbacks& callbacks) {
  Status st;
  std::unique_ptr<VideoSource> source = VideoSource::Open(inputs, &st);
  return internal::MeanOfFrames(std::move(source), st, start, count, "the background", background,
                                callbacks);
}

std::vector<PoseSide> AnalysedArms(const AnalysisOptions& options) {
  if (options.engine.kind != EngineKind::kPose) return {options.engine.pose.side};
  return internal::FollowedSides(options.engine.pose.side);
}

std::vector<std::string> ArmOutputPaths(const AnalysisOptions& options, const std::string& path) {
  const std::vector<PoseSide> arms = AnalysedArms(options);
  if (arms.size() == 1) return {path};
  const std::size_t slash = path.find_last_of('/');
  const std::size_t name = slash == std::string::npos ? 0 : slash + 1;
  std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || dot <= name) dot = path.size();  // no extension (or ".tsv")
  std::vector<std::string> paths;
  paths.reserve(arms.size());
  for (PoseSide side : arms) {
    paths.push_back(path.substr(0, dot) + "." + PoseSideName(side) + path.substr(dot));
  }
  return paths;
}

Status RunAnalysis(const AnalysisOptions& options, const AnalysisCallbacks& callbacks,
                   AnalysisSummary* summary) {
  return Run(options, callbacks, nullptr, nullptr, summary);
}

Status AnalyzeToFile(const AnalysisOptions& options, const std::string& output_path,
                     const AnalysisCallbacks& callbacks, AnalysisSummary* summary) {
  const std::vector<std::string> paths = ArmOutputPaths(options, output_path);
  std::vector<AngleFileWriter> writers(paths.size());
  const bool file_column = options.engine.kind == EngineKind::kMarker;
  // The engines that rate their own rows (pose, lk, hybrid, and bgsub's two-segment fit, not its
  // thesis path) write the optional confidence column.
  const bool confidence_column =
      options.engine.kind == EngineKind::kPose || options.engine.kind == EngineKind::kLk ||
      options.engine.kind == EngineKind::kHybrid ||
      (options.engine.kind == EngineKind::kBgsub && !options.engine.bgsub.thesis_mode);
  // Only BlazePose measures the arm in 3-D.
  const bool columns_3d = options.engine.kind == EngineKind::kPose &&
                          options.engine.pose.network == PoseNetworkKind::kBlazePose;
  Status st = Run(
      options, callbacks,
      [&](const std::vector<AngleMeta>& metas) {
        for (std::size_t i = 0; i < writers.size(); ++i) {
          Status opened = writers[i].Open(paths[i], metas.at(i), file_column, confidence_column,
                                          /*signed_yaw_column=*/file_column, columns_3d);
          if (!opened) return opened;
        }
        return Status::Ok();
      },
      [&](const ArmMeasurement& m) {
        const std::vector<const ArmMeasurement*> arms = m.Arms();
        for (std::size_t i = 0; i < writers.size(); ++i) {
          Status written = writers[i].Write(arms.at(i)->ToRow());
          if (!written) return written;
        }
        return Status::Ok();
      },
      summary);
  if (!st) return st;
  if (summary->meta.empty()) return Status::Ok();  // cancelled before the file was opened
  for (AngleFileWriter& writer : writers) {
    st = writer.Commit(!summary->cancelled && summary->incomplete.empty(), summary->incomplete);
    if (!st) return st;
  }
  return Status::Ok();
}

}  // namespace armmimic
