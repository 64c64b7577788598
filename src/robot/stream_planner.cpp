#include "armmimic/robot/stream_planner.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"

namespace armmimic::robot {
namespace {

constexpr double kPi = 3.14159265358979323846;

double RoundTo(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

// The largest step towards `want` that is a whole number of written units and at most `limit`.
double LimitStep(double want, double limit, int decimals) {
  if (std::abs(want) <= limit) return want;
  const double scale = std::pow(10.0, decimals);
  const double step = std::floor(limit * scale + 1e-9) / scale;
  return want > 0 ? step : -step;
}

}  // namespace

const char* HoldReasonName(HoldReason reason) {
  switch (reason) {
    case HoldReason::kNone:
      return "following";
    case HoldReason::kNoData:
      return "no measurement yet";
    case HoldReason::kLost:
      return "lost";
    case HoldReason::kJump:
      return "impossible jump";
    case HoldReason::kLimits:
      return "outside the limits";
    case HoldReason::kStale:
      return "no recent frame";
    case HoldReason::kDeadband:
      return "deadband or min interval";
    case HoldReason::kOperator:
      return "held by the operator";
  }
  return "?";
}

double StreamPlanner::Biquad::Step(double x) {
  const double y = b0 * x + z1;
  z1 = b1 * x - a1 * y + z2;
  z2 = b2 * x - a2 * y;
  return y;
}

void StreamPlanner::Biquad::Reset(double x) {
  // The steady state of a constant input x (the same start as the offline filter's passes).
  z2 = (b2 - a2) * x;
  z1 = (1 - b0) * x;
}

Status StreamPlanner::Begin(const PlannerOptions& options, SourceKind kind, double sample_rate_hz,
                            int decimals, double stale_after_s) {
  *this = StreamPlanner();
  Status s = options.Check();
  if (!s.ok()) return s;
  options_ = options;
  s = MappingForSource(options.mapping, kind, &options_.mapping);
  if (!s.ok()) return s;
  if (!(sample_rate_hz > 0) || !std::isfinite(sample_rate_hz)) {
    return Status::Error("the source has no frame rate: live mimicking needs one");
  }
  if (!(stale_after_s > 0)) return Status::Error("the stale-frame timeout must be > 0 s");
  fs_ = sample_rate_hz;
  decimals_ = decimals;
  stale_after_s_ = stale_after_s;
  filter_on_ = options.cutoff_hz > 0;
  if (filter_on_) {
    if (!(options.cutoff_hz < 0.5 * fs_)) {
      return Status::Error("cutoff " + FormatNumber(options.cutoff_hz, 2) +
                           " Hz must be below half the frame rate (" + FormatNumber(fs_, 3) +
                           " fps)");
    }
    // 2nd-order Butterworth low-pass by the bilinear transform, as filter.cpp, run forwards.
    const double k = std::tan(kPi * options.cutoff_hz / fs_);
    const double s2 = std::sqrt(2.0);
    const double norm = 1.0 / (1.0 + s2 * k + k * k);
    for (Biquad& f : filter_) {
      f.b0 = k * k * norm;
      f.b1 = 2 * f.b0;
      f.b2 = f.b0;
      f.a1 = 2 * (k * k - 1) * norm;
      f.a2 = (1 - s2 * k + k * k) * norm;
    }
  }
  return Status::Ok();
}

double StreamPlanner::StepHorizonS() const {
  return std::min(options_.max_interval_s, std::max(2 * options_.min_interval_s, 0.1));
}

double StreamPlanner::FilterDelayS() const {
  return filter_on_ ? std::sqrt(2.0) / (2 * kPi * options_.cutoff_hz) : 0.0;
}

// Steps 1 (unwrap, jumps): true with the unwrapped values for a measured frame.
bool StreamPlanner::Measure(const AngleRow& row, double prev_row_t, double* upper, double* bend,
                            double* yaw) {
  const bool marker = options_.mapping.kind == SourceKind::kMarker;
  const double t = row.time_s;
  if (!row.ok()) return false;
  double u = marker ? 0.0 : row.upper_deg;
  double b = row.bend_deg;
  // The marker engine's signed yaw turns J1; nan (the sign could not be told) holds it.
  const double turn = marker ? row.yaw_signed_deg : row.yaw_deg;
  double y = std::isfinite(turn) ? turn : kNaN;
  // An arm engine's 3-D columns, when it measures them (docs/robot.md, "Mapping the 3-D columns").
  const MappingOptions& m = options_.mapping;
  if (!marker && m.arm_3d && m.image_side != 0 && std::isfinite(row.upper_az_deg) &&
      !SourcesFrom3d(row, m.image_side, &u, &b, &y)) {
    return false;
  }
  if (!std::isfinite(u) || !std::isfinite(b)) return false;
  if (have_prev_) {
    u -= 360.0 * std::round((u - prev_upper_) / 360.0);
    b -= 360.0 * std::round((b - prev_bend_) / 360.0);
    const double allowed = options_.max_jump_deg_s * (t - ref_t_);
    double jump = std::max(std::abs(u - prev_upper_), std::abs(b - prev_bend_));
    if (!std::isnan(y) && !std::isnan(prev_yaw_)) jump = std::max(jump, std::abs(y - prev_yaw_));
    if (jump > allowed) {
      ref_t_ += t - prev_row_t;  // time in flagged frames earns no allowance
      ++stats_.flagged_jumps;
      newest_ = HoldReason::kJump;
      return false;
    }
  }
  prev_upper_ = u;
  prev_bend_ = b;
  prev_yaw_ = y;
  ref_t_ = t;
  *upper = u;
  *bend = b;
  *yaw = y;
  return true;
}

void StreamPlanner::Push(const AngleRow& row, double now_s) {
  ++stats_.frames;
  newest_ = HoldReason::kLost;
  const bool had_prev = have_prev_;
  const double prev_row_t = prev_row_t_;
  prev_row_t_ = row.time_s;
  double upper = 0, bend = 0, yaw = kNaN;
  if (!Measure(row, prev_row_t, &upper, &bend, &yaw)) {
    if (newest_ == HoldReason::kLost) ++stats_.lost;
    return;
  }
  have_prev_ = true;
  ++stats_.ok;
  if (!std::isnan(yaw)) held_yaw_ = yaw;
  const JointArray mapped =
      options_.mapping.Map(upper, bend, std::isnan(held_yaw_) ? 0.0 : held_yaw_);
  // 4. Causal low-pass; restarted after a long gap so stale values do not slide in.
  const bool restart = !had_prev || row.time_s - last_good_t_ > options_.max_gap_s + 1e-9;
  last_good_t_ = row.time_s;
  if (restart && had_prev) ++stats_.restarts;
  JointArray q = mapped;
  if (filter_on_) {
    for (int j = 0; j < 3; ++j) {
      if (restart) filter_[j].Reset(mapped[j]);
      q[j] = filter_[j].Step(mapped[j]);
    }
  }
  // 5. Limits.
  for (int j = 0; j < kJoints; ++j) {
    if (options_.limits.Inside(j, q[j])) continue;
    if (!options_.clamp) {
      ++stats_.limit_holds;
      newest_ = HoldReason::kLimits;
      return;
    }
    q[j] = std::clamp(q[j], options_.limits.min_deg[j], options_.limits.max_deg[j]);
    ++stats_.clamped;
  }
  target_ = q;
  has_target_ = true;
  target_frame_ = row.frame;
  newest_ = HoldReason::kNone;
  last_good_now_s_ = now_s;
}

HoldReason StreamPlanner::holding(double now_s) const {
  if (newest_ != HoldReason::kNone) return newest_;  // kNoData until the first target
  if (now_s - last_good_now_s_ > stale_after_s_) return HoldReason::kStale;
  return HoldReason::kNone;
}

bool StreamPlanner::Next(double now_s, StreamCommand* out) const {
  if (holding(now_s) != HoldReason::kNone) return false;
  JointArray want{};
  for (int j = 0; j < kJoints; ++j) want[j] = RoundTo(target_[j], decimals_);
  StreamCommand c;
  c.frame = target_frame_;
  c.time_s = now_s;
  if (!has_sent_) {
    c.joint_deg = want;
    *out = c;
    return true;
  }
  // 6. Deadband and intervals.
  const double dt = now_s - last_sent_s_;
  double moved = 0;
  for (int j = 0; j < kJoints; ++j) moved = std::max(moved, std::abs(want[j] - last_sent_[j]));
  const double unit = 0.5 * std::pow(10.0, -decimals_);
  const bool by_motion = moved > options_.deadband_deg && dt >= options_.min_interval_s - 1e-9;
  const bool by_time = moved > unit && dt >= options_.max_interval_s - 1e-9;
  if (!by_motion && !by_time) return false;
  // 7. Speed: at most max_speed * dt per joint, the robot lags rather than hurries.
  const double dt_speed = std::min(dt, StepHorizonS());
  bool changed = false;
  for (int j = 0; j < kJoints; ++j) {
    const double want_step = want[j] - last_sent_[j];
    const double step =
        LimitStep(want_step, options_.limits.max_speed_deg_s[j] * dt_speed, decimals_);
    if (step != want_step) c.rate_limited = true;
    c.joint_deg[j] = RoundTo(last_sent_[j] + step, decimals_);
    changed = changed || c.joint_deg[j] != last_sent_[j];
  }
  if (!changed) return false;
  *out = c;
  return true;
}

void StreamPlanner::Written(double time_s) {
  if (has_sent_ && std::isfinite(time_s)) last_sent_s_ = std::max(last_sent_s_, time_s);
}

void StreamPlanner::Sent(const StreamCommand& command) {
  last_sent_ = command.joint_deg;
  last_sent_s_ = command.time_s;
  has_sent_ = true;
  ++stats_.commands;
  if (command.rate_limited) ++stats_.rate_limited;
}

}  // namespace armmimic::robot
