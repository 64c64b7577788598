#include "common/arm_gate.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"

namespace armmimic {

void ArmGate::Reset() {
  confirmed_ = o_.start_confirmed;
  have_last_ = false;
  run_length_ = 0;
  frame_dt_ = 0;
  missed_ = false;
  after_gap_s_ = 0;
}

void ArmGate::Anchor(double upper_deg, double fore_deg, double time_s) {
  last_.upper_deg = upper_deg;
  last_.bend_deg = AngleDiff(fore_deg, upper_deg);
  last_.time_s = time_s;
  have_last_ = true;
  confirmed_ = true;
  run_length_ = 0;
  missed_ = false;
}

double ArmGate::Reach(double dt_s) const {
  // At least one frame's worth (the smallest step seen; 30 fps before one is seen).
  const double dt = std::max(dt_s, frame_dt_ > 0 ? frame_dt_ : 1.0 / 30);
  return o_.max_speed_deg_s * dt;
}

bool ArmGate::Consistent(const Pose& from, const Pose& to) const {
  // Still images (no time between them) can hold any poses: no speed to check.
  if (!(to.time_s > from.time_s)) return true;
  const double reach = Reach(to.time_s - from.time_s);
  return std::abs(AngleDiff(to.upper_deg, from.upper_deg)) <= reach &&
         std::abs(AngleDiff(to.bend_deg, from.bend_deg)) <= reach;
}

ArmGate::Pose ArmGate::PoseOf(const ArmMeasurement& m) {
  Pose p;
  p.upper_deg = m.upper_deg;
  p.bend_deg = AngleDiff(m.fore_deg, m.upper_deg);
  p.time_s = m.time_s;
  return p;
}

bool ArmGate::GapVouchesForNothing(const Pose& now) const {
  return o_.confirm_after_gap && confirmed_ && have_last_ && missed_ &&
         Reach(now.time_s - last_.time_s) >= 180;
}

bool ArmGate::Reachable(const ArmMeasurement& m) const {
  if (!confirmed_ || !std::isfinite(m.upper_deg) || !std::isfinite(m.fore_deg)) return false;
  if (!have_last_) return true;
  const Pose now = PoseOf(m);
  return !GapVouchesForNothing(now) && Consistent(last_, now);
}

void LoseRow(ArmMeasurement* m, const std::string& why) {
  m->phase = MeasurementPhase::kLost;
  m->note = why;
  m->upper_deg = m->fore_deg = m->yaw_deg = m->bend_deg = kNaN;
  m->upper_com_px = m->fore_com_px = cv::Point2d(kNaN, kNaN);
}

void ArmGate::Lose(ArmMeasurement* m, const std::string& why) {
  LoseRow(m, why + (m->note.empty() ? "" : " (" + m->note + ")"));
}

void ArmGate::Review(ArmMeasurement* m, double support) {
  if (m->phase != MeasurementPhase::kOk) {
    run_length_ = 0;
    missed_ = true;
    return;
  }
  if (std::isfinite(support) && support < o_.min_support) {
    run_length_ = 0;
    missed_ = true;
    Lose(m, "evidence too weak (support " + FormatNumber(support, 2) + ")");
    return;
  }
  const Pose now = PoseOf(*m);
  if (have_last_ && now.time_s > last_.time_s) {
    const double dt = now.time_s - last_.time_s;
    frame_dt_ = frame_dt_ > 0 ? std::min(frame_dt_, dt) : dt;
  }
  if (GapVouchesForNothing(now)) {
    // Frames without a pose since the last accepted one, so many that an arm could have turned
    // anywhere: the speed check vouches for nothing, and the pose needs agreeing frames as after
    // a rejected jump.
    confirmed_ = false;
    run_length_ = 0;
    after_gap_s_ = now.time_s - last_.time_s;
  }
  if (confirmed_) {
    if (!have_last_ || Consistent(last_, now)) {
      last_ = now;
      have_last_ = true;
      missed_ = false;
      return;
    }
    const double turn = std::max(std::abs(AngleDiff(now.upper_deg, last_.upper_deg)),
                                 std::abs(AngleDiff(now.bend_deg, last_.bend_deg)));
    const double dt = now.time_s - last_.time_s;
    confirmed_ = false;
    after_gap_s_ = 0;
    run_last_ = now;
    run_length_ = 1;
    Lose(m, "jump of " + FormatNumber(turn, 0) + " deg in " + FormatNumber(dt, 3) +
                " s, faster than an arm turns");
    return;
  }
  // Unconfirmed: a run of agreeing candidates re-acquires the arm.
  run_length_ = run_length_ > 0 && Consistent(run_last_, now) ? run_length_ + 1 : 1;
  run_last_ = now;
  if (run_length_ >= o_.confirm_frames) {
    confirmed_ = true;
    run_length_ = 0;
    last_ = now;
    have_last_ = true;
    missed_ = false;
    m->note = "re-acquired; " + m->note;
    return;
  }
  const std::string gap =
      after_gap_s_ > 0 ? " after " + FormatNumber(after_gap_s_, 2) + " s without a pose" : "";
  Lose(m, "re-acquiring" + gap + " (" + std::to_string(run_length_) + "/" +
              std::to_string(o_.confirm_frames) + " agreeing frames)");
}

}  // namespace armmimic
