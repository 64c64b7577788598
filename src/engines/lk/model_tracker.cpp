// The model tracker: the LK engine's default path when the arm's joints are known in the start
// frame. From that frame it learns what the arm looks like (arm_appearance.h: its colour against
// its surroundings, the segments' widths, the hand) and starts learning the scene without the
// arm. Every later frame the features (lk/arm_flow.h) predict how the arm moved; the two-segment
// model (arm_model_fit.h) is then fitted around that prediction and around the last pose, and
// over every pose the arm can take. The frame is written with a confidence: how well the best
// pose explains the image compared with how well the arm usually does, and `lost` when that is
// weak or when a far-apart pose explains the image about as well.
// Length: Track is one frame's search whose stages share the candidate poses and their scores.
#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angle_file.h"
#include "common/arm_model_fit.h"
#include "lk/arm_flow.h"
#include "lk/tracker.h"

namespace armmimic::lk {
namespace {

constexpr double kLocalRangeDeg = 15;  // searched around each prediction
constexpr int kGlobalCandidates = 4;   // poses kept from the search over every pose
constexpr double kDistinctDeg = 15;    // poses farther apart than this are different poses
// A pose found anywhere replaces the local one when it explains the image this much better (a
// share of the arm's usual score): the arm moved beyond the features and the local search.
constexpr double kRedetectMargin = 0.15;
// A far-apart pose scoring at least this share of the best one makes the frame ambiguous.
constexpr double kAmbiguousShare = 0.9;
// The forearm alone: another forearm direction this far from the fitted one (the upper arm kept)
// scoring at least this share of the fitted forearm leaves the forearm's direction unsaid (a
// forearm across the torso in the shirt's cloth, a sleeve washed out by the light).
constexpr double kForeApartDeg = 20;
constexpr double kForeAmbiguousShare = 0.62;
constexpr double kTypicalRate = 0.05, kTypicalStartRate = 0.3;
constexpr int kTypicalStartFrames = 10;
constexpr double kTypicalDecay = 0.995;  // per lost frame: the bar lowers slowly
constexpr double kBackgroundRate = 0.2;
constexpr double kVelocityGain = 0.5;
constexpr int kMinTurnFeatures = 3;
constexpr double kMaxShoulderShiftShare = 0.1;  // of the upper arm, per frame
constexpr double kReachMargin = 1.15;           // evidence region around the shoulder
// A pose with this share of its pixels where the learnt scene has never been seen without the arm
// is supported there by colour alone (the cloth the arm hid looks like the arm); below the lower
// share it lies where the scene is known.
constexpr double kUnseenShare = 0.25, kSeenShare = 0.1;

class ModelTracker : public Tracker {
 public:
  explicit ModelTracker(const LkOptions& options) : o_(options), flow_(options) {}

  TrackerPose Start(const TrackerStart& start) override {
    size_ = start.gray.size();
    background_ = arm::LearntBackground();
    pose_.shoulder = start.shoulders.front();
    start_shoulder_ = pose_.shoulder;
    pose_.upper_deg = Wrap180(o_.initial_upper_deg);
    pose_.fore_deg = Wrap180(o_.initial_fore_deg);
    arm::ArmShape lengths;
    if (start.upper_length_px > 0 && start.fore_length_px > 0) {
      lengths.upper_px = start.upper_length_px;
      lengths.fore_px = start.fore_length_px;
    } else {
      const double arm = start.arm_length_px > 0 ? start.arm_length_px : 0.4 * start.gray.rows;
      lengths.upper_px = o_.upper_fraction * arm;
      lengths.fore_px = arm - lengths.upper_px;
    }
    const arm::ArmJoints joints = arm::JointsOf(pose_, lengths);
    arm::LearntArm learnt = arm::LearnArm(start.bgr, joints, Reach(lengths));
    shape_ = learnt.shape;
    colour_ = std::move(learnt.colour);
    background_.Reset(start.bgr, Hidden(pose_));
    flow_.Reset(start.gray);
    flow_.Refresh(start.gray, pose_, shape_);
    typical_ = -1;
    frame_ = 0;
    anchor_ = pose_;
    weak_ = false;
    wide_ = arm::WideSearchMemory();
    seen_elsewhere_ = false;
    reach_deg_ = 0;
    last_time_s_ = time_s_;
    upper_velocity_ = fore_velocity_ = 0;
    return MakePose(true, 1, "start: the calibrated posture");
  }

  TrackerPose Track(const cv::Mat& gray, const cv::Mat& bgr) override {
    ++frame_;
    const FlowCue cue = flow_.Track(gray, pose_, shape_);
    arm::ArmPose held = pose_;
    if (o_.shoulder_sway > 0 && cue.body_count > 0 &&
        cv::norm(cue.shoulder_shift) < kMaxShoulderShiftShare * shape_.upper_px) {
      held.shoulder += cue.shoulder_shift;
      const cv::Point2d off = held.shoulder - start_shoulder_;
      const double far = cv::norm(off), limit = o_.shoulder_sway * shape_.upper_px;
      if (far > limit) held.shoulder = start_shoulder_ + (limit / far) * off;
    }
    arm::ArmPose moved = held;
    moved.upper_deg =
        Wrap180(held.upper_deg +
                (cue.upper_count >= kMinTurnFeatures ? cue.upper_turn_deg : upper_velocity_));
    moved.fore_deg = Wrap180(
        held.fore_deg + (cue.fore_count >= kMinTurnFeatures ? cue.fore_turn_deg : fore_velocity_));
    const double r = kReachMargin * Reach(shape_) + 4;
    const cv::Rect region(cvFloor(held.shoulder.x - r), cvFloor(held.shoulder.y - r), cvCeil(2 * r),
                          cvCeil(2 * r));
    evidence_.Compute(bgr, background_, colour_, region, Hidden(pose_));

    arm::LocalSearch local;
    local.upper_range_deg = local.bend_range_deg = kLocalRangeDeg;
    arm::FitResult best = arm::FitNear(evidence_, shape_, moved, local);
    if (arm::PoseDistanceDeg(moved, held) > 3) {
      const arm::FitResult near_held = arm::FitNear(evidence_, shape_, held, local);
      if (near_held.score.total > best.score.total) best = near_held;
    }
    if (typical_ < 0) typical_ = std::max(kMinTypical, best.score.total);
    // Where the arm can be: within what it can turn since the last confident frame. The reach
    // grows only while the pose being tracked is itself weak (the arm is not where it was
    // followed); a far pose that merely explains the frame better is a rival, not a new lock.
    const double dt = time_s_ > last_time_s_ ? time_s_ - last_time_s_ : kDefaultFrameS;
    last_time_s_ = time_s_;
    const double step = o_.max_speed_deg_s * dt;
    reach_deg_ = weak_ ? reach_deg_ + step : step;
    const std::vector<arm::FitResult> anywhere =
        arm::FitAnywhere(evidence_, shape_, held.shoulder, kGlobalCandidates, &wide_);
    std::string note = "model";
    for (const arm::FitResult& f : anywhere) {
      if (arm::PoseDistanceDeg(f.pose, anchor_) > reach_deg_) continue;
      if (arm::PoseDistanceDeg(f.pose, best.pose) > kDistinctDeg &&
          f.score.total > best.score.total + kRedetectMargin * typical_) {
        best = f;
        note = "model: found again away from the prediction";
      }
      break;  // best first: the best reachable pose
    }
    double rival = -2;
    for (const arm::FitResult& f : anywhere) {
      if (arm::PoseDistanceDeg(f.pose, best.pose) > kDistinctDeg)
        rival = std::max(rival, f.score.total);
    }
    const double ratio = best.score.total / typical_;
    double support = std::clamp(ratio, 0.0, 1.0);
    weak_ = support < o_.min_support;
    const bool ambiguous = rival > kAmbiguousShare * best.score.total;
    if (ambiguous) {
      support = 0;
      note = "ambiguous: a pose " + FormatNumber(kDistinctDeg, 0) +
             "+ deg away explains the frame as well";
    }
    // The forearm's own margin decides only what is written: the pose is still the best one, and
    // is tracked on as before.
    double written = support;
    double rival_apart_deg = kNaN;
    if (written >= o_.min_support && ForeAmbiguous(best)) {
      written = 0;
      rival_apart_deg = kForeApartDeg;
      note = "ambiguous forearm: a direction " + FormatNumber(kForeApartDeg, 0) +
             "+ deg away explains it as well";
    }
    // Updated on every frame: the arm is seen elsewhere mostly on frames that are lost anyway.
    const bool unconfirmed = Unconfirmed(best, anywhere, support);
    if (written >= o_.min_support && unconfirmed) {
      written = 0;
      rival_apart_deg = kDistinctDeg;
      note =
          "unconfirmed: where the scene was never seen without the arm, and the arm was seen "
          "elsewhere";
    }
    note += " (score " + FormatNumber(best.score.total, 2) + " of a usual " +
            FormatNumber(typical_, 2) + ")";
    const bool confident = support >= o_.min_support;
    const double du = AngleDiff(best.pose.upper_deg, pose_.upper_deg);
    const double df = AngleDiff(best.pose.fore_deg, pose_.fore_deg);
    pose_ = best.pose;
    if (!weak_) anchor_ = pose_;
    if (confident) {
      const double rate = frame_ <= kTypicalStartFrames ? kTypicalStartRate : kTypicalRate;
      typical_ = std::max(kMinTypical, (1 - rate) * typical_ + rate * best.score.total);
      background_.Update(bgr, Hidden(pose_), kBackgroundRate, region, evidence_, colour_);
      upper_velocity_ = (1 - kVelocityGain) * upper_velocity_ + kVelocityGain * du;
      fore_velocity_ = (1 - kVelocityGain) * fore_velocity_ + kVelocityGain * df;
      flow_.Refresh(gray, pose_, shape_);
    } else {
      typical_ = std::max(kMinTypical, kTypicalDecay * typical_);
      upper_velocity_ = fore_velocity_ = 0;
      flow_.ForgetArm();
    }
    TrackerPose out = MakePose(true, written, note);
    out.undecided = confident && written < o_.min_support;
    out.rival_apart_deg = rival_apart_deg;
    out.fit_support = support;
    return out;
  }

 private:
  static constexpr double kMinTypical = 0.1;
  static constexpr double kDefaultFrameS = 1.0 / 30;  // still images: one frame at 30 fps

  // Another forearm direction, the upper arm kept, explains the image about as well as the
  // fitted forearm: its evidence does not say where it points.
  bool ForeAmbiguous(const arm::FitResult& best) const {
    const double rival = arm::ForeRivalScore(evidence_, shape_, best.pose, kForeApartDeg);
    return rival > kForeAmbiguousShare * best.score.fore.score;
  }

  // Evidence where the learnt scene is unknown (the pixels the arm hid at the start) is colour
  // alone: the torso in the sleeve's cloth behind the starting posture scores like the arm. Once a
  // pose on known pixels has explained a frame better than the tracked one (the arm seen
  // elsewhere), a pose lying partly on unknown pixels is unconfirmed until the arm is found again
  // where the scene is known. Like the forearm's margin, this decides only what is written.
  bool Unconfirmed(const arm::FitResult& best, const std::vector<arm::FitResult>& anywhere,
                   double support) {
    const double unseen = UnseenShare(best.pose);
    for (const arm::FitResult& f : anywhere) {
      if (f.score.total > best.score.total &&
          arm::PoseDistanceDeg(f.pose, best.pose) > kDistinctDeg &&
          UnseenShare(f.pose) <= kUnseenShare) {
        seen_elsewhere_ = true;
        break;
      }
    }
    if (seen_elsewhere_ && unseen > kUnseenShare) return true;
    if (support >= o_.min_support && unseen < kSeenShare) seen_elsewhere_ = false;
    return false;
  }

  // The share of the arm's pixels in `pose` where the learnt scene is unknown: still as the start
  // frame showed them, the arm hiding the scene.
  double UnseenShare(const arm::ArmPose& pose) const {
    cv::Mat mask = cv::Mat::zeros(background_.known().size(), CV_8U);
    arm::DrawArm(mask, arm::JointsOf(pose, shape_), shape_, 0);
    const int all = cv::countNonZero(mask);
    if (all == 0) return 0;
    mask.setTo(0, background_.known());
    return static_cast<double>(cv::countNonZero(mask)) / all;
  }

  static double Reach(const arm::ArmShape& s) { return s.upper_px + s.fore_px + s.hand_px; }

  // The pixels the arm in `pose` covers, with a margin: not learnt as background, and left out of
  // the noise estimate.
  cv::Mat Hidden(const arm::ArmPose& pose) const {
    cv::Mat mask = cv::Mat::zeros(background_.empty() ? size_ : background_.image().size(), CV_8U);
    const double grow = std::max(2.0, 0.5 * std::max(shape_.upper_hw, shape_.fore_hw)) + 1;
    arm::DrawArm(mask, arm::JointsOf(pose, shape_), shape_, grow);
    return mask;
  }

  TrackerPose MakePose(bool ok, double support, const std::string& note) const {
    const arm::ArmJoints j = arm::JointsOf(pose_, shape_);
    TrackerPose p = MakeTrackerPose(pose_.upper_deg, pose_.fore_deg, true, j.shoulder, j.elbow,
                                    j.wrist, flow_.Points(1), flow_.Points(2), note);
    p.ok = ok;
    p.support = support;
    return p;
  }

  LkOptions o_;
  ArmFlow flow_;
  cv::Size size_;
  arm::ArmPose pose_;
  cv::Point2d start_shoulder_;  // the calibrated shoulder
  arm::ArmShape shape_;
  arm::ColourModel colour_;
  arm::LearntBackground background_;
  arm::EvidenceMap evidence_;
  // What the last frame's search over every pose leaves this frame's: it saves work only.
  arm::WideSearchMemory wide_;
  double typical_ = -1;  // the arm's usual score (confident frames)
  arm::ArmPose anchor_;  // the last well-supported pose
  bool weak_ = false;    // the last frame's pose was weakly supported
  // A pose on known pixels beat the tracked one since the arm was last found on known pixels.
  bool seen_elsewhere_ = false;
  double reach_deg_ = 0;  // how far the arm may have turned from anchor_
  double last_time_s_ = 0;
  int frame_ = 0;
  double upper_velocity_ = 0, fore_velocity_ = 0;  // degrees a frame
};

}  // namespace

std::unique_ptr<Tracker> CreateModelTracker(const LkOptions& options) {
  return std::make_unique<ModelTracker>(options);
}

}  // namespace armmimic::lk
