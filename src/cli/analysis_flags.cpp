#include "analysis_flags.h"
#include "flag_for_key.h"

#include <map>
#include <set>

#include "armmimic/engines/option_fields.h"

namespace armmimic::cli {

const std::map<std::string, std::set<EngineKind>>& AnalysisFlags::EngineFlags() {
  static const std::map<std::string, std::set<EngineKind>> flags = {
      {"--background", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--background-frames", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--arm-length", {EngineKind::kBgsub}},
      {"--start", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kPose}},
      {"--standstill-frames", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--threshold", {EngineKind::kBgsub}},
      {"--shoulder", {EngineKind::kBgsub, EngineKind::kLk}},
      {"--elbow", {EngineKind::kLk}},
      {"--wrist", {EngineKind::kLk}},
      {"--roi", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kPose}},
      {"--side", {EngineKind::kPose, EngineKind::kLk}},
      {"--model", {EngineKind::kPose, EngineKind::kLk}},
      {"--auto-calibrate", {EngineKind::kLk}},
      {"--initial-upper", {EngineKind::kLk}},
      {"--initial-fore", {EngineKind::kLk}},
      {"--reference", {EngineKind::kMarker}},
      {"--low", {EngineKind::kMarker}},
      {"--high", {EngineKind::kMarker}},
      {"--fov", {EngineKind::kMarker}},
  };
  return flags;
}

std::string AnalysisFlags::ParamList() {
  std::string out = "\nEvery engine parameter, for --param, with its default:\n";
  std::string line;
  for (char c : DescribeEngineOptions(76)) {
    if (c == '\n') {
      out += (line.empty() ? "" : "  " + line) + "\n";
      line.clear();
    } else {
      line += c;
    }
  }
  out.pop_back();  // the help text adds the paragraph's last newline
  return out;
}

void AnalysisFlags::Register(ArgParser& p) {
  p.String("--engine", &engine_name_, "NAME", "bgsub, lk, marker or pose (required)");
  p.String("--background", &o_->background_path, "BG.png", "bgsub/lk: the empty scene image");
  p.Int("--background-frames", &o_->background_frames, "K",
        "bgsub/lk: estimate the background from frames [0, K) of the video", 1, 1000000);
  p.String("--arm-length", &o_->arm_length_path, "ARM.png",
           "bgsub: straight horizontal arm at zero yaw (gives b)");
  p.Int("--start", &o_->start, "F",
        "bgsub/lk: first standstill frame; pose: first frame (default 0; a camera or stream "
        "drops F frames)",
        0);
  p.Int("--standstill-frames", &standstill_, "N", "bgsub/lk: standstill length (default 60)", 1,
        100000);
  p.Int("--threshold", &threshold_, "T", "bgsub: grey-level difference threshold (default 45)", 1,
        254);
  p.Custom("--shoulder", "X,Y", "bgsub/lk: fixed shoulder position in pixels",
           [&](const std::string& v) {
             const std::string e = ParsePointArg(v, &shoulder_);
             if (e.empty()) o_->shoulder_px = shoulder_;
             return e;
           });
  p.Custom("--elbow", "X,Y", "lk: the elbow in frame F (with --shoulder and --wrist)",
           [&](const std::string& v) {
             const std::string e = ParsePointArg(v, &elbow_);
             if (e.empty()) o_->elbow_px = elbow_;
             return e;
           });
  p.Custom("--wrist", "X,Y", "lk: the wrist in frame F (with --shoulder and --elbow)",
           [&](const std::string& v) {
             const std::string e = ParsePointArg(v, &wrist_);
             if (e.empty()) o_->wrist_px = wrist_;
             return e;
           });
  p.Custom("--roi", "X,Y,W,H", "bgsub/lk: analyse only this rectangle", [&](const std::string& v) {
    const std::string e = ParseRectArg(v, &roi_);
    if (e.empty()) o_->roi = roi_;
    return e;
  });
  p.Double("--initial-upper", &o_->engine.lk.initial_upper_deg, "DEG",
           "lk: upper-arm direction at the start (default -90)");
  p.Double("--initial-fore", &o_->engine.lk.initial_fore_deg, "DEG",
           "lk: forearm direction at the start (default -90)");
  p.String("--reference", &o_->reference_path, "REF.png",
           "marker: the joint at zero yaw and zero bend");
  p.Int("--low", &o_->engine.marker.low, "L",
        "marker: lower grey level of the markers (default 20)", 0, 255);
  p.Int("--high", &o_->engine.marker.high, "H",
        "marker: upper grey level of the markers (default 80)", 0, 255);
  p.Double("--fov", &o_->engine.marker.fov_deg, "D",
           "marker: the camera's horizontal field of view, degrees (default 60; 0: a distant "
           "camera)");
  p.String("--side", &side_name_, "left|right",
           "pose, lk --auto-calibrate: the person's own arm (default: the better seen)");
  p.String("--model", &o_->model_dir, "DIR",
           "pose, lk --auto-calibrate: the folder holding movenet-lightning.json and .bin");
  p.Flag("--auto-calibrate", &o_->auto_calibrate,
         "lk: the shoulder, elbow and wrist in frame F from the pose network");
  p.Flag("--thesis", &thesis_, "run the thesis method only, without the improvements");
  p.Custom("--param", "ENGINE.KEY=VALUE",
           "any engine parameter listed above; repeatable, applied after the other flags",
           [&](const std::string& v) {
             EngineOptions probe;
             const Status st = SetEngineOption(v, &probe);
             if (st) params_.push_back(v);
             return st ? std::string() : st.message();
           });
}

std::optional<int> AnalysisFlags::CheckEngine(const ArgParser& p) const {
  if (engine_name_.empty()) return p.UsageError("missing --engine (bgsub, lk, marker or pose)");
  if (!ParseEngineKind(engine_name_, &o_->engine.kind)) {
    return p.UsageError("--engine: unknown engine '" + engine_name_ +
                        "' (bgsub, lk, marker or pose)");
  }
  return std::nullopt;
}

std::optional<int> AnalysisFlags::Finish(const ArgParser& p) {
  for (const auto& [flag, engines] : EngineFlags()) {
    if (p.Given(flag) && !engines.count(o_->engine.kind)) {
      return p.UsageError(flag + " is not used by --engine " + engine_name_);
    }
  }
  for (const std::string& assignment : params_) {
    if (assignment.rfind(engine_name_ + ".", 0) != 0) {
      return p.UsageError("--param " + assignment + " is not used by --engine " + engine_name_);
    }
  }
  if (p.Given("--side")) {
    PoseSide side = PoseSide::kAuto;
    if (!ParsePoseSide(side_name_, &side)) {
      return p.UsageError("--side '" + side_name_ + "': expected left or right (the person's own)");
    }
    o_->engine.pose.side = side;
    o_->calibrate_side = side;
  }
  if (o_->engine.kind != EngineKind::kPose && !o_->auto_calibrate &&
      (p.Given("--side") || p.Given("--model"))) {
    return p.UsageError(std::string(p.Given("--side") ? "--side" : "--model") +
                        " is used by --engine " + engine_name_ + " only with --auto-calibrate");
  }
  if (o_->engine.kind == EngineKind::kLk && (p.Given("--shoulder") || o_->auto_calibrate) &&
      p.Given("--standstill-frames")) {
    return p.UsageError(
        "--standstill-frames is not used by --engine lk with --shoulder: frame F is the starting "
        "posture and gets a row");
  }
  if (p.Given("--elbow") && (p.Given("--initial-upper") || p.Given("--initial-fore"))) {
    return p.UsageError(
        std::string(p.Given("--initial-upper") ? "--initial-upper" : "--initial-fore") +
        " cannot be given with --elbow and --wrist: the clicked joints give the "
        "starting directions");
  }
  o_->engine.bgsub.standstill_frames = standstill_;
  o_->engine.lk.standstill_frames = standstill_;
  o_->engine.bgsub.threshold = threshold_;
  if (o_->background_frames > 0) o_->engine.bgsub.background_frames = o_->background_frames;
  o_->engine.bgsub.thesis_mode = thesis_;
  o_->engine.lk.thesis_mode = thesis_;
  o_->engine.marker.thesis_mode = thesis_;
  // An explicit grey window is used as given; otherwise the marker engine may shift it when the
  // reference's markers do not show in 20..80 (other illumination).
  if (p.Given("--low") || p.Given("--high")) o_->engine.marker.auto_window = false;
  for (const std::string& assignment : params_) SetEngineOption(assignment, &o_->engine);
  if (Status st = o_->Check(); !st) return p.UsageError(Worded(st));

  return std::nullopt;
}

}  // namespace armmimic::cli
