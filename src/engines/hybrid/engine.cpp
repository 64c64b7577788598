// The hybrid engine (docs/hybrid.md): lk's model tracker carries the arm, started from the
// standstill's self-calibration (or clicked joints, or the pose network), and a second opinion
// measures the same arm afresh in every frame: bgsub's background difference, or, where there
// is no empty room (joints clicked on real footage), the pose network (hybrid/pose_opinion.h).
// A row is `ok` only when both are and they place each segment alike (hybrid/agreement.h); its
// directions are the mean of the two, its yaw the second opinion's (bgsub's: a straight arm's
// foreshortening against the calibrated length). Where the tracker has lost the arm, the pose
// network's own row stands (its own gate loses a frame it is unsure of); the background
// difference's never does (alone it is wrong on unseen figures). A tracker that has had no pose
// of its own for hybrid.restart_frames rows (lost, or its calibration refused) restarts from the
// second opinion's joints once those have been steady for hybrid.confirm_frames rows. With
// neither (no empty room and no pose model) the rows are lk's alone, as the first row says.
#include <algorithm>
#include <cmath>
#include <string>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "common/arm_gate.h"
#include "common/engine_internal.h"
#include "hybrid/agreement.h"
#include "hybrid/pose_opinion.h"

namespace armmimic {
namespace {

// The two measurements' confidences as one: the lower (either may be unrated, nan).
double Lower(double a, double b) {
  if (!std::isfinite(a)) return b;
  if (!std::isfinite(b)) return a;
  return std::min(a, b);
}

class HybridEngine final : public Engine {
 public:
  HybridEngine(const HybridOptions& hybrid, const LkOptions& lk, const BgsubOptions& bgsub,
               const PoseOptions& pose)
      : o_(hybrid), lk_options_(lk), bgsub_options_(bgsub), pose_options_(pose) {
    // One standstill for both: the frames lk averages are the frames bgsub does.
    bgsub_options_.standstill_frames = lk_options_.standstill_frames;
  }

  EngineKind kind() const override { return EngineKind::kHybrid; }

  Status Begin(const EngineContext& context) override {
    context_ = context;
    lk_ = internal::CreateLkEngine(lk_options_);
    bgsub_.reset();
    pose_.reset();
    alone_why_.clear();
    untracked_ = 0;
    steady_ = 0;
    restarts_ = 0;
    opinion_ok_throughout_ = true;
    if (Status st = lk_->Begin(context); !st) return st;
    if (!context.background.empty() && !context.arm_length.empty()) {
      // The second opinion calibrates itself: clicked joints are the tracker's start, and a
      // measurement that took them too would no longer be apart from it.
      EngineContext own = context;
      own.shoulder_px.reset();
      own.elbow_px.reset();
      own.wrist_px.reset();
      bgsub_ = internal::CreateBgsubEngine(bgsub_options_);
      if (Status st = bgsub_->Begin(own); !st) return st;
      name_ = "the background difference";
    } else {
      pose_ = internal::PoseOpinion::Start(context, pose_options_, &alone_why_);
      name_ = "the pose network";
    }
    first_row_ = true;
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    if (!lk_) throw std::logic_error("hybrid: Process() before a successful Begin()");
    ArmMeasurement m = lk_->Process(frame);
    if (!bgsub_ && !pose_) {
      if (m.row() && first_row_) {
        first_row_ = false;
        m.estimate =
            Join(m.estimate, "hybrid: no background and arm-length image, and no pose network (" +
                                 alone_why_ +
                                 "), so no second opinion: the rows are the tracker's "
                                 "alone");
      }
      return m;
    }
    const ArmMeasurement b = bgsub_ ? bgsub_->Process(frame) : pose_->Process(frame);
    m.estimate = Join(m.estimate, b.estimate);
    if (!m.row()) return m;  // the standstill: both average it
    first_row_ = false;
    // Only a tracker that has lost the arm restarts: one that tracks and disagrees with the
    // background difference is a second opinion to keep apart, and the rows it disagrees on are
    // lost. The pose network sees a real person better than a tracker that disagrees with it
    // (which has drifted): those rows count as the tracker's own pose lost.
    const bool tracked = m.phase == MeasurementPhase::kOk;
    Decide(b, &m);
    const bool disagreed =
        tracked && m.phase != MeasurementPhase::kOk && b.phase == MeasurementPhase::kOk;
    untracked_ = tracked && !(pose_ && disagreed) ? 0 : untracked_ + 1;
    Steady(b);
    if (b.phase != MeasurementPhase::kOk) opinion_ok_throughout_ = false;
    // A tracker that could not calibrate from the standstill has never had a pose of its own:
    // it starts from the background difference's first row, which that engine's own gate
    // checked against the standstill's calibrated pose, as long as every row since was ok.
    const bool never_started = bgsub_ && restarts_ == 0 && opinion_ok_throughout_ && steady_ >= 1 &&
                               internal::LkCalibrationRefused(*lk_);
    if ((untracked_ >= o_.restart_frames && steady_ >= o_.confirm_frames) || never_started) {
      Restart(frame, b, &m);
    }
    return m;
  }

  AngleMeta Describe() const override {
    AngleMeta meta = {{"second_opinion", bgsub_  ? "bgsub"
                                         : pose_ ? "pose"
                                                 : "none"},
                      {"max_disagreement", FormatNumber(o_.max_disagreement_deg, 2)},
                      {"joint_px", FormatNumber(o_.joint_px, 2)},
                      {"restart_frames", std::to_string(o_.restart_frames)},
                      {"confirm_frames", std::to_string(o_.confirm_frames)}};
    if (lk_) {
      for (auto& [key, value] : lk_->Describe()) meta.emplace_back("lk_" + key, value);
    }
    if (bgsub_) {
      for (auto& [key, value] : bgsub_->Describe()) meta.emplace_back("bgsub_" + key, value);
    }
    return meta;
  }

 private:
  // The frame's row from the tracker's (m) and the background difference's (b).
  void Decide(const ArmMeasurement& b, ArmMeasurement* out) {
    ArmMeasurement& m = *out;
    // The background difference's own shapes, drawn under the tracker's joints.
    m.arm_contour = b.arm_contour;
    m.arm_hull = b.arm_hull;
    if (!m.body_box) m.body_box = b.body_box;
    if (m.phase != MeasurementPhase::kOk) {
      if (pose_ && b.phase == MeasurementPhase::kOk) {
        TakeOpinion(b, &m);
        return;
      }
      if (bgsub_ && b.phase == MeasurementPhase::kOk && DecidedByOpinion(b, &m)) return;
      m.note = "the tracker: " + m.note;
      return;
    }
    if (b.phase == MeasurementPhase::kSetup) {
      LoseRow(&m, name_ + ", the second opinion, is still taking the standstill");
      return;
    }
    if (b.phase != MeasurementPhase::kOk) {
      LoseRow(&m, name_ + ", the second opinion: " + b.note);
      return;
    }
    if (const std::string why = internal::Disagreement(m, b, o_, name_); !why.empty()) {
      if (pose_) {
        // A tracker that disagrees with the pose network has drifted (it counts as having lost
        // the arm, below): the network's row stands as where the tracker is lost.
        m.note = why;
        TakeOpinion(b, &m);
        return;
      }
      LoseRow(&m, why);
      return;
    }
    Combine(b, &m);
  }

  // Two measurements that err apart: their mean halves what they do not share.
  static void Combine(const ArmMeasurement& b, ArmMeasurement* m) {
    m->upper_deg = Wrap180(m->upper_deg + Wrap180(b.upper_deg - m->upper_deg) / 2);
    m->fore_deg = Wrap180(m->fore_deg + Wrap180(b.fore_deg - m->fore_deg) / 2);
    m->bend_deg = Wrap180(m->fore_deg - m->upper_deg);
    m->yaw_deg = b.yaw_deg;
    m->confidence = Lower(m->confidence, b.confidence);
  }

  // A pose the tracker withheld because its own evidence could not tell it from a rival far
  // from it (lk/tracker.h, TrackerPose::undecided) stands when the background difference,
  // measured apart from the tracker and supported by its own pixels, places both segments alike:
  // the rival is then not what the frame shows. A rival the background difference agrees with
  // instead, or no agreement, leaves the row lost.
  bool DecidedByOpinion(const ArmMeasurement& b, ArmMeasurement* m) const {
    const internal::UndecidedPose* undecided = internal::LkUndecidedPose(*lk_);
    if (!undecided) return false;
    const ArmMeasurement* u = &undecided->row;
    if (!internal::DisagreementWithRival(*u, b, o_, undecided->rival_apart_deg, name_).empty()) {
      return false;
    }
    TakePose(*u, m);
    m->bent = u->bent;
    Combine(b, m);
    m->note = "the tracker could not tell this pose from another alone (" + u->note + "); " +
              name_ + " places it alike";
    return true;
  }

  // The pose network's own row where the tracker has lost the arm.
  static void TakeOpinion(const ArmMeasurement& b, ArmMeasurement* m) {
    const std::string tracker = m->note;
    TakePose(b, m);
    m->note = "the pose network's row alone (the tracker: " + tracker + ")";
  }

  // `from`'s status, angles, centres, joints and confidence into *m (its overlay shapes kept).
  static void TakePose(const ArmMeasurement& from, ArmMeasurement* m) {
    m->phase = from.phase;
    m->upper_deg = from.upper_deg;
    m->fore_deg = from.fore_deg;
    m->bend_deg = from.bend_deg;
    m->yaw_deg = from.yaw_deg;
    m->upper_com_px = from.upper_com_px;
    m->fore_com_px = from.fore_com_px;
    m->shoulder_px = from.shoulder_px;
    m->elbow_px = from.elbow_px;
    m->wrist_px = from.wrist_px;
    m->confidence = from.confidence;
  }

  // Counts the frames in a row the second opinion has been ok, each pose within
  // max_disagreement_deg of the last.
  void Steady(const ArmMeasurement& b) {
    const bool ok = b.phase == MeasurementPhase::kOk && b.shoulder_px && b.elbow_px && b.wrist_px;
    if (!ok) {
      steady_ = 0;
      return;
    }
    const bool near =
        steady_ > 0 &&
        std::abs(Wrap180(b.upper_deg - steady_upper_deg_)) <= o_.max_disagreement_deg &&
        std::abs(Wrap180(b.fore_deg - steady_fore_deg_)) <= o_.max_disagreement_deg;
    steady_ = near ? steady_ + 1 : 1;
    steady_upper_deg_ = b.upper_deg;
    steady_fore_deg_ = b.fore_deg;
  }

  // A tracker that has had no pose of its own for a while (lost, or never calibrated) starts
  // again from the second opinion's joints in this frame, as if they had been clicked. This
  // frame's row stays what Decide made it: the tracker has no pose of its own in it.
  void Restart(const Frame& frame, const ArmMeasurement& b, ArmMeasurement* m) {
    EngineContext c = context_;
    c.shoulder_px = *b.shoulder_px;
    c.elbow_px = *b.elbow_px;
    c.wrist_px = *b.wrist_px;
    std::unique_ptr<Engine> lk = internal::CreateLkEngine(lk_options_);
    if (!lk->Begin(c)) return;  // joints lk cannot start from: keep waiting
    lk->Process(frame);         // the start posture: no measurement of its own
    lk_ = std::move(lk);
    untracked_ = 0;
    ++restarts_;
    m->note += "; the tracker restarts from " + name_ + "'s joints (restart " +
               std::to_string(restarts_) + ")";
  }

  static std::string Join(const std::string& a, const std::string& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return a + "; " + b;
  }

  HybridOptions o_;
  LkOptions lk_options_;
  BgsubOptions bgsub_options_;
  PoseOptions pose_options_;
  std::unique_ptr<Engine> lk_;
  std::unique_ptr<Engine> bgsub_;                // the second opinion; null without a background
  std::unique_ptr<internal::PoseOpinion> pose_;  // or this one, without a background
  std::string name_;                             // the second opinion's, for notes
  std::string alone_why_;                        // why neither could start
  bool first_row_ = true;
  EngineContext context_;        // the run's, for a restarted tracker
  int untracked_ = 0;            // rows in a row the tracker has had no pose of its own
  int steady_ = 0;               // rows in a row the background difference has been steady
  double steady_upper_deg_ = 0;  // its last pose
  double steady_fore_deg_ = 0;
  int restarts_ = 0;
  bool opinion_ok_throughout_ = true;  // the second opinion ok on every row so far
};

}  // namespace

namespace internal {

std::unique_ptr<Engine> CreateHybridEngine(const HybridOptions& hybrid, const LkOptions& lk,
                                           const BgsubOptions& bgsub, const PoseOptions& pose) {
  return std::make_unique<HybridEngine>(hybrid, lk, bgsub, pose);
}

}  // namespace internal
}  // namespace armmimic
