// The marker-joint engine (thesis chapter 4, docs/marker.md): three black markers on a model
// joint give its yaw (acos(n/N)) and bend (eqs. 4-2..4-5) from every image.
#include <cmath>
#include <cstdio>
#include <string>

#include "armmimic/core/angle_file.h"
#include "engine_factories.h"
#include "marker_detect.h"

namespace armmimic {

Status MarkerOptions::Check() const {
  if (median_size < 1 || median_size % 2 == 0 || median_size > 31) {
    return Status::Error("--median: window must be odd, 1..31 (got " + std::to_string(median_size) +
                         ")");
  }
  if (low < 0 || low > 255) return Status::Error("--low must be in [0, 255]");
  if (high < 0 || high > 255) return Status::Error("--high must be in [0, 255]");
  if (low > high) {
    return Status::Error("--low " + std::to_string(low) + " is above --high " +
                         std::to_string(high));
  }
  if (flood_range < 0 || flood_range > 255) {
    return Status::Error("--flood-range must be in [0, 255]");
  }
  if (min_area < 1 || max_area < min_area) {
    return Status::Error("--min-area/--max-area: need 1 <= min-area <= max-area");
  }
  if (!(min_aspect > 0 && max_aspect >= min_aspect)) {
    return Status::Error("--min-aspect/--max-aspect: need 0 < min-aspect <= max-aspect");
  }
  if (!(min_fill >= 0 && min_fill <= 1)) return Status::Error("--min-fill must be in [0, 1]");
  if (!(max_marker_turn_deg > 0 && max_marker_turn_deg <= 90)) {
    return Status::Error("--max-marker-turn must be in (0, 90] degrees");
  }
  if (!(min_foreshortening >= 0 && min_foreshortening < 1)) {
    return Status::Error("--min-foreshortening must be in [0, 1)");
  }
  if (!(geometry_tolerance > 0 && geometry_tolerance <= 1)) {
    return Status::Error("--geometry-tolerance must be in (0, 1]");
  }
  if (!(ambiguity_margin >= 0)) return Status::Error("--ambiguity-margin must be >= 0");
  if (!(max_area_misfit > 0)) return Status::Error("--max-area-misfit must be > 0");
  if (!(min_width_ratio > 0 && max_width_ratio >= min_width_ratio)) {
    return Status::Error("marker options: need 0 < min_width_ratio <= max_width_ratio");
  }
  return Status::Ok();
}

namespace internal {
namespace {

std::string Fixed(double v, int decimals) { return FormatNumber(v, decimals); }

class MarkerEngine : public Engine {
 public:
  explicit MarkerEngine(const MarkerOptions& options) : requested_(options), options_(options) {}

  EngineKind kind() const override { return EngineKind::kMarker; }

  Status Begin(const EngineContext& context) override {
    begun_ = false;
    const cv::Mat& ref = context.reference;
    if (ref.empty()) {
      return Status::Error(
          "--reference: the marker engine needs a reference image (the joint at zero yaw and "
          "zero bend)");
    }
    if (ref.type() != CV_8UC3) return Status::Error("--reference: the image must be 8-bit BGR");
    if (!context.frame_size.empty() && context.frame_size != ref.size()) {
      return Status::Error("--reference: the reference is " + std::to_string(ref.cols) + "x" +
                           std::to_string(ref.rows) + " but the input is " +
                           std::to_string(context.frame_size.width) + "x" +
                           std::to_string(context.frame_size.height));
    }
    options_ = requested_;
    std::vector<MarkerBlob> blobs = FindMarkerCandidates(ref, options_, &scratch_);
    MarkerTriple t;
    bool found = ChooseReferenceTriple(blobs, scratch_.filtered, options_.thesis_mode, &t);
    if (!found && options_.auto_window && !options_.thesis_mode) {
      // Other illumination: shift the window, nearest first, until the markers show.
      const int width = requested_.high - requested_.low;
      for (int shift = 5; shift <= 255 && !found; shift += 5) {
        for (int sign : {-1, 1}) {
          MarkerOptions o = requested_;
          o.low = requested_.low + sign * shift;
          o.high = o.low + width;
          if (o.low < 0 || o.high > 255) continue;
          std::vector<MarkerBlob> b = FindMarkerCandidates(ref, o, &scratch_);
          if (ChooseReferenceTriple(b, scratch_.filtered, false, &t)) {
            options_ = o;
            blobs = std::move(b);
            found = true;
            break;
          }
        }
      }
      if (found) FindMarkerCandidates(ref, options_, &scratch_);  // scratch for the refinement
    }
    if (!found) {
      return Status::Error("--reference: cannot find the three markers (" +
                           std::to_string(blobs.size()) +
                           " dark blobs passed the threshold and the heuristics; expected two "
                           "side by side and one centred above them)");
    }
    MarkerReference r;
    if (!options_.thesis_mode) {
      // Refine once with the darkest level, learn marker / surround, refine again with it.
      double ratio = 0;
      int count = 0;
      for (MarkerBlob* b : {&t.upper, &t.left, &t.right}) {
        if (RefineMarker(scratch_.gray, scratch_.filtered, 0, 0, b)) {
          ratio += b->core / b->surround;
          ++count;
        }
      }
      if (count == 3) {
        r.core_ratio = ratio / 3;
        for (MarkerBlob* b : {&t.upper, &t.left, &t.right}) {
          b->centre = {b->box.x + (b->box.width - 1) / 2.0, b->box.y + (b->box.height - 1) / 2.0};
          RefineMarker(scratch_.gray, scratch_.filtered, r.core_ratio, 0, b);
        }
        r.face_area_px = t.upper.coverage_px;
        r.marker_height_px = t.upper.box.height;
        const double cos_alpha =
            std::clamp(0.5 * (t.left.coverage_px + t.right.coverage_px) / r.face_area_px, 0.0, 1.0);
        r.alpha_deg = DegFromRad(std::acos(cos_alpha));
      }
    }
    r.markers = t;
    const cv::Point2d mid = (t.left.centre + t.right.centre) * 0.5;
    r.pair_level = SampleStretch(scratch_.filtered, t.left.centre, t.right.centre).level;
    r.upper_level =
        SampleStretch(scratch_.filtered, {mid.x, 0.5 * (mid.y + t.upper.centre.y)}, t.upper.centre)
            .level;
    r.n_px = t.right.centre.x - t.left.centre.x;
    r.e_px = 0.5 * ((t.left.centre.y + t.right.centre.y) * 0.5 - t.upper.centre.y);
    if (r.n_px < 3 || r.e_px < 3) {
      return Status::Error("--reference: the markers are too close together (N = " +
                           Fixed(r.n_px, 1) + " px, e = " + Fixed(r.e_px, 1) + " px)");
    }
    if (!options_.thesis_mode && r.face_area_px <= 0) {
      return Status::Error("--reference: the markers have too little contrast to measure");
    }
    ref_ = r;
    size_ = ref.size();
    begun_ = true;
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
    const std::vector<MarkerBlob> blobs = FindMarkerCandidates(frame.image, options_, &scratch_);
    m.candidate_boxes.reserve(blobs.size());
    for (const MarkerBlob& b : blobs) m.candidate_boxes.push_back(b.box);
    MarkerTriple t;
    bool ambiguous = false;
    if (!ChooseTriple(blobs, scratch_.filtered, ref_, options_, &t, &ambiguous)) {
      m.note = blobs.size() < 3 ? "fewer than three markers found (one hidden?)"
               : ambiguous      ? "two sets of blobs fit the joint's geometry (clutter competes)"
                                : "no three blobs fit the joint's geometry";
      return m;
    }
    if (!options_.thesis_mode) {
      for (MarkerBlob* b : {&t.upper, &t.left, &t.right}) {
        RefineMarker(scratch_.gray, scratch_.filtered, ref_.core_ratio, ref_.marker_height_px, b);
      }
    }
    m.marker_centres = {t.upper.centre, t.left.centre, t.right.centre};
    const MarkerAngles a = ComputeMarkerAngles(t, ref_, options_.thesis_mode);
    if (!options_.thesis_mode && std::isfinite(a.area_yaw_deg) &&
        std::abs(std::abs(a.area_yaw_deg) - a.acos_yaw_deg) > options_.max_yaw_disagreement_deg) {
      m.note = "the lower markers' areas (yaw " + Fixed(std::abs(a.area_yaw_deg), 0) +
               ") disagree with their distance (yaw " + Fixed(a.acos_yaw_deg, 0) +
               "): not the markers";
      return m;
    }
    if (!options_.thesis_mode && std::abs(a.pair_area_ratio - 1) > options_.max_area_misfit) {
      m.note = "the lower pair shows " + Fixed(100 * a.pair_area_ratio, 0) +
               " % of the area the joint would: not the markers";
      return m;
    }
    if (!options_.thesis_mode && ref_.alpha_deg + a.yaw_deg > options_.max_marker_turn_deg) {
      m.note = "a lower marker is nearly edge-on (turned " + Fixed(ref_.alpha_deg + a.yaw_deg, 0) +
               " degrees from the camera)";
      return m;
    }
    if (!options_.thesis_mode && a.foreshortening < options_.min_foreshortening) {
      m.note = "a lower marker is nearly edge-on (shows " + Fixed(100 * a.foreshortening, 0) +
               " % of its face)";
      return m;
    }
    m.phase = MeasurementPhase::kOk;
    m.yaw_deg = a.yaw_deg;
    m.bend_deg = a.bend_deg;
    m.shoulder_px = a.pivot_px;  // the pivot, for the overlay
    m.note = options_.thesis_mode ? "three largest"
                                  : "geometry check; the more turned lower marker shows " +
                                        Fixed(100 * a.foreshortening, 0) + " % of its face";
    return m;
  }

  AngleMeta Describe() const override {
    AngleMeta meta = {
        {"median", std::to_string(options_.median_size)},
        {"low", std::to_string(options_.low)},
        {"high", std::to_string(options_.high)},
        {"flood_range", std::to_string(options_.flood_range)},
        {"area", std::to_string(options_.min_area) + ".." + std::to_string(options_.max_area)},
        {"mode", options_.thesis_mode ? "thesis" : "geometry"}};
    if (begun_) {
      meta.emplace_back("N_px", Fixed(ref_.n_px, 3));
      meta.emplace_back("e_px", Fixed(ref_.e_px, 3));
      if (!options_.thesis_mode) meta.emplace_back("alpha_deg", Fixed(ref_.alpha_deg, 2));
    }
    return meta;
  }

  // For tests and the benchmark: the calibration from the reference.
  const MarkerReference& reference() const { return ref_; }

 private:
  MarkerOptions requested_;
  MarkerOptions options_;  // as used: the window may be shifted by Begin
  MarkerReference ref_;
  MarkerScratch scratch_;
  cv::Size size_;
  bool begun_ = false;
};

}  // namespace

std::unique_ptr<Engine> CreateMarkerEngine(const MarkerOptions& options) {
  return std::make_unique<MarkerEngine>(options);
}

}  // namespace internal
}  // namespace armmimic
