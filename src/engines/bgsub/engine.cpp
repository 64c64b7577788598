// The background-subtraction engine (thesis chapter 5) behind the Engine interface: the
// standstill phase, then one measurement per frame. See docs/bgsub.md for the steps.
#include <cmath>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "bgsub/arm.h"
#include "bgsub/calib.h"
#include "bgsub/fit.h"
#include "bgsub/masks.h"
#include "bgsub/pixels.h"
#include "bgsub/scene.h"
#include "bgsub/support.h"
#include "common/arm_gate.h"
#include "common/engine_internal.h"

namespace armmimic {
namespace {

std::string SizeText(const cv::Size& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

cv::Point2d Offset(const cv::Point2d& p, const cv::Point& o) { return {p.x + o.x, p.y + o.y}; }

std::vector<cv::Point> Offset(std::vector<cv::Point> pts, const cv::Point& o) {
  for (cv::Point& p : pts) p += o;
  return pts;
}

class BgsubEngine final : public Engine {
 public:
  explicit BgsubEngine(const BgsubOptions& options) : options_(options) {}

  EngineKind kind() const override { return EngineKind::kBgsub; }

  Status Begin(const EngineContext& context) override {
    const cv::Size size = context.frame_size;
    if (size.width <= 0 || size.height <= 0) return Status::Error("bgsub: the frame size is empty");
    if (context.background.empty()) {
      return Status::Error("analysis.background",
                           "bgsub needs a background image (given, or averaged from frames)");
    }
    if (context.background.size() != size) {
      return Status::Error("bgsub: the background image is " + SizeText(context.background.size()) +
                           " but the video is " + SizeText(size));
    }
    if (context.arm_length.empty()) {
      return Status::Error("analysis.arm_length", "bgsub needs an arm-length image");
    }
    if (context.arm_length.size() != size) {
      return Status::Error("analysis.arm_length", "bgsub: the arm-length image is " +
                                                      SizeText(context.arm_length.size()) +
                                                      " but the video is " + SizeText(size));
    }
    frame_size_ = size;
    region_ = cv::Rect(0, 0, size.width, size.height);
    if (context.roi) {
      region_ &= *context.roi;
      if (region_.area() < 16) {
        return Status::Error("analysis.roi", "the region of interest " +
                                                 std::to_string(context.roi->x) + "," +
                                                 std::to_string(context.roi->y) + "," +
                                                 std::to_string(context.roi->width) + "," +
                                                 std::to_string(context.roi->height) +
                                                 " lies outside the " + SizeText(size) + " frame");
      }
    }
    scene_ = bgsub::SceneModel();
    bgsub::ToGray(context.background(region_), &scene_.background);
    bgsub::ToGray(context.arm_length(region_), &arm_length_gray_);
    arm_length_bgr_ = context.arm_length(region_).clone();
    scene_.background_bgr = context.background(region_).clone();
    fixed_shoulder_.reset();
    if (context.shoulder_px) {
      fixed_shoulder_ =
          cv::Point2d(context.shoulder_px->x - region_.x, context.shoulder_px->y - region_.y);
      scene_.fixed_shoulder = fixed_shoulder_;
    }
    standstill_sum_ = cv::Mat::zeros(region_.size(), CV_32FC1);
    standstill_count_ = 0;
    pixels_.Begin(region_.size());
    cal_ = bgsub::ArmCalibration();
    ArmGateOptions gate;
    gate.max_speed_deg_s = options_.max_speed_deg_s;
    gate.min_support = options_.min_support;
    gate.confirm_frames = options_.confirm_frames;
    gate.start_confirmed = false;   // until the standstill gives the rest pose (or a first run)
    gate.confirm_after_gap = true;  // each frame is fitted on its own: no tracker carries the arm
    gate_ = ArmGate(gate);
    begun_ = true;
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    if (!begun_) throw std::logic_error("BgsubEngine::Process called before Begin");
    ArmMeasurement m;
    m.frame = frame.index;
    m.time_s = frame.time_s;
    m.file = frame.name;
    if (frame.image.size() != frame_size_) {
      m.phase = MeasurementPhase::kLost;
      m.note = "frame is " + SizeText(frame.image.size()) + ", expected " + SizeText(frame_size_);
      return m;
    }
    // The standstill (5.2.2): the mean of the first standstill_frames frames; no rows.
    if (standstill_count_ < options_.standstill_frames) {
      if (options_.thesis_mode) {
        bgsub::ToGray(frame.image(region_), &gray_);
        cv::accumulate(gray_, standstill_sum_);
      } else {
        pixels_.AddStandstill(frame.image(region_));
      }
      ++standstill_count_;
      m.phase = MeasurementPhase::kSetup;
      m.note = "standstill " + std::to_string(standstill_count_) + "/" +
               std::to_string(options_.standstill_frames);
      if (standstill_count_ == options_.standstill_frames) {
        FinishStandstill();
        // The protocol's standstill: the arm hangs at its rest pose when the rows begin.
        if (!options_.thesis_mode && cal_.ok) {
          gate_.Anchor(options_.rest_deg, options_.rest_deg, frame.time_s);
        }
      }
      FillSceneOverlay(&m);
      return m;
    }
    if (options_.thesis_mode) {
      bgsub::ToGray(frame.image(region_), &gray_);
      MeasureThesis(&m);
    } else {
      MeasureFit(frame, &m);
      gate_.Review(&m, m.phase == MeasurementPhase::kOk ? m.confidence : kNaN);
    }
    return m;
  }

  AngleMeta Describe() const override {
    return {{"threshold", std::to_string(options_.threshold)},
            {"standstill_frames", std::to_string(options_.standstill_frames)},
            {"straight_ratio", Num(options_.straight_ratio)},
            {"closing", std::to_string(options_.closing_size)},
            {"mode", options_.thesis_mode ? "thesis" : "improved"}};
  }

 private:
  void FinishStandstill() {
    if (options_.thesis_mode) {
      standstill_sum_.convertTo(scene_.standstill, CV_8UC1, 1.0 / standstill_count_);
      bgsub::BuildScene(arm_length_gray_, options_, &buffers_, &scene_);
      return;
    }
    pixels_.Finish(scene_.background_bgr, options_.threshold);
    cal_ = bgsub::Calibrate(pixels_, arm_length_bgr_, fixed_shoulder_);
    if (!cal_.ok) return;
    const double upper = options_.upper_arm_fraction * cal_.reach_px;
    evidence_.Begin(cal_, region_.size(), options_.rest_deg);
    fitter_.Begin(static_cast<int>(evidence_.weights().step1()), upper, cal_.reach_px - upper,
                  cal_.half_width_px, options_.max_bend_deg);
    cv::Mat person, uncovered;
    pixels_.StandstillPerson(&person);
    pixels_.Differ(arm_length_bgr_, pixels_.standstill(), &uncovered);
    pixels_.SetThird(arm_length_bgr_);
    support_.Begin(cal_, upper, options_.rest_deg, evidence_.rect(), person, uncovered);
  }

  void FillSceneOverlay(ArmMeasurement* m) const {
    const cv::Point o = region_.tl();
    if (options_.thesis_mode) {
      if (scene_.body_box) m->body_box = *scene_.body_box + o;
      if (auto s = scene_.Shoulder(scene_.side, options_)) m->shoulder_px = Offset(*s, o);
      return;
    }
    if (cal_.body_box) m->body_box = *cal_.body_box + o;
    if (cal_.ok) m->shoulder_px = Offset(cal_.shoulder_px, o);
  }

  // The default path: the two-segment fit to the per-pixel evidence (bgsub/fit.h).
  void MeasureFit(const Frame& frame, ArmMeasurement* m) {
    m->phase = MeasurementPhase::kLost;
    FillSceneOverlay(m);
    if (!cal_.ok) {
      m->note = cal_.note.empty() ? "no calibration" : cal_.note;
      return;
    }
    pixels_.Compare(frame.image(region_), evidence_.rect(), cv::Mat(), &person_, &moved_);
    pixels_.CompareThird(frame.image(region_), evidence_.rect(), &not_uncovered_);
    // Specks of a textured shirt moving a little (sway, noise, compression) are no arm; a moved
    // arm is a solid region.
    cv::morphologyEx(moved_, moved_, cv::MORPH_OPEN, kSpeckKernel);
    evidence_.Update(person_, moved_);
    const bgsub::ArmFit fit = fitter_.Fit(evidence_.weights(), evidence_.origin());
    if (!fit.found) {
      m->note = "no arm";
      return;
    }
    // Confidence: the weaker segment's support, less what speaks against the arm, 0 when the
    // arm's surroundings look like arm too (a flooded mask: any pose there would fit).
    const double conf =
        fit.clutter > kMaxClutter
            ? 0.0
            : std::clamp(std::min(fit.upper_support, fit.fore_support) * (1 - fit.against) / 0.5,
                         0.0, 1.0);
    // In words for the operator; the numbers are the confidence (its own column).
    std::string note = "both segments fit";
    if (fit.clutter > kMaxClutter) {
      note = "the arm's surroundings look like arm too";
    } else if (std::min(fit.upper_support, fit.fore_support) < 0.5) {
      note = fit.upper_support < fit.fore_support ? "the upper arm fits weakly"
                                                  : "the forearm fits weakly";
    }
    if (fit.against > 0.25) note += ", with moving pixels against it";
    // The support rule (bgsub/support.h).
    const std::string why =
        support_.Check(support_.Joints(fit.upper_deg, fit.fore_deg, fit.scale, fit.split), person_,
                       moved_, not_uncovered_);
    if (!why.empty()) {
      m->note = why;
      return;
    }
    const cv::Point2d o = cv::Point2d(region_.tl()) + cv::Point2d(evidence_.window_tl());
    m->phase = MeasurementPhase::kOk;
    m->note = note;
    m->confidence = conf;
    m->upper_deg = fit.upper_deg;
    m->fore_deg = fit.fore_deg;
    m->bend_deg = AngleDiff(fit.fore_deg, fit.upper_deg);
    m->bent = std::fabs(m->bend_deg) > kStraightDeg;
    m->yaw_deg = m->bent ? kNaN : StraightYaw(fit.scale);
    m->elbow_px = fit.elbow_px + o;
    m->wrist_px = fit.wrist_px + o;
    m->upper_com_px = (*m->shoulder_px + *m->elbow_px) * 0.5;
    m->fore_com_px = (*m->elbow_px + *m->wrist_px) * 0.5;
  }

  // The thesis path (chapter 5): the largest region of the two-step difference, its hull and
  // deepest defect, the 30 % rule and the split.
  void MeasureThesis(ArmMeasurement* m) {
    m->phase = MeasurementPhase::kLost;
    FillSceneOverlay(m);
    if (!scene_.note.empty() && !scene_.body_box && !scene_.fixed_shoulder) {
      m->note = scene_.note;
      return;
    }
    cv::Rect box;
    std::string note;
    if (!bgsub::FindArmMask(gray_, scene_, options_, &buffers_, &box, &note)) {
      m->note = note;
      return;
    }
    // Side unknown (no arm in the arm-length image): the moving region's place decides it.
    int side = scene_.side;
    if (side == 0 && scene_.body_box) {
      const RegionMoments rm = ComputeMoments(buffers_.arm, box);
      side = rm.cx >= scene_.body_box->x + 0.5 * scene_.body_box->width ? 1 : -1;
    }
    const std::optional<cv::Point2d> shoulder = scene_.Shoulder(side, options_);
    if (!shoulder) {
      m->note = "no shoulder: no body in the standstill and no fixed shoulder";

      return;
    }
    const bgsub::ArmGeometry g = bgsub::AnalyzeArm(buffers_.arm, box, *shoulder, options_);
    if (!g.found) {
      m->note = g.note;
      return;
    }
    const cv::Point o = region_.tl();
    m->phase = MeasurementPhase::kOk;
    m->note = g.note;
    m->upper_deg = Wrap180(g.upper_deg);
    m->fore_deg = Wrap180(g.fore_deg);
    m->bend_deg = g.bent ? AngleDiff(g.fore_deg, g.upper_deg) : 0.0;
    m->yaw_deg = g.bent ? kNaN : Yaw(g);
    m->upper_com_px = Offset(g.upper_com_px, o);
    m->fore_com_px = Offset(g.fore_com_px, o);
    m->shoulder_px = Offset(*shoulder, o);
    m->elbow_px = Offset(g.elbow_px, o);
    m->wrist_px = Offset(g.wrist_px, o);
    m->bent = g.bent;
    m->arm_contour = Offset(g.contour, o);
    m->arm_hull = Offset(g.hull, o);
  }

  // A straight arm's yaw from how much both segments are foreshortened against the arm-length
  // image's straight arm: acos of the shared length scale. A shortening under one pixel of the
  // reach is within what the fit can measure: no yaw.
  double StraightYaw(double scale) const {
    if (scale * cal_.reach_px > cal_.reach_px - 1) return 0;
    return DegFromRad(std::acos(std::clamp(scale, 0.0, 1.0)));
  }

  // yaw = acos(a/b) (5.2.6): a from this frame, b from the arm-length image.
  double Yaw(const bgsub::ArmGeometry& g) const {
    const double a = g.axes.major, b = scene_.ref_major_px;
    if (!(b > 0) || !std::isfinite(a)) return kNaN;
    return DegFromRad(std::acos(std::min(1.0, std::max(0.0, a / b))));
  }

  // The moved mask's opening, and the largest share of the arm's flanks that may look like arm.
  inline static const cv::Mat kSpeckKernel = cv::Mat::ones(3, 3, CV_8UC1);
  static constexpr double kMaxClutter = 0.5;
  // A bend under this many degrees is a straight arm (yaw is measured, not nan).
  static constexpr double kStraightDeg = 10;

  BgsubOptions options_;
  bool begun_ = false;
  cv::Size frame_size_;
  cv::Rect region_;
  std::optional<cv::Point2d> fixed_shoulder_;
  // The thesis path.
  bgsub::SceneModel scene_;
  cv::Mat arm_length_gray_;
  cv::Mat arm_length_bgr_;
  cv::Mat standstill_sum_;
  int standstill_count_ = 0;
  cv::Mat gray_;
  bgsub::Buffers buffers_;
  // The default path.
  bgsub::PixelModel pixels_;
  bgsub::ArmCalibration cal_;
  bgsub::ArmEvidence evidence_;
  bgsub::ArmFitter fitter_;
  cv::Mat person_, moved_;
  cv::Mat not_uncovered_;      // differs from the arm-length image (what the hanging arm covers)
  bgsub::FitSupport support_;  // an `ok` pose lies on pixels that show an arm now
  ArmGate gate_;               // honest status: weak evidence or an impossible jump is `lost`
};

}  // namespace

namespace internal {
std::unique_ptr<Engine> CreateBgsubEngine(const BgsubOptions& options) {
  return std::make_unique<BgsubEngine>(options);
}
}  // namespace internal
}  // namespace armmimic
