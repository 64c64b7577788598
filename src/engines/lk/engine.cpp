// The Lucas-Kanade engine (thesis chapter 6): the setup that finds the shoulder (6.1), then one
// of the two trackers (lk/thesis_tracker.cpp, lk/anchored_tracker.cpp) frame by frame.
//
// Setup: with a background and no --shoulder, the first standstill_frames frames are averaged
// (phase kSetup, no rows); the body box of standstill vs background gives the shoulder, and the
// last standstill frame is the known starting posture. With --shoulder, there is no setup: the
// first frame processed is the known starting posture and already gets a row.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angle_file.h"
#include "common/arm_gate.h"
#include "common/engine_internal.h"
#include "common/standstill_calibration.h"
#include "lk/body_box.h"
#include "lk/tracker.h"

namespace armmimic {
namespace {

std::string SizeText(const cv::Size& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

class LkEngine : public Engine {
 public:
  explicit LkEngine(const LkOptions& options) : o_(options) {}

  EngineKind kind() const override { return EngineKind::kLk; }

  Status Begin(const EngineContext& context) override {
    if (context.frame_size.width <= 0 || context.frame_size.height <= 0) {
      return Status::Error("lk: the video has no frame size");
    }
    frame_size_ = context.frame_size;
    const cv::Rect full(cv::Point(0, 0), frame_size_);
    roi_ = full;
    if (context.roi) {
      const cv::Rect r = *context.roi;
      if (r.width <= 0 || r.height <= 0 || (r & full) != r) {
        return Status::Error("analysis.roi", "the region of interest " + std::to_string(r.x) + "," +
                                                 std::to_string(r.y) + "," +
                                                 std::to_string(r.width) + "," +
                                                 std::to_string(r.height) + " is not inside the " +
                                                 SizeText(frame_size_) + " frame");
      }
      if (r.width < 16 || r.height < 16) {
        return Status::Error("analysis.roi",
                             "the region of interest is too small for tracking (at least 16x16 "
                             "pixels)");
      }
      roi_ = r;
    }
    background_.release();
    if (!context.background.empty()) {
      if (context.background.size() != frame_size_ || context.background.type() != CV_8UC3) {
        return Status::Error("lk: the background image is " + SizeText(context.background.size()) +
                             " but the video is " + SizeText(frame_size_));
      }
      background_ = context.background(roi_).clone();
    }
    arm_length_.release();
    if (!context.arm_length.empty()) {
      if (context.arm_length.size() != frame_size_ || context.arm_length.type() != CV_8UC3) {
        return Status::Error("analysis.arm_length",
                             "lk: the arm-length image is " + SizeText(context.arm_length.size()) +
                                 " but the video is " + SizeText(frame_size_));
      }
      arm_length_ = context.arm_length(roi_).clone();
    }
    shoulder_given_.reset();
    if (context.shoulder_px) {
      const cv::Point2d s = *context.shoulder_px;
      if (!std::isfinite(s.x) || !std::isfinite(s.y) ||
          !full.contains(cv::Point(cvFloor(s.x), cvFloor(s.y)))) {
        return Status::Error("analysis.shoulder", "the shoulder " + FormatNumber(s.x, 1) + "," +
                                                      FormatNumber(s.y, 1) + " is outside the " +
                                                      SizeText(frame_size_) + " frame");
      }
      shoulder_given_ = s - cv::Point2d(roi_.tl());
    }
    upper_length_px_ = fore_length_px_ = 0;
    if (context.elbow_px && context.wrist_px && shoulder_given_) {
      // The clicked joints: starting directions and segment lengths, measured.
      const cv::Point2d s = *context.shoulder_px, e = *context.elbow_px, w = *context.wrist_px;
      o_.initial_upper_deg = DirectionDeg(s, e);
      o_.initial_fore_deg = DirectionDeg(e, w);
      upper_length_px_ = cv::norm(e - s);
      fore_length_px_ = cv::norm(w - e);
    }
    if (!shoulder_given_ && background_.empty()) {
      return Status::Error("analysis.shoulder",
                           "lk: needs a background (an image or frames to average) or a fixed "
                           "shoulder");
    }
    tracker_ = o_.thesis_mode         ? lk::CreateThesisTracker(o_)
               : upper_length_px_ > 0 ? lk::CreateModelTracker(o_)
                                      : lk::CreateAnchoredTracker(o_);
    ArmGateOptions gate;
    gate.max_speed_deg_s = o_.max_speed_deg_s;
    gate.min_support = o_.min_support;
    gate.confirm_frames = o_.confirm_frames;
    gate_ = ArmGate(gate);
    state_ = shoulder_given_ ? State::kStart : State::kStandstill;
    standstill_count_ = 0;
    sum_.release();
    body_box_.reset();
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    ArmMeasurement m;
    m.frame = frame.index;
    m.time_s = frame.time_s;
    if (!tracker_) throw std::logic_error("lk: Process() before a successful Begin()");
    undecided_.reset();
    if (frame.image.size() != frame_size_ || frame.image.type() != CV_8UC3) {
      m.phase = MeasurementPhase::kLost;
      m.note = "frame " + std::to_string(frame.index) + " is not a " + SizeText(frame_size_) +
               " colour image";
      return m;
    }
    const cv::Mat view = frame.image(roi_);
    cv::Mat gray;
    cv::cvtColor(view, gray, cv::COLOR_BGR2GRAY);
    tracker_->SetTime(frame.time_s);
    switch (state_) {
      case State::kStandstill:
        return Standstill(view, gray, m);
      case State::kStart: {
        lk::TrackerStart start;
        start.gray = gray;
        start.bgr = view;
        start.shoulders = {*shoulder_given_};
        start.shoulder_fixed = true;
        if (upper_length_px_ > 0) {
          start.upper_length_px = upper_length_px_;
          start.fore_length_px = fore_length_px_;
          start.arm_length_px = upper_length_px_ + fore_length_px_;
        } else {
          start.arm_length_px = kArmToRoiHeight * roi_.height;
          m.estimate = "lk: arm length " + FormatNumber(start.arm_length_px, 0) +
                       " px estimated as " + FormatNumber(kArmToRoiHeight, 1) + " x the " +
                       (roi_.size() == frame_size_ ? "frame" : "region of interest") +
                       " height; give the elbow and wrist to measure it";
        }
        state_ = State::kTracking;
        return Fill(tracker_->Start(start), m);
      }
      case State::kTracking:
        return Fill(tracker_->Track(gray, view), m);
      case State::kFailed:
        m.phase = MeasurementPhase::kLost;
        m.note = failure_;
        return m;
    }
    return m;
  }

  AngleMeta Describe() const override {
    return {{"mode", o_.thesis_mode ? "thesis" : "anchored"},
            {"standstill_frames", std::to_string(o_.standstill_frames)},
            {"initial_upper", FormatNumber(o_.initial_upper_deg, 2)},
            {"initial_fore", FormatNumber(o_.initial_fore_deg, 2)},
            {"calibration", !arm_length_.empty() && !shoulder_given_ ? "standstill+arm_length"
                            : upper_length_px_ > 0                   ? "joints"
                            : shoulder_given_                        ? "shoulder"
                                                                     : "standstill"},
            {"side", LkArmSideName(o_.side)},
            {"quality", FormatNumber(o_.quality_level, 4)},
            {"min_distance", FormatNumber(o_.min_distance_px, 2)},
            {"window", std::to_string(o_.window_px)},
            {"levels", std::to_string(o_.pyramid_levels)},
            {"motion_threshold", FormatNumber(o_.motion_threshold_px, 2)},
            {"still_frames_drop", std::to_string(o_.still_frames_drop)}};
  }

  // The standstill calibration was refused: no pose will come.
  bool calibration_refused() const { return state_ == State::kFailed; }

  // This frame's pose the tracker withheld as undecided (lk/tracker.h, TrackerPose::undecided),
  // as an ok row would have it, when the gate finds it reachable; null otherwise.
  const internal::UndecidedPose* undecided() const { return undecided_ ? &*undecided_ : nullptr; }

 private:
  enum class State { kStandstill, kStart, kTracking, kFailed };

  ArmMeasurement Standstill(const cv::Mat& view, const cv::Mat& gray, ArmMeasurement& m) {
    m.phase = MeasurementPhase::kSetup;
    m.note = "standstill";
    if (sum_.empty()) sum_ = cv::Mat::zeros(view.size(), CV_32FC3);
    cv::accumulate(view, sum_);
    if (++standstill_count_ < o_.standstill_frames) return m;
    cv::Mat mean;
    sum_.convertTo(mean, CV_8UC3, 1.0 / standstill_count_);
    sum_.release();
    if (!arm_length_.empty()) return Calibrated(mean, view, gray, m);
    const lk::BodyBox body = lk::FindBodyBox(background_, mean, o_);
    if (!body.found) {
      state_ = State::kFailed;
      failure_ = "no person in the standstill: it does not differ from the background";
      m.note = failure_;
      return m;
    }
    body_box_ = body.box + roi_.tl();
    m.body_box = body_box_;
    lk::TrackerStart start;
    start.gray = gray;
    start.bgr = view;
    switch (o_.side) {
      case LkArmSide::kLeft:
        start.shoulders = {body.left_shoulder};
        break;
      case LkArmSide::kRight:
        start.shoulders = {body.right_shoulder};
        break;
      case LkArmSide::kAuto:
        start.shoulders = {body.left_shoulder, body.right_shoulder};
        break;
    }
    const double below_shoulder = body.box.y + body.box.height - body.left_shoulder.y;
    start.arm_length_px = kArmToTrunk * below_shoulder;
    m.estimate = "lk: shoulder (" + FormatNumber(start.shoulders.front().x + roi_.x, 0) + "," +
                 FormatNumber(start.shoulders.front().y + roi_.y, 0) + ") and arm length " +
                 FormatNumber(start.arm_length_px, 0) +
                 " px estimated from the standstill's body box; without the elbow and wrist the "
                 "anchored path runs, which is often confidently wrong on scenes unlike the "
                 "thesis' (docs/accuracy.md): give the shoulder, elbow and wrist, or "
                 "auto-calibrate";

    start.head_limit_y = body.left_shoulder.y - 0.05 * body.box.height;
    tracker_->Start(start);
    state_ = State::kTracking;
    return m;
  }

  // With the arm-length image: the joints from the standstill (common/standstill_calibration.h),
  // then the model tracker as with clicked joints, started on this last standstill frame.
  ArmMeasurement Calibrated(const cv::Mat& mean, const cv::Mat& view, const cv::Mat& gray,
                            ArmMeasurement& m) {
    const StandstillCalibration cal = CalibrateFromStandstill(background_, mean, arm_length_, o_);
    if (!cal.ok) {
      state_ = State::kFailed;
      failure_ = "lk: cannot calibrate from the standstill: " + cal.note;
      m.note = failure_;
      m.estimate = failure_;
      return m;
    }
    o_.initial_upper_deg = DirectionDeg(cal.shoulder, cal.elbow);
    o_.initial_fore_deg = DirectionDeg(cal.elbow, cal.wrist);
    o_.side = cal.side > 0 ? LkArmSide::kRight : LkArmSide::kLeft;
    upper_length_px_ = cv::norm(cal.elbow - cal.shoulder);
    fore_length_px_ = cv::norm(cal.wrist - cal.elbow);
    tracker_ = lk::CreateModelTracker(o_);
    tracker_->SetTime(m.time_s);
    lk::TrackerStart start;
    start.gray = gray;
    start.bgr = view;
    start.shoulders = {cal.shoulder};
    start.shoulder_fixed = true;
    start.arm_length_px = upper_length_px_ + fore_length_px_;
    tracker_->Start(start);
    m.estimate = "lk: " + cal.Describe(cv::Point2d(roi_.tl()));
    m.shoulder_px = cal.shoulder + cv::Point2d(roi_.tl());
    m.elbow_px = cal.elbow + cv::Point2d(roi_.tl());
    m.wrist_px = cal.wrist + cv::Point2d(roi_.tl());
    state_ = State::kTracking;
    return m;
  }

  ArmMeasurement& Fill(const lk::TrackerPose& pose, ArmMeasurement& m) {
    const cv::Point2d off(roi_.tl());
    m.phase = pose.ok ? MeasurementPhase::kOk : MeasurementPhase::kLost;
    m.note = pose.note;
    m.body_box = body_box_;
    if (std::isfinite(pose.support)) m.confidence = std::clamp(pose.support, 0.0, 1.0);
    if (!pose.ok) {
      if (!o_.thesis_mode) gate_.Review(&m, pose.support);
      return m;
    }
    m.upper_deg = pose.upper_deg;
    m.fore_deg = pose.fore_deg;
    m.bend_deg = AngleDiff(pose.fore_deg, pose.upper_deg);
    m.yaw_deg = kNaN;  // not measured by this engine
    m.bent = std::abs(m.bend_deg) > kBentDeg;
    if (pose.have_shoulder) {
      m.shoulder_px = pose.shoulder + off;
      m.elbow_px = pose.elbow + off;
      m.wrist_px = pose.wrist + off;
      m.upper_com_px = pose.upper_com + off;
      m.fore_com_px = pose.fore_com + off;
    }
    const cv::Point2f offf(static_cast<float>(off.x), static_cast<float>(off.y));
    for (const cv::Point2f& p : pose.upper_features) m.upper_features.push_back(p + offf);
    for (const cv::Point2f& p : pose.fore_features) m.fore_features.push_back(p + offf);
    if (o_.thesis_mode) return m;
    if (pose.undecided && gate_.Reachable(m)) {
      undecided_ = internal::UndecidedPose{m, pose.rival_apart_deg};
      undecided_->row.confidence = std::clamp(pose.fit_support, 0.0, 1.0);
    }
    gate_.Review(&m, pose.support);
    return m;
  }

  // Shoulder-to-wrist length as a fraction of the body box below the shoulder (a prior only:
  // the engine learns the elbow from the motion).
  static constexpr double kArmToTrunk = 0.9;
  // With a shoulder but no elbow or wrist: shoulder-to-wrist as a fraction of the analysed
  // height (a guess, reported as such).
  static constexpr double kArmToRoiHeight = 0.4;
  static constexpr double kBentDeg = 10;  // overlay: drawn as bent beyond this

  LkOptions o_;
  std::unique_ptr<lk::Tracker> tracker_;
  ArmGate gate_;  // honest status: weak evidence or an impossible jump is `lost`
  std::optional<internal::UndecidedPose> undecided_;  // this frame's withheld pose
  cv::Size frame_size_;
  cv::Rect roi_;
  cv::Mat background_;
  cv::Mat arm_length_;  // the arm-length image's region; empty when not given
  std::optional<cv::Point2d> shoulder_given_;
  double upper_length_px_ = 0, fore_length_px_ = 0;  // clicked; 0 when not given
  State state_ = State::kStandstill;
  int standstill_count_ = 0;
  cv::Mat sum_;
  std::optional<cv::Rect> body_box_;
  std::string failure_;
};

}  // namespace

namespace internal {
std::unique_ptr<Engine> CreateLkEngine(const LkOptions& options) {
  return std::make_unique<LkEngine>(options);
}

bool LkCalibrationRefused(const Engine& lk) {
  const auto* engine = dynamic_cast<const LkEngine*>(&lk);
  return engine && engine->calibration_refused();
}

const UndecidedPose* LkUndecidedPose(const Engine& lk) {
  const auto* engine = dynamic_cast<const LkEngine*>(&lk);
  return engine ? engine->undecided() : nullptr;
}
}  // namespace internal
}  // namespace armmimic
