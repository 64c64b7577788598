// The analysis flags of analyze and mimic (analysis_flags.h).
// Length: Register is one call per flag, a flat list in --help order.
#include "analysis_flags.h"
#include "flag_for_key.h"
#include "table_flags.h"

#include <map>
#include <set>
#include <utility>

#include "armmimic/engines/option_fields.h"

namespace armmimic::cli {

const std::map<std::string, std::set<EngineKind>>& AnalysisFlags::EngineFlags() {
  static const std::map<std::string, std::set<EngineKind>> flags = {
      {"--background", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kHybrid}},
      {"--background-frames", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kHybrid}},
      {"--arm-length", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kHybrid}},
      {"--start", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kPose, EngineKind::kHybrid}},
      {"--standstill-frames", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kHybrid}},
      {"--threshold", {EngineKind::kBgsub, EngineKind::kHybrid}},
      {"--shoulder", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kHybrid}},
      {"--elbow", {EngineKind::kLk, EngineKind::kHybrid}},
      {"--wrist", {EngineKind::kLk, EngineKind::kHybrid}},
      {"--roi", {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kPose, EngineKind::kHybrid}},
      {"--side", {EngineKind::kPose, EngineKind::kLk, EngineKind::kHybrid}},
      {"--network", {EngineKind::kPose}},
      {"--model", {EngineKind::kPose, EngineKind::kLk, EngineKind::kHybrid}},
      {"--auto-calibrate", {EngineKind::kLk, EngineKind::kHybrid}},
      {"--initial-upper", {EngineKind::kLk, EngineKind::kHybrid}},
      {"--initial-fore", {EngineKind::kLk, EngineKind::kHybrid}},
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

namespace {

// The row `key` of an engine's table (a row the table must have).
template <typename O>
const OptionField<O>& Row(const std::vector<OptionField<O>>& fields, const char* key) {
  return *FindOptionField(fields, key);
}

// Which engines read a flag, before the row's help.
RowFlagWords For(const char* engines, const char* metavar = "") {
  RowFlagWords w;
  w.prefix = std::string(engines) + ": ";
  w.metavar = metavar;
  return w;
}

}  // namespace

void AnalysisFlags::Register(ArgParser& p, bool both_arms) {
  AnalysisOptions& f = f_;
  EngineOptions& e = f.engine;
  p.String("--engine", &engine_name_, "NAME", "bgsub, lk, marker, pose or hybrid (required)");
  p.String("--background", &f.background_path, "BG.png", "bgsub/lk/hybrid: the empty scene image");
  p.Int("--background-frames", &f.background_frames, "K",
        "bgsub/lk/hybrid: estimate the background from frames [0, K) of the video", 1, 1000000);
  p.String("--arm-length", &f.arm_length_path, "ARM.png",
           "bgsub: straight horizontal arm at zero yaw (gives b); lk/hybrid: with the "
           "standstill, gives the joints");
  p.Int("--start", &f.start, "F",
        "bgsub/lk/hybrid: first standstill frame; pose: first frame (default 0; a camera or stream "
        "drops F frames)",
        0);
  {
    // One flag for the standstill of both engines; their rows agree (OptionTablesTest).
    const auto& bgsub = Row(BgsubOptionFields(), "standstill_frames");
    const auto& lk = Row(LkOptionFields(), "standstill_frames");
    p.Custom(bgsub.flag, RowMetavar(bgsub), RowHelp(bgsub, For("bgsub/lk/hybrid")),
             [&bgsub, &lk, &e](const std::string& v) {
               const std::string error = ParseRowValue(bgsub, v, &e.bgsub);
               return error.empty() ? ParseRowValue(lk, v, &e.lk) : error;
             });
  }
  AddRowFlag(p, Row(BgsubOptionFields(), "threshold"), &e.bgsub, For("bgsub/hybrid"));
  auto point = [](std::optional<cv::Point2d>* out) {
    return [out](const std::string& v) {
      cv::Point2d pt;
      const std::string e = ParsePointArg(v, &pt);
      if (e.empty()) *out = pt;
      return e;
    };
  };
  p.Custom("--shoulder", "X,Y", "bgsub/lk/hybrid: fixed shoulder position in pixels",
           point(&f.shoulder_px));
  p.Custom("--elbow", "X,Y", "lk/hybrid: the elbow in frame F (with --shoulder and --wrist)",
           point(&f.elbow_px));
  p.Custom("--wrist", "X,Y", "lk/hybrid: the wrist in frame F (with --shoulder and --elbow)",
           point(&f.wrist_px));
  p.Custom("--roi", "X,Y,W,H", "bgsub/lk/hybrid: analyse only this rectangle",
           [&f](const std::string& v) {
             cv::Rect roi;
             const std::string e = ParseRectArg(v, &roi);
             if (e.empty()) f.roi = roi;
             return e;
           });
  AddRowFlag(p, Row(LkOptionFields(), "initial_upper_deg"), &e.lk, For("lk/hybrid"));
  AddRowFlag(p, Row(LkOptionFields(), "initial_fore_deg"), &e.lk, For("lk/hybrid"));
  p.String("--reference", &f.reference_path, "REF.png",
           "marker: the joint at zero yaw and zero bend");
  AddRowFlag(p, Row(MarkerOptionFields(), "low"), &e.marker, For("marker"));
  AddRowFlag(p, Row(MarkerOptionFields(), "high"), &e.marker, For("marker"));
  AddRowFlag(p, Row(MarkerOptionFields(), "fov_deg"), &e.marker, For("marker"));
  {
    // Read after the engine is known (CheckFor): lk takes it only with --auto-calibrate.
    const auto& side = Row(PoseOptionFields(), "side");
    RowFlagWords words = For("pose, lk/hybrid --auto-calibrate (left or right)");
    if (!both_arms)
      words.help = "the person's own arm (auto: the better seen over the first second)";
    p.String(side.flag, &side_name_, both_arms ? "left|right|both" : "left|right",
             RowHelp(side, words));
  }
  AddRowFlag(p, Row(PoseOptionFields(), "network"), &e.pose, For("pose"));
  p.String("--model", &f.model_dir, "DIR",
           "pose, lk/hybrid --auto-calibrate, hybrid with no background (the network is its "
           "second opinion): the folder holding the network's files "
           "(movenet-lightning.json and .bin; blazepose-full.json and .bin as well for "
           "--network blazepose)");
  p.Flag("--auto-calibrate", &f.auto_calibrate,
         "lk/hybrid: the shoulder, elbow and wrist in frame F from the pose network");
  p.Flag("--thesis", &thesis_, "run the thesis method only, without the improvements");
  p.Custom("--param", "ENGINE.KEY=VALUE",
           "any engine parameter listed above; repeatable, applied after the other flags",
           [this](const std::string& v) {
             EngineOptions probe;
             const Status st = SetEngineOption(v, &probe);
             if (st) params_.push_back(v);
             return st ? std::string() : st.message();
           });
}

std::optional<int> AnalysisFlags::ParseEngine(const ArgParser& p, EngineKind* kind) const {
  if (!engine_name_.empty() && !ParseEngineKind(engine_name_, kind)) {
    return p.UsageError("--engine: unknown engine '" + engine_name_ +
                        "' (bgsub, lk, marker, pose or hybrid)");
  }
  return std::nullopt;
}

std::string AnalysisFlags::CheckStartingDirections(const ArgParser& p) const {
  if (p.Given("--elbow") && (p.Given("--initial-upper") || p.Given("--initial-fore"))) {
    return std::string(p.Given("--initial-upper") ? "--initial-upper" : "--initial-fore") +
           " cannot be given with --elbow and --wrist: the clicked joints give the starting "
           "directions";
  }
  return "";
}

std::string AnalysisFlags::CheckFor(const ArgParser& p, const AnalysisOptions& o) const {
  const std::string engine = EngineName(o.engine.kind);
  for (const auto& [flag, engines] : EngineFlags()) {
    if (p.Given(flag) && !engines.count(o.engine.kind)) {
      return flag + " is not used by --engine " + engine;
    }
  }
  for (const std::string& assignment : params_) {
    const auto prefixed = [&](const char* name) {
      return assignment.rfind(std::string(name) + ".", 0) == 0;
    };
    // The hybrid engine runs lk and bgsub, and takes their parameters too.
    const bool used = prefixed(engine.c_str()) || (o.engine.kind == EngineKind::kHybrid &&
                                                   (prefixed("lk") || prefixed("bgsub")));
    if (!used) return "--param " + assignment + " is not used by --engine " + engine;
  }
  PoseSide side = PoseSide::kAuto;
  if (p.Given("--side") && !ParsePoseSide(side_name_, &side)) {
    return "--side '" + side_name_ + "': expected left, right or both (the person's own)";
  }
  if (side == PoseSide::kBoth && o.engine.kind != EngineKind::kPose) {
    return "--side both is for --engine pose only (one pass of the network gives both arms); "
           "--engine " +
           engine + " takes left or right";
  }
  const bool auto_calibrate = o.auto_calibrate || f_.auto_calibrate;
  // The hybrid engine with no empty room takes the network as its second opinion.
  const bool model_used =
      o.engine.kind == EngineKind::kPose || o.engine.kind == EngineKind::kHybrid || auto_calibrate;
  if ((o.engine.kind != EngineKind::kPose && !auto_calibrate && p.Given("--side")) ||
      (!model_used && p.Given("--model"))) {
    return std::string(p.Given("--side") ? "--side" : "--model") + " is used by --engine " +
           engine + " only with --auto-calibrate";
  }
  if (o.engine.kind == EngineKind::kLk && (p.Given("--shoulder") || auto_calibrate) &&
      p.Given("--standstill-frames")) {
    return "--standstill-frames is not used by --engine lk with --shoulder: frame F is the "
           "starting posture and gets a row";
  }
  return CheckStartingDirections(p);
}

void AnalysisFlags::ApplyGiven(const ArgParser& p, AnalysisOptions* o) const {
  const AnalysisOptions& f = f_;
  if (p.Given("--background")) {
    o->background_path = f.background_path;
    o->background_frames = 0;
  }
  if (p.Given("--background-frames")) {
    o->background_frames = f.background_frames;
    o->background_path.clear();
  }
  if (p.Given("--arm-length")) o->arm_length_path = f.arm_length_path;
  if (p.Given("--reference")) o->reference_path = f.reference_path;
  if (p.Given("--start")) o->start = f.start;
  if (p.Given("--shoulder")) o->shoulder_px = f.shoulder_px;
  if (p.Given("--elbow")) o->elbow_px = f.elbow_px;
  if (p.Given("--wrist")) o->wrist_px = f.wrist_px;
  if (p.Given("--roi")) o->roi = f.roi;
  if (p.Given("--model")) o->model_dir = f.model_dir;
  if (f.auto_calibrate) o->auto_calibrate = true;
  if (p.Given("--side")) {
    ParsePoseSide(side_name_, &o->engine.pose.side);  // checked in CheckFor
    o->calibrate_side = o->engine.pose.side;
  }
  if (p.Given("--standstill-frames")) {
    o->engine.bgsub.standstill_frames = f.engine.bgsub.standstill_frames;
    o->engine.lk.standstill_frames = f.engine.lk.standstill_frames;
  }
  if (p.Given("--threshold")) o->engine.bgsub.threshold = f.engine.bgsub.threshold;
  if (p.Given("--network")) o->engine.pose.network = f.engine.pose.network;
  if (p.Given("--initial-upper")) o->engine.lk.initial_upper_deg = f.engine.lk.initial_upper_deg;
  if (p.Given("--initial-fore")) o->engine.lk.initial_fore_deg = f.engine.lk.initial_fore_deg;
  // An explicit grey window is used as given; otherwise the marker engine may shift it when the
  // reference's markers do not show in 20..80 (other illumination).
  if (p.Given("--low")) o->engine.marker.low = f.engine.marker.low;
  if (p.Given("--high")) o->engine.marker.high = f.engine.marker.high;
  if (p.Given("--low") || p.Given("--high")) o->engine.marker.auto_window = false;
  if (p.Given("--fov")) o->engine.marker.fov_deg = f.engine.marker.fov_deg;
  if (thesis_) {
    o->engine.bgsub.thesis_mode = true;
    o->engine.lk.thesis_mode = true;
    o->engine.marker.thesis_mode = true;
  }
  for (const std::string& assignment : params_) SetEngineOption(assignment, &o->engine);
}

std::optional<int> AnalysisFlags::Finish(const ArgParser& p, AnalysisOptions* o) const {
  if (engine_name_.empty())
    return p.UsageError("missing --engine (bgsub, lk, marker, pose or hybrid)");
  if (auto code = ParseEngine(p, &o->engine.kind)) return code;
  if (const std::string e = CheckFor(p, *o); !e.empty()) return p.UsageError(e);
  ApplyGiven(p, o);
  if (Status st = o->Check(); !st) return p.UsageError(Worded(st));
  return std::nullopt;
}

}  // namespace armmimic::cli
