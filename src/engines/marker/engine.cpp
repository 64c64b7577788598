// The marker-joint engine (thesis chapter 4, docs/marker.md): the lower part's silhouette and
// markers give the joint's signed yaw through a cylinder model, the upper marker its bend; the
// thesis path (acos(n/N), eqs. 4-2..4-5) runs under --thesis.
// Length: the reference is calibrated in up to four images (the luma, then each colour channel),
// each as taken and levelled, over the threshold windows; the tries share the engine's scratch
// images and calibration, which Process then measures with.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angle_file.h"
#include "common/engine_internal.h"
#include "marker/detect.h"
#include "marker/level.h"
#include "marker/model.h"

namespace armmimic {

namespace internal {
namespace {

std::string Fixed(double v, int decimals) { return FormatNumber(v, decimals); }

constexpr int kNarrowMedian = 3;

// A camera tilted less than this is taken as level (the limbs' lean measures the tilt to about
// 0.3 degrees, and resampling blurs the view a little); more than kLevelMaxDeg, the limbs' lean is
// not a tilt but a limb fit gone astray (LevelPitch).
constexpr double kLevelMinDeg = 1.5;
constexpr double kLevelMaxDeg = 12;
// Levelling turns the view by a few degrees, which moves the lower markers' angles on the joint
// by a fraction of a degree: two calibrations whose marker angles differ by more than this have
// placed a silhouette differently, and the levelled one is not taken.
constexpr double kLevelAlphaDeg = 2;
// Calibrations in two colour channels whose marker angles differ by more than this (as
// kLevelAlphaDeg) have placed a silhouette differently (BeginMono).
constexpr double kChannelAlphaDeg = kLevelAlphaDeg;

// How plainly a calibration's limbs step from the background: the weaker side's steepest band
// (grey levels a pixel; 0 when a side was placed by the markers' symmetry alone).
double LimbContrast(const LowerCalibration& cal) {
  return std::min(cal.steepest(0), cal.steepest(1));
}

class MarkerEngine : public Engine {
 public:
  explicit MarkerEngine(const MarkerOptions& options) : requested_(options), options_(options) {}

  EngineKind kind() const override { return EngineKind::kMarker; }

  Status Begin(const EngineContext& context) override {
    begun_ = false;
    const cv::Mat& ref = context.reference;
    if (ref.empty()) {
      return Status::Error("analysis.reference",
                           "the marker engine needs a reference image (the joint at zero yaw and "
                           "zero bend)");
    }
    if (ref.type() != CV_8UC3) {
      return Status::Error("analysis.reference", "the reference image must be 8-bit BGR");
    }
    if (!context.frame_size.empty() && context.frame_size != ref.size()) {
      return Status::Error("analysis.reference",
                           "the reference is " + std::to_string(ref.cols) + "x" +
                               std::to_string(ref.rows) + " but the input is " +
                               std::to_string(context.frame_size.width) + "x" +
                               std::to_string(context.frame_size.height));
    }
    options_ = requested_;
    if (!options_.thesis_mode) {
      const Status st = BeginMono(ref);
      if (!st.ok()) return st;
    } else {
      MarkerTriple t;
      if (!FindReferenceMarkers(ref, &t)) return NoTriple();
      ref_.markers = t;
      ref_.n_px = t.right.centre.x - t.left.centre.x;
      ref_.e_px = 0.5 * ((t.left.centre.y + t.right.centre.y) * 0.5 - t.upper.centre.y);
      if (ref_.n_px < 3 || ref_.e_px < 3) {
        return Status::Error("analysis.reference",
                             "the reference's markers are too close together (N = " +
                                 Fixed(ref_.n_px, 1) + " px, e = " + Fixed(ref_.e_px, 1) + " px)");
      }
    }
    size_ = ref.size();
    begun_ = true;
    decisions_told_ = false;
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    ArmMeasurement m;
    m.frame = frame.index;
    m.time_s = frame.time_s;
    m.file = frame.name;
    m.phase = MeasurementPhase::kLost;
    if (!begun_) {
      m.note = "the engine has no reference yet";
      return m;
    }
    if (frame.image.empty() || frame.image.size() != size_ || frame.image.type() != CV_8UC3) {
      m.note = "image size differs from the reference";
      return m;
    }
    if (options_.thesis_mode) return ProcessThesis(frame.image, m);
    MonoImage(frame.image, channel_, &scratch_.gray);
    if (level_.active()) level_.Apply(scratch_.gray, &level_gray_);
    const cv::Mat& gray = level_.active() ? level_gray_ : scratch_.gray;
    const MarkerViewResult r = MeasureMarkerView(gray, cal_, options_, &view_);
    // What the view shows is drawn on the image as taken: points of a levelled view map back.
    auto shown = [&](cv::Point2d p) { return level_.active() ? level_.ToOriginal(p) : p; };
    m.note = r.note;
    if (!decisions_told_) {
      decisions_told_ = true;
      m.estimate = CalibrationDecisions();
    }
    m.candidate_boxes = r.candidates;
    if (level_.active()) {
      for (cv::Rect& box : m.candidate_boxes) box = level_.ToOriginal(box);
    }
    if (std::isfinite(r.axis_x_px)) {
      const double bottom = r.bottom_row;
      m.cylinder_axis_px = {shown({r.axis_x_px, bottom}), shown(r.pivot_px)};
      m.cylinder_edges_px = {shown({r.left_edge_px, r.pivot_px.y}), shown({r.left_edge_px, bottom}),
                             shown({r.right_edge_px, r.pivot_px.y}),
                             shown({r.right_edge_px, bottom})};
    }
    if (!r.ok) return m;
    m.phase = MeasurementPhase::kOk;
    m.yaw_deg = std::abs(DegFromRad(r.yaw));
    // The signed column only where the sign rests on evidence; the row stays ok for yaw_deg.
    m.yaw_signed_deg = r.sign_known ? DegFromRad(r.yaw) : kNaN;
    m.bend_deg = std::isfinite(r.bend) ? Wrap180(DegFromRad(r.bend)) : kNaN;
    m.shoulder_px = shown(r.pivot_px);  // the pivot, for the overlay
    m.marker_centres = {shown(r.upper_px), shown(r.left_px), shown(r.right_px)};
    return m;
  }

  AngleMeta Describe() const override {
    AngleMeta meta = {
        {"median", std::to_string(options_.median_size)},
        {"low", std::to_string(options_.low)},
        {"high", std::to_string(options_.high)},
        {"flood_range", std::to_string(options_.flood_range)},
        {"area", std::to_string(options_.min_area) + ".." + std::to_string(options_.max_area)},
        {"mode", options_.thesis_mode ? "thesis" : "cylinder"}};
    if (!begun_) return meta;
    if (options_.thesis_mode) {
      meta.emplace_back("N_px", Fixed(ref_.n_px, 3));
      meta.emplace_back("e_px", Fixed(ref_.e_px, 3));
    } else {
      meta.emplace_back("fov_deg", Fixed(options_.fov_deg, 1));
      meta.emplace_back("radius_px", Fixed(cal_.radius_px, 2));
      meta.emplace_back("alpha_deg", Fixed(DegFromRad(cal_.lower.alpha()), 2));
      meta.emplace_back("e_radii", Fixed(cal_.upper.e, 3));
      if (channel_ != MarkerChannel::kLuma) meta.emplace_back("channel", ChannelName(channel_));
      if (level_.active())
        meta.emplace_back("camera_pitch_deg", Fixed(DegFromRad(level_.pitch()), 2));
    }
    return meta;
  }

 private:
  Status NoTriple() const {
    return Status::Error("analysis.reference",
                         "cannot find the three markers in the reference (" +
                             std::to_string(reference_blobs_) +
                             " dark blobs passed the threshold and the heuristics; expected two "
                             "side by side and one centred above them)");
  }

  // Sub-pixel centroids of the triple (once with the darkest level, then with the learnt
  // marker/surround) and the cylinder model's calibration from them, the reference taken by
  // `camera`; false with a message, and *measured set when the markers could be measured (the
  // model itself refused them).
  bool CalibrateFrom(MarkerTriple t, const MarkerCamera& camera, std::string* message,
                     bool* measured) {
    *measured = false;
    double ratio = 0;
    for (MarkerBlob* b : {&t.upper, &t.left, &t.right}) {
      if (!RefineMarker(scratch_.gray, scratch_.filtered, 0, 0, b)) {
        *message = "the reference's markers have too little contrast to measure";
        return false;
      }
      ratio += b->core / b->surround;
    }
    *measured = true;
    for (MarkerBlob* b : {&t.upper, &t.left, &t.right}) {
      b->centre = {b->box.x + (b->box.width - 1) / 2.0, b->box.y + (b->box.height - 1) / 2.0};
      RefineMarker(scratch_.gray, scratch_.filtered, ratio / 3, 0, b);
    }
    if (!CalibrateMarkerJoint(scratch_.gray, camera, t, &cal_, message)) {
      *message = "the reference: " + *message;
      return false;
    }
    triple_ = t;
    return true;
  }

  // The cylinder model's calibration on the luma image; when the luma refuses the reference, on
  // each colour channel alone (MonoImage). The luma is tried first, so a reference it calibrates
  // is measured as before. A limb is where the joint's material meets the wall's, the same
  // column in every channel that shows a step there: channels whose calibrations place the
  // markers' angles apart (kChannelAlphaDeg) have taken something else for a limb in at least
  // one of them (a wall bar of a hue one channel darkens), and the reference is refused. One
  // channel alone is kept only when both its limbs step in it (LimbContrast > 0): a limb placed
  // by the markers' symmetry alone, in the one channel that calibrates, is confirmed by nothing.
  // Of the channels kept, the one whose limbs step most plainly measures the views.
  Status BeginMono(const cv::Mat& ref) {
    const Status luma = BeginCylinder(ref, MarkerChannel::kLuma);
    if (luma.ok()) return luma;
    struct Kept {
      MarkerChannel channel;
      MarkerOptions options;
      MarkerCalibration cal;
      LevelWarp level;
      MarkerTriple triple;
      double contrast;
    };
    std::vector<Kept> kept;
    for (MarkerChannel c : {MarkerChannel::kRed, MarkerChannel::kGreen, MarkerChannel::kBlue}) {
      options_ = requested_;
      if (BeginCylinder(ref, c).ok()) {
        kept.push_back({c, options_, cal_, level_, triple_, LimbContrast(cal_.lower)});
      }
    }
    channel_ = MarkerChannel::kLuma;
    bool agree = !kept.empty() && (kept.size() > 1 || kept[0].contrast > 0);
    for (const Kept& a : kept) {
      for (const Kept& b : kept) {
        agree &=
            std::abs(a.cal.lower.alpha() - b.cal.lower.alpha()) <= RadFromDeg(kChannelAlphaDeg);
      }
    }
    if (!agree) {
      options_ = requested_;
      level_ = LevelWarp();
      if (kept.empty()) return luma;
      // The channels were tried too: the operator is told what they showed.
      std::string tried;
      for (const Kept& k : kept) {
        tried += std::string(tried.empty() ? "" : ", ") + ChannelName(k.channel) + " " +
                 Fixed(DegFromRad(k.cal.lower.alpha()), 1);
      }
      return Status::Error(
          luma.key(),
          luma.message() +
              (kept.size() > 1
                   ? "; single colour channels calibrate it with lower markers " + tried +
                         " degrees either side of the front, which disagree"
                   : "; only its " + std::string(ChannelName(kept[0].channel)) +
                         " channel calibrates it, with a limb placed by the markers' symmetry "
                         "alone"));
    }
    const Kept& best =
        *std::max_element(kept.begin(), kept.end(),
                          [](const Kept& a, const Kept& b) { return a.contrast < b.contrast; });
    channel_ = best.channel;
    options_ = best.options;
    cal_ = best.cal;
    level_ = best.level;
    triple_ = best.triple;
    return Status::Ok();
  }

  // The cylinder model's calibration, on a camera levelled when the reference's limbs show it
  // tilted (LevelPitch): past kLevelMinDeg and within kLevelMaxDeg (a larger lean is a limb fit
  // gone astray, not "a little" tilt), the reference is levelled and its markers calibrated
  // again, kept when that calibration's limbs stand within kLevelMinDeg of upright and its
  // marker angles agree with the tilted one's (kLevelAlphaDeg); otherwise the tilted
  // calibration stays.
  // The reference (BGR) is seen through `channel`, which the views are then measured in.
  Status BeginCylinder(const cv::Mat& ref, MarkerChannel channel) {
    level_ = LevelWarp();
    channel_ = channel;
    MonoImage(ref, channel, &mono_ref_);
    const Status tilted = CalibrateCylinder(mono_ref_);
    if (!tilted.ok()) return tilted;
    const double pitch = LevelPitch(cal_.lower, cal_.camera);
    if (!(std::abs(pitch) >= RadFromDeg(kLevelMinDeg) &&
          std::abs(pitch) <= RadFromDeg(kLevelMaxDeg))) {
      return tilted;
    }
    // The same three markers, found in the image as taken, measured again in the levelled one
    // (searched afresh, fragments of a marker the resampling split had been taken).
    const MarkerCalibration tilted_cal = cal_;
    const LevelWarp warp(cal_.camera, ref.size(), pitch);
    cv::Mat level;
    warp.Apply(ref, &level, LevelWarp::Resampling::kSharp);
    MonoImage(level, channel, &mono_ref_);
    MarkerImages(mono_ref_, options_, &scratch_);
    MarkerTriple t = triple_;
    for (MarkerBlob* b : {&t.upper, &t.left, &t.right}) {
      b->box = warp.ToLevel(b->box);
      b->centre = warp.ToLevel(b->centre);
    }
    std::string message;
    bool measured = false;
    const bool levelled = CalibrateFrom(t, warp.camera(), &message, &measured);
    if (levelled && std::abs(LevelPitch(cal_.lower, cal_.camera)) < RadFromDeg(kLevelMinDeg) &&
        std::abs(cal_.lower.alpha() - tilted_cal.lower.alpha()) <= RadFromDeg(kLevelAlphaDeg)) {
      level_ = warp;
      return Status::Ok();
    }
    cal_ = tilted_cal;
    return tilted;
  }

  // The cylinder model's reference: the most symmetric triples of dark blobs in turn (a
  // symmetric triple of wall blobs beside the joint fails the model, the joint's own markers
  // do not), in the threshold windows and area bounds FindReferenceMarkers tries.
  Status CalibrateCylinder(const cv::Mat& ref) {
    // Why the reference is refused: the first triple the joint's model itself turned down says
    // more than a triple whose blobs could not even be measured (a wall blob, one cut by the
    // image's edge), which may have been tried first.
    std::string first_error, model_error;
    int tried = 0;
    auto attempt = [&](const MarkerOptions& o) {
      const std::vector<MarkerBlob> blobs = FindMarkerCandidates(ref, o, &scratch_);
      for (const MarkerTriple& t : RankReferenceTriples(blobs, scratch_.filtered, 4)) {
        ++tried;
        std::string message;
        bool measured = false;
        if (CalibrateFrom(t, MarkerCamera::FromFov(o.fov_deg, ref.size()), &message, &measured)) {
          return true;
        }
        if (first_error.empty()) first_error = message;
        if (measured && model_error.empty()) model_error = message;
      }
      return false;
    };
    reference_blobs_ = static_cast<int>(FindMarkerCandidates(ref, requested_, &scratch_).size());
    if (attempt(requested_)) return Status::Ok();
    if (options_.auto_window) {
      for (const MarkerOptions& o : ReferenceWindows()) {
        if (attempt(o)) {
          options_ = o;
          return Status::Ok();
        }
      }
    }
    if (tried == 0) return NoTriple();
    return Status::Error("analysis.reference", (model_error.empty() ? first_error : model_error) +
                                                   " (" + std::to_string(tried) +
                                                   " candidate triple" + (tried == 1 ? "" : "s") +
                                                   " of dark blobs tried)");
  }

  // When [low, high] does not show the reference's markers (other illumination), the nearest
  // windows of the same width; then the same with larger area bounds. The thesis' bounds suit
  // its markers at its distance; the cylinder model measures any size, so larger markers (or a
  // nearer camera) are looked for too, the triple's symmetry still deciding which blobs are the
  // markers.
  std::vector<MarkerOptions> ReferenceWindows() const {
    std::vector<MarkerOptions> out;
    const int width = requested_.high - requested_.low;
    for (int area_scale : {1, 3, 9}) {
      for (int shift = 0; shift <= 255; shift += 5) {
        for (int sign : {-1, 1}) {
          if (shift == 0 && (sign < 0 || area_scale == 1)) continue;
          MarkerOptions o = requested_;
          o.max_area = requested_.max_area * area_scale;
          o.low = requested_.low + sign * shift;
          o.high = o.low + width;
          if (o.low < 0 || o.high > 255) continue;
          out.push_back(o);
        }
      }
    }
    // A marker seen nearly edge-on (near a limb) is a stripe narrower than the median's window,
    // which wipes it out: last, the same windows with the narrowest median that still removes
    // single-pixel noise.
    if (requested_.median_size > kNarrowMedian) {
      const std::size_t n = out.size();
      MarkerOptions o = requested_;
      o.median_size = kNarrowMedian;
      out.push_back(o);
      for (std::size_t i = 0; i < n; ++i) {
        out.push_back(out[i]);
        out.back().median_size = kNarrowMedian;
      }
    }
    return out;
  }

  // The reference's three markers (4.2) for the thesis path.
  bool FindReferenceMarkers(const cv::Mat& ref, MarkerTriple* t) {
    std::vector<MarkerBlob> blobs = FindMarkerCandidates(ref, options_, &scratch_);
    reference_blobs_ = static_cast<int>(blobs.size());
    return ChooseReferenceTriple(blobs, scratch_.filtered, options_.thesis_mode, t);
  }

  ArmMeasurement& ProcessThesis(const cv::Mat& image, ArmMeasurement& m) {
    const std::vector<MarkerBlob> blobs = FindMarkerCandidates(image, options_, &scratch_);
    m.candidate_boxes.reserve(blobs.size());
    for (const MarkerBlob& b : blobs) m.candidate_boxes.push_back(b.box);
    MarkerTriple t;
    if (!ThreeLargest(blobs, &t)) {
      m.note = "fewer than three markers found (one hidden?)";
      return m;
    }
    m.marker_centres = {t.upper.centre, t.left.centre, t.right.centre};
    const MarkerAngles a = ComputeThesisAngles(t, ref_);
    m.phase = MeasurementPhase::kOk;
    m.yaw_deg = a.yaw_deg;
    m.bend_deg = a.bend_deg;
    m.shoulder_px = a.pivot_px;
    m.note = "three largest; yaw = acos(n/N)";
    return m;
  }

  // What the calibration chose that the operator did not give, told once (on_estimate): a camera
  // levelled, a colour channel measured instead of the luma.
  std::string CalibrationDecisions() const {
    std::vector<std::string> told;
    if (level_.active()) {
      const double pitch = DegFromRad(level_.pitch());  // positive looking down
      told.push_back("the camera looks " + Fixed(std::abs(pitch), 1) +
                     (pitch > 0 ? " degrees down" : " degrees up") +
                     " (read from the reference's limbs), so every view is levelled");
    }
    if (channel_ != MarkerChannel::kLuma) {
      told.push_back(std::string("the reference's limbs show only in its ") +
                     ChannelName(channel_) + " channel, so every view is measured in it");
    }
    std::string text;
    for (const std::string& t : told) text += (text.empty() ? "marker: " : "; ") + t;
    return text;
  }

  MarkerOptions requested_;
  MarkerOptions options_;  // as used: the window may be shifted by Begin
  MarkerReference ref_;    // thesis path
  MarkerCalibration cal_;  // cylinder model
  MarkerScratch scratch_;
  MarkerViewScratch view_;
  LevelWarp level_;      // a tilted camera's views levelled (cylinder model)
  MarkerTriple triple_;  // the reference's markers as calibrated
  cv::Mat level_gray_;   // the levelled view's buffer
  cv::Mat mono_ref_;     // the reference in the channel being calibrated
  MarkerChannel channel_ = MarkerChannel::kLuma;  // what the views are measured in
  int reference_blobs_ = 0;
  cv::Size size_;
  bool begun_ = false;
  bool decisions_told_ = false;
};

}  // namespace

std::unique_ptr<Engine> CreateMarkerEngine(const MarkerOptions& options) {
  return std::make_unique<MarkerEngine>(options);
}

}  // namespace internal
}  // namespace armmimic
