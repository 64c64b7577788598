// StreamPlanner: the planner (planner.h) applied causally, one analysed frame at a time, for live
// mimicking (docs/live.md). The same options and the same steps, each changed only where the
// offline planner looks ahead:
//   1. unwrap from the last measured frame; a change faster than max_jump_deg_s is flagged and
//      the frame treated as lost (time in flagged frames earns no allowance, as offline);
//   2. a lost or flagged frame holds: no new target, the robot stays where it was sent. A gap
//      (no measured frame) longer than stale_after_s holds too. Nothing is ever extrapolated,
//      and nothing is interpolated (that would need the frame after the gap);
//   3. the same mapping; yaw held while NaN (0 until the first measured yaw);
//   4. the low-pass is the same 2nd-order Butterworth run forwards only (no look-ahead): it
//      lags by FilterDelayS() (sqrt(2) / (2 pi cutoff), 75 ms at 3 Hz). After a gap longer than
//      max_gap_s it restarts at the next measurement instead of sliding from stale values;
//   5. a target outside the limits is clamped with `clamp`, otherwise that frame holds;
//   6. a command goes out when the link is free and a joint moved more than deadband_deg from
//      the last command (not sooner than min_interval_s after it), or max_interval_s passed
//      with any change;
//   7. no step is faster than the speed limits: each joint moves at most max_speed * dt towards
//      its target, dt being the time since the last command, so the robot lags rather than
//      hurries. dt is capped at StepHorizonS() (twice min_interval_s): a controller acknowledges
//      a move when it has ended, so smaller steps keep the robot turning towards the newest
//      target instead of finishing a long move towards an old one. The targets are rounded as
//      written (profile decimals), and the safety gate checks every line again with the same times
//      before it is written.
#pragma once

#include <string>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/robot/limits.h"
#include "armmimic/robot/mapping.h"
#include "armmimic/robot/planner.h"

namespace armmimic::robot {

// Why the robot is holding (no command would go out now).
enum class HoldReason {
  kNone,      // following
  kNoData,    // no measured frame yet
  kLost,      // the newest frame is lost
  kJump,      // the newest frame changed impossibly fast (treated as lost)
  kLimits,    // the newest target is outside the limits (and clamp is off)
  kStale,     // no measured frame for longer than stale_after_s
  kDeadband,  // following, but the target has not moved enough (or too soon) for a command
  kOperator,  // the operator holds the robot (dead-man released, not confirmed, stopped)
};
const char* HoldReasonName(HoldReason reason);  // "lost", "stale", ...

struct StreamCommand {
  JointArray joint_deg{};     // rounded to the profile's decimals
  int frame = -1;             // the frame whose target this is
  double time_s = 0;          // stream clock when it is written
  bool rate_limited = false;  // a joint was held back by its speed limit
};

struct StreamStats {
  int frames = 0;
  int ok = 0;
  int lost = 0;
  int flagged_jumps = 0;
  int limit_holds = 0;
  int clamped = 0;
  int restarts = 0;  // filter restarts after a long gap
  int commands = 0;
  int rate_limited = 0;
};

class StreamPlanner {
 public:
  // `sample_rate_hz`: the source's frame rate (the filter's design rate; must be more than twice
  // the cutoff). `decimals`: how targets are written (ControllerProfile::decimals).
  Status Begin(const PlannerOptions& options, SourceKind kind, double sample_rate_hz,
               int decimals = 2, double stale_after_s = 0.2);
  // One analysed frame, arriving at `now_s` on the stream clock (the row's own time_s is the
  // video's, used for the jump allowance).
  void Push(const AngleRow& row, double now_s);
  // The command to write at `now_s` when the link is free, or false (holding(now_s) says why).
  bool Next(double now_s, StreamCommand* out) const;
  // The command went out (Next's output).
  void Sent(const StreamCommand& command);
  // The last command reached the port at `time_s` (on the clock of `now_s`), which under load can
  // be later than it was planned for: the next step is limited from then, so the step between
  // two writes never exceeds the speed limit over the time between the writes themselves.
  void Written(double time_s);

  HoldReason holding(double now_s) const;
  // The filtered, limited target of the newest measured frame (valid once one was measured).
  bool has_target() const { return has_target_; }
  const JointArray& target() const { return target_; }
  int target_frame() const { return target_frame_; }
  bool has_sent() const { return has_sent_; }
  const JointArray& last_sent() const { return last_sent_; }
  const StreamStats& stats() const { return stats_; }
  const MappingOptions& mapping() const { return options_.mapping; }
  // The low-pass's lag at low frequencies, in seconds (0 with the filter off).
  double FilterDelayS() const;
  // The longest time one command's step may cover (the cap on dt in step 7).
  double StepHorizonS() const;
  double stale_after_s() const { return stale_after_s_; }

 private:
  struct Biquad {
    double b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0;
    double z1 = 0, z2 = 0;
    double Step(double x);
    void Reset(double x);
  };
  bool Measure(const AngleRow& row, double prev_row_t, double* upper, double* bend, double* yaw);

  PlannerOptions options_;
  double stale_after_s_ = 0.2;
  double fs_ = 30;
  int decimals_ = 2;
  bool filter_on_ = false;
  Biquad filter_[3];
  // Unwrap and jump state (video time).
  bool have_prev_ = false;
  double prev_upper_ = 0, prev_bend_ = 0, prev_yaw_ = kNaN;
  double ref_t_ = 0;        // the jump allowance counts from here
  double prev_row_t_ = 0;   // the previous row, whatever its status
  double last_good_t_ = 0;  // the newest measured frame
  double held_yaw_ = kNaN;
  // Target state.
  bool has_target_ = false;
  JointArray target_{};
  int target_frame_ = -1;
  HoldReason newest_ = HoldReason::kNoData;
  double last_good_now_s_ = -1;  // stream clock of the newest measured frame
  // Command state.
  bool has_sent_ = false;
  JointArray last_sent_{};
  double last_sent_s_ = 0;
  StreamStats stats_;
};

}  // namespace armmimic::robot
