// The parameter tables of the engines. One line per option: kind, key, pointer to the
// member, documented default, range, label and help. The engines test checks each table against
// its struct (same defaults, every field listed, ranges that pass Check()).
#include "armmimic/engines/option_fields.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/text.h"

namespace armmimic {
namespace {

// Builds one OptionField; the chained calls set what most fields leave at its default.
template <typename O>
struct Row {
  OptionField<O> f;
  Row& Main() { return Group(OptionGroup::kMain); }
  Row& Input() { return Group(OptionGroup::kInput); }
  Row& Group(OptionGroup g) {
    f.group = g;
    return *this;
  }
  Row& Step(double step) {
    f.step = step;
    return *this;
  }
  // Check() wants this field <= (strict: <) the field `key`.
  Row& Below(const char* key, bool strict = false) {
    f.below = key;
    f.strictly_below = strict;
    return *this;
  }
  operator OptionField<O>() const { return f; }  // NOLINT: rows convert into the table
};

template <typename O>
Row<O> Base(const char* key, OptionKind kind, double def, double lo, double hi, const char* label,
            const char* help) {
  Row<O> r;
  r.f.key = key;
  r.f.kind = kind;
  r.f.default_value = def;
  r.f.min = lo;
  r.f.max = hi;
  r.f.label = label;
  r.f.help = help;
  return r;
}

template <typename O>
Row<O> Int(const char* key, int O::*m, int def, int lo, int hi, const char* label,
           const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kInt, def, lo, hi, label, help);
  r.f.get = [m](const O& o) { return static_cast<double>(o.*m); };
  r.f.set = [m](O& o, double v) { o.*m = static_cast<int>(std::lround(v)); };
  return r;
}

template <typename O>
Row<O> Real(const char* key, double O::*m, double def, double lo, double hi, int decimals,
            const char* label, const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kDouble, def, lo, hi, label, help);
  r.f.decimals = decimals;
  r.f.step = std::pow(10.0, -std::max(0, decimals - 1));
  r.f.get = [m](const O& o) { return o.*m; };
  r.f.set = [m](O& o, double v) { o.*m = v; };
  return r;
}

template <typename O>
Row<O> Bool(const char* key, bool O::*m, bool def, const char* label, const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kBool, def ? 1 : 0, 0, 1, label, help);
  r.f.get = [m](const O& o) { return o.*m ? 1.0 : 0.0; };
  r.f.set = [m](O& o, double v) { o.*m = v != 0; };
  return r;
}

template <typename O, typename E>
Row<O> Enum(const char* key, E O::*m, E def, const std::vector<std::string>& choices,
            const char* label, const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kEnum, static_cast<int>(def), 0,
                     static_cast<double>(choices.size()) - 1, label, help);
  r.f.choices = choices;
  r.f.get = [m](const O& o) { return static_cast<double>(static_cast<int>(o.*m)); };
  r.f.set = [m](O& o, double v) { o.*m = static_cast<E>(static_cast<int>(std::lround(v))); };
  return r;
}

using B = BgsubOptions;
using L = LkOptions;
using M = MarkerOptions;
using P = PoseOptions;

}  // namespace

const std::vector<OptionField<BgsubOptions>>& BgsubOptionFields() {
  static const std::vector<OptionField<B>> fields = {
      Int<B>("threshold", &B::threshold, 45, 1, 254, "Threshold",
             "grey-level difference from the background (5.2.2, 5.2.4)")
          .Main(),
      Int<B>("background_frames", &B::background_frames, 45, 1, 100000, "Background frames",
             "frames averaged into the background image (5.2.1)")
          .Input(),
      Int<B>("standstill_frames", &B::standstill_frames, 60, 1, 100000, "Standstill frames",
             "frames averaged into the standstill image (5.2.2)")
          .Main(),
      Real<B>("straight_ratio", &B::straight_ratio, 0.30, 0.10, 0.95, 2, "Straight-arm ratio",
              "defect depth below this share of the semi-major axis: a straight arm")
          .Main(),
      Int<B>("closing_size", &B::closing_size, 5, 0, 51, "Closing size",
             "morphological closing kernel, pixels (0 or 1: none)")
          .Main(),
      Int<B>("min_arm_area_px", &B::min_arm_area_px, 40, 1, 100000, "Minimum arm area",
             "a smaller moving region is no arm (lost), pixels"),
      Real<B>("shoulder_height", &B::shoulder_height, 0.6, 0, 1, 3, "Shoulder height",
              "shoulder at this share of the body box height, from its bottom (5.2.2)"),
      Real<B>("shoulder_side", &B::shoulder_side, 1.0 / 6, 0, 0.5, 3, "Shoulder inset",
              "shoulder at this share of the body box width in from the moving arm's side"),
      Bool<B>("thesis_mode", &B::thesis_mode, false, "Thesis path only",
              "none of the improvements below")
          .Main(),
      Bool<B>("compensate_drift", &B::compensate_drift, true, "Compensate brightness drift",
              "subtract the global brightness drift before thresholding"),
      Bool<B>("color_difference", &B::color_difference, true, "Colour difference",
              "threshold the largest channel difference, not the grey one"),
      Bool<B>("reject_shadow", &B::reject_shadow, true, "Reject shadows",
              "drop pixels that are the background darkened with its hue kept"),
      Bool<B>("reject_head", &B::reject_head, true, "Ignore the head",
              "ignore movement above the shoulders, between them"),
      Real<B>("near_shoulder", &B::near_shoulder, 0.5, 0.05, 10, 2, "Blob near shoulder",
              "keep the blob nearest the shoulder, within this times the arm length"),
      Bool<B>("two_line_split", &B::two_line_split, true, "Two-line split",
              "refine the upper/fore split by the distance to the two segments"),
      Bool<B>("extent_yaw", &B::extent_yaw, true, "Yaw from reach",
              "yaw from the arm's reach along its axis, not the ellipse"),
      Real<B>("bend_hysteresis", &B::bend_hysteresis, 0.05, 0, 0.09, 3, "Bend hysteresis",
              "straight/bent switch at the straight-arm ratio -/+ this")
          .Below("straight_ratio", true),
      Bool<B>("shoulder_from_arm_length", &B::shoulder_from_arm_length, true,
              "Shoulder from arm-length image",
              "shoulder where the horizontal arm of the arm-length image meets the body"),
      Bool<B>("rest_pose", &B::rest_pose, true, "Rest pose",
              "an unmoved arm is at its standstill pose, not lost"),
      Real<B>("rest_deg", &B::rest_deg, -90, -180, 180, 1, "Rest direction",
              "the standstill pose's direction, degrees (arms hanging: -90)"),
      Real<B>("upper_arm_fraction", &B::upper_arm_fraction, 0.45, 0.11, 0.89, 2,
              "Upper-arm fraction", "upper arm / shoulder-to-fingertip reach"),
      Bool<B>("upper_from_person", &B::upper_from_person, true, "Upper arm from person mask",
              "an upper arm near rest is fitted in the person mask with the torso removed"),
      Real<B>("max_speed_deg_s", &B::max_speed_deg_s, 600, 10, 100000, 0, "Fastest arm turn",
              "a segment turning faster than this, degrees a second, is a wrong pick: lost"),
      Real<B>("min_support", &B::min_support, 0.5, 0, 1, 2, "Minimum support",
              "a fitted arm with less of its length on the person mask (0..1) is lost"),
      Int<B>("confirm_frames", &B::confirm_frames, 3, 1, 1000, "Frames to re-acquire",
             "agreeing frames before a new pick is trusted (also at the start)"),
  };
  return fields;
}

const std::vector<OptionField<LkOptions>>& LkOptionFields() {
  static const std::vector<OptionField<L>> fields = {
      Int<L>("standstill_frames", &L::standstill_frames, 60, 1, 100000, "Standstill frames",
             "frames averaged into the standstill image (6.1)")
          .Main(),
      Int<L>("body_threshold", &L::body_threshold, 45, 0, 255, "Body threshold",
             "grey-level difference standstill vs background that makes the body box"),
      Real<L>("shoulder_height", &L::shoulder_height, 0.6, 0, 1, 3, "Shoulder height",
              "shoulder at this share of the body box height, from its bottom"),
      Real<L>("shoulder_inset", &L::shoulder_inset, 1.0 / 6, 0, 0.5, 3, "Shoulder inset",
              "shoulder at this share of the body box width in from the arm's side"),
      Real<L>("anchored_shoulder_height", &L::anchored_shoulder_height, 0.7, 0, 1, 3,
              "Anchored shoulder height", "the anchored path's body-box shoulder height"),
      Real<L>("anchored_shoulder_inset", &L::anchored_shoulder_inset, 0.09, 0, 0.5, 3,
              "Anchored shoulder inset", "the anchored path's body-box shoulder inset"),
      Enum<L>("side", &L::side, LkArmSide::kAuto, {"auto", "left", "right"}, "Arm side",
              "side of the body box the moving arm is on, as seen on screen"),
      Real<L>("initial_upper_deg", &L::initial_upper_deg, -90, -180, 180, 1, "Initial upper arm",
              "upper-arm direction at the start, degrees")
          .Main(),
      Real<L>("initial_fore_deg", &L::initial_fore_deg, -90, -180, 180, 1, "Initial forearm",
              "forearm direction at the start, degrees")
          .Main(),
      Int<L>("max_corners", &L::max_corners, 300, 4, 10000, "Max. corners",
             "strongest Shi-Tomasi corners kept per detection (6.2.1)"),
      Real<L>("quality_level", &L::quality_level, 0.01, 0.0001, 1, 4, "Corner quality",
              "a corner's eigenvalue is at least this share of the strongest one"),
      Real<L>("min_distance_px", &L::min_distance_px, 5, 0, 1000, 1, "Corner distance",
              "minimum distance between corners, pixels"),
      Int<L>("block_size", &L::block_size, 3, 3, 31, "Eigenvalue block",
             "eigenvalue neighbourhood, pixels"),
      Int<L>("window_px", &L::window_px, 15, 5, 101, "LK window",
             "Lucas-Kanade search window, pixels, odd (6.2.2)")
          .Step(2),
      Int<L>("pyramid_levels", &L::pyramid_levels, 3, 0, 8, "Pyramid levels",
             "pyramid levels above the full image"),
      Int<L>("max_iterations", &L::max_iterations, 20, 1, 1000, "LK iterations",
             "iterations per pyramid level"),
      Real<L>("epsilon", &L::epsilon, 0.03, 0.001, 10, 3, "LK epsilon",
              "stop when the update is smaller than this, pixels"),
      Real<L>("motion_threshold_px", &L::motion_threshold_px, 1.0, 0, 100, 2, "Motion threshold",
              "a feature that moved more than this is on the arm, pixels (6.2.3)"),
      Int<L>("still_frames_drop", &L::still_frames_drop, 10, 0, 100000, "Drop still features after",
             "a feature still for more than this many frames is dropped")
          .Main(),
      Bool<L>("thesis_mode", &L::thesis_mode, false, "Thesis path only",
              "2-means and summed increments only, none of the improvements")
          .Main(),
      Bool<L>("use_bar", &L::use_bar, true, "Sleeve bars", "anchor each part on its sleeve colour"),
      Real<L>("bar_search_deg", &L::bar_search_deg, 30, 1, 90, 1, "Bar search",
              "bars searched this far around the features' estimate, degrees"),
      Real<L>("bar_min_score", &L::bar_min_score, 0.4, -1, 1, 2, "Bar minimum score",
              "weaker bars (part in front of the body) are not used"),
      Bool<L>("refine_shoulder", &L::refine_shoulder, true, "Refine shoulder",
              "refine a body-box shoulder from the sleeve's lines"),
      Real<L>("upper_fraction", &L::upper_fraction, 0.53, 0.2, 0.8, 2, "Upper-arm fraction",
              "upper arm / shoulder-to-wrist, the elbow prior"),
      Real<L>("forward_backward_px", &L::forward_backward_px, 1.0, 0, 100, 2,
              "Forward-backward check",
              "drop a track whose backward track misses by more, pixels "
              "(0: off)"),
      Real<L>("confirm_motion_px", &L::confirm_motion_px, 4.0, 0, 1000, 1, "Confirm motion",
              "a feature joins the fit once the model moved it this far, pixels"),
      Real<L>("outlier_px", &L::outlier_px, 3.0, 0.1, 1000, 1, "Outlier residual",
              "residual above which a feature is an outlier, pixels"),
      Int<L>("outlier_frames_drop", &L::outlier_frames_drop, 3, 0, 100000, "Drop outliers after",
             "consecutive outlier frames before a feature is dropped"),
      Int<L>("reseed_interval", &L::reseed_interval, 5, 1, 100000, "Re-seed interval",
             "frames between re-seeding corners on the arm"),
      Int<L>("min_part_features", &L::min_part_features, 12, 0, 10000, "Min. part features",
             "re-seed at once when a part has fewer features"),
      Real<L>("arm_width_ratio", &L::arm_width_ratio, 0.14, 0.01, 1, 3, "Arm band width",
              "half-width of the arm band / arm length (re-seed mask)"),
      Real<L>("joint_weight", &L::joint_weight, 1.0, 0, 1000, 2, "Joint weight",
              "weight of the shoulder/elbow pseudo-feature in the fits"),
      Real<L>("prior_weight", &L::prior_weight, 2, 0, 1000, 2, "Prior weight",
              "the previous pose votes like this many features at a part's end"),
      Real<L>("inlier_deg", &L::inlier_deg, 8, 0.5, 90, 1, "Inlier angle",
              "a feature whose implied direction is this far off is ignored, degrees"),
      Real<L>("bend_for_elbow_deg", &L::bend_for_elbow_deg, 20, 0, 180, 1, "Bend to learn elbow",
              "the elbow is located only when bent this much, degrees"),
      Real<L>("max_bend_deg", &L::max_bend_deg, 150, 90, 180, 1, "Largest bend",
              "the forearm's sleeve is not searched folded further back onto the upper arm, "
              "degrees"),
      Real<L>("max_speed_deg_s", &L::max_speed_deg_s, 600, 10, 100000, 0, "Fastest arm turn",
              "a segment turning faster than this, degrees a second, is a wrong lock: lost"),
      Real<L>("min_support", &L::min_support, 0.3, 0, 1, 2, "Minimum support",
              "a pose backed by less sleeve and feature evidence (0..1) is lost"),
      Int<L>("confirm_frames", &L::confirm_frames, 3, 1, 1000, "Frames to re-acquire",
             "agreeing frames before the arm is trusted again after a rejected jump"),
      Real<L>("shoulder_sway", &L::shoulder_sway, 0.05, 0, 1, 2, "Shoulder sway",
              "with clicked joints: how far the body's features may move the shoulder from the "
              "click, a share of the upper arm (0: kept at the click)"),
  };
  return fields;
}

const std::vector<OptionField<MarkerOptions>>& MarkerOptionFields() {
  static const std::vector<OptionField<M>> fields = {
      Int<M>("median_size", &M::median_size, 5, 1, 31, "Median window",
             "median filter window, odd (4.2.1)")
          .Step(2)
          .Main(),
      Int<M>("low", &M::low, 20, 0, 255, "Low threshold", "darkest marker grey level (4.2.2)")
          .Below("high")
          .Main(),
      Int<M>("high", &M::high, 80, 0, 255, "High threshold", "brightest marker grey level (4.2.2)")
          .Main(),
      Int<M>("flood_range", &M::flood_range, 10, 0, 255, "Flood range",
             "flood-fill value range (+/-) around the seed (4.2.3)")
          .Main(),
      Int<M>("min_area", &M::min_area, 10, 1, 100000, "Min. area",
             "smallest marker area, pixels at 320x240 (4.2.4)")
          .Below("max_area"),
      Int<M>("max_area", &M::max_area, 200, 1, 100000, "Max. area",
             "largest marker area, pixels at 320x240 (4.2.4)"),
      Real<M>("min_aspect", &M::min_aspect, 0.2, 0.01, 100, 2, "Min. aspect",
              "smallest bounding-box width / height")
          .Below("max_aspect"),
      Real<M>("max_aspect", &M::max_aspect, 3.0, 0.01, 100, 2, "Max. aspect",
              "largest bounding-box width / height"),
      Real<M>("min_fill", &M::min_fill, 0.7, 0, 1, 2, "Min. fill",
              "smallest area / bounding-box area"),
      Bool<M>("auto_window", &M::auto_window, true, "Shift the grey window",
              "when [low, high] misses the reference's markers, use the nearest window that "
              "shows them"),
      Bool<M>("thesis_mode", &M::thesis_mode, false, "Thesis path only",
              "three largest survivors, box centres, yaw = acos(n/N)")
          .Main(),
      Real<M>("fov_deg", &M::fov_deg, 60, 0, 140, 1, "Camera field of view",
              "the camera's horizontal field of view, degrees (0: a distant camera)")
          .Main(),
      Real<M>("max_marker_turn_deg", &M::max_marker_turn_deg, 74, 1, 89, 1, "Max. marker turn",
              "a view is read only when a lower marker faces the camera within this, degrees"),
      Real<M>("agreement_sigmas", &M::agreement_sigmas, 4, 0.5, 100, 1, "Marker agreement",
              "lost when the two lower markers' yaws differ by more than this many expected "
              "spreads (plus 1 degree)"),
      Real<M>("max_upper_turn_deg", &M::max_upper_turn_deg, 60, 1, 89, 1, "Max. upper turn",
              "the bend is measured while the upper marker faces the camera within this, "
              "degrees"),
      Real<M>("upper_tolerance", &M::upper_tolerance, 0.06, 0.01, 1, 2, "Upper marker tolerance",
              "how far (relative to e) the upper marker may lie from where the model puts it"),
  };
  return fields;
}

const std::vector<OptionField<PoseOptions>>& PoseOptionFields() {
  static const std::vector<OptionField<P>> fields = {
      Enum<P>("side", &P::side, PoseSide::kAuto, {"auto", "left", "right"}, "Arm",
              "the person's own arm (auto: the better seen over the first second)")
          .Main(),
      Real<P>("min_score", &P::min_score, 0.4, 0, 1, 2, "Minimum keypoint score",
              "a shoulder, elbow or wrist scored lower is not seen: lost")
          .Main(),
      Real<P>("min_length_ratio", &P::min_length_ratio, 0.55, 0, 1, 2, "Minimum segment length",
              "a segment shorter than this share of its usual length points at the camera: lost")
          .Main(),
      Real<P>("crop_score", &P::crop_score, 0.2, 0, 1, 2, "Crop keypoint score",
              "keypoints above this score place the next frame's crop"),
      Real<P>("arm_crop", &P::arm_crop, 1.5, 0, 4, 2, "Arm look size",
              "a second look through a square this many times the upper body's extent gives the "
              "directions (0: one look)"),
      Real<P>("max_disagreement_deg", &P::max_disagreement_deg, 15, 1, 180, 1,
              "Maximum disagreement",
              "a segment whose direction differs more between the looks "
              "(degrees) is lost"),
      Bool<P>("flip", &P::flip, false, "Mirrored look",
              "also look at the mirrored crop and average (one more inference per frame)"),
  };
  return fields;
}

namespace {

template <typename O>
std::string ValueText(const OptionField<O>& f, double v) {
  switch (f.kind) {
    case OptionKind::kBool:
      return v != 0 ? "true" : "false";
    case OptionKind::kEnum:
      return f.choices[static_cast<std::size_t>(v)];
    case OptionKind::kInt:
      return std::to_string(static_cast<long long>(std::lround(v)));
    case OptionKind::kDouble:
      break;
  }
  std::string text = FormatNumber(v, 6);  // shortest form: 0.300000 -> 0.3
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

template <typename O>
std::string Accepts(const OptionField<O>& f) {
  switch (f.kind) {
    case OptionKind::kBool:
      return "true or false";
    case OptionKind::kEnum: {
      std::string names;
      for (const std::string& c : f.choices) names += (names.empty() ? "" : ", ") + c;
      return "one of " + names;
    }
    case OptionKind::kInt:
      return "a whole number in [" + ValueText(f, f.min) + ", " + ValueText(f, f.max) + "]";
    case OptionKind::kDouble:
      break;
  }
  return "a number in [" + ValueText(f, f.min) + ", " + ValueText(f, f.max) + "]";
}

template <typename O>
Status SetField(const std::vector<OptionField<O>>& fields, const std::string& engine,
                const std::string& key, const std::string& text, O* o) {
  const OptionField<O>* f = FindOptionField(fields, key);
  if (!f) {
    std::string keys;
    for (const auto& g : fields) keys += (keys.empty() ? "" : ", ") + g.key;
    return Status::Error("'" + engine + "." + key + "' is no " + engine + " parameter (" + keys +
                         ")");
  }
  const std::string name = engine + "." + key;
  double v = 0;
  bool ok = false;
  if (f->kind == OptionKind::kBool) {
    std::string t;
    for (char c : text) t += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    ok = t == "true" || t == "on" || t == "1" || t == "false" || t == "off" || t == "0";
    v = (t == "true" || t == "on" || t == "1") ? 1 : 0;
  } else if (f->kind == OptionKind::kEnum) {
    const auto it = std::find(f->choices.begin(), f->choices.end(), text);
    ok = it != f->choices.end();
    v = static_cast<double>(it - f->choices.begin());
  } else {
    ok = ParseFiniteDouble(text, &v) && v >= f->min && v <= f->max &&
         (f->kind != OptionKind::kInt || v == std::floor(v));
  }
  if (!ok) return Status::Error(name + " '" + text + "': expected " + Accepts(*f));
  f->set(*o, v);
  return Status::Ok();
}

template <typename O>
void Describe(const std::vector<OptionField<O>>& fields, const std::string& engine, int width,
              std::string* out) {
  const O defaults;
  std::string line;
  for (const auto& f : fields) {
    const std::string item = engine + "." + f.key + "=" + ValueText(f, f.get(defaults));
    if (!line.empty() && static_cast<int>(line.size() + 1 + item.size()) > width) {
      *out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + item;
  }
  if (!line.empty()) *out += line + "\n";
}

}  // namespace

Status SetEngineOption(const std::string& assignment, EngineOptions* o) {
  const auto eq = assignment.find('=');
  const auto dot = assignment.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq) {
    return Status::Error("'" + assignment +
                         "': expected ENGINE.KEY=VALUE, e.g. lk.max_corners=200");
  }
  const std::string engine = assignment.substr(0, dot);
  const std::string key = assignment.substr(dot + 1, eq - dot - 1);
  const std::string value = Trim(assignment.substr(eq + 1));
  if (engine == "bgsub") return SetField(BgsubOptionFields(), engine, key, value, &o->bgsub);
  if (engine == "lk") return SetField(LkOptionFields(), engine, key, value, &o->lk);
  if (engine == "marker") return SetField(MarkerOptionFields(), engine, key, value, &o->marker);
  if (engine == "pose") return SetField(PoseOptionFields(), engine, key, value, &o->pose);
  return Status::Error("'" + assignment + "': unknown engine '" + engine +
                       "' (bgsub, lk, marker or pose)");
}

namespace {

// The exact text of each value (doubles in their shortest round-trip form), as
// SetEngineOption reads it back.
template <typename O>
void AppendValues(const std::vector<OptionField<O>>& fields, const std::string& engine, const O& o,
                  bool changed_only, std::vector<std::pair<std::string, std::string>>* out) {
  const O defaults;
  for (const auto& f : fields) {
    const double v = f.get(o);
    if (changed_only && v == f.get(defaults)) continue;
    std::string text;
    if (f.kind == OptionKind::kDouble) {
      char buf[64];
      const auto r = std::to_chars(buf, buf + sizeof(buf), v);
      text.assign(buf, r.ptr);
    } else {
      text = ValueText(f, v);
    }
    out->emplace_back(engine + "." + f.key, text);
  }
}

std::vector<std::pair<std::string, std::string>> EngineValues(const EngineOptions& o,
                                                              bool changed_only) {
  std::vector<std::pair<std::string, std::string>> out;
  switch (o.kind) {
    case EngineKind::kBgsub:
      AppendValues(BgsubOptionFields(), "bgsub", o.bgsub, changed_only, &out);
      break;
    case EngineKind::kLk:
      AppendValues(LkOptionFields(), "lk", o.lk, changed_only, &out);
      break;
    case EngineKind::kMarker:
      AppendValues(MarkerOptionFields(), "marker", o.marker, changed_only, &out);
      break;
    case EngineKind::kPose:
      AppendValues(PoseOptionFields(), "pose", o.pose, changed_only, &out);
      break;
  }
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> ChangedEngineOptions(const EngineOptions& o) {
  return EngineValues(o, true);
}

std::vector<std::pair<std::string, std::string>> EngineOptionValues(const EngineOptions& o) {
  return EngineValues(o, false);
}

std::string DescribeEngineOptions(int width) {
  std::string out;
  Describe(BgsubOptionFields(), "bgsub", width, &out);
  out += "\n";
  Describe(LkOptionFields(), "lk", width, &out);
  out += "\n";
  Describe(MarkerOptionFields(), "marker", width, &out);
  out += "\n";
  Describe(PoseOptionFields(), "pose", width, &out);
  return out;
}

}  // namespace armmimic
