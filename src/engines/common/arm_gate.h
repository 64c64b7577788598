// ArmGate: the arm engines' last word on a frame. An engine proposes a pose with a support score
// (how much of its own evidence backs it); the gate keeps it `ok` only when the evidence is
// strong enough and the pose is one an arm can reach from the last accepted pose in the time
// between them (still images, whose time stamps do not advance, have no speed to check).
// Otherwise the frame is `lost`, with the reason in the note. After a rejected
// jump the gate re-acquires the arm by itself once a few consecutive, mutually consistent
// candidates with good support agree, so a wrong lock is not taken on the first frame. For an
// engine that measures each frame on its own (no tracker carrying the arm through frames it does
// not report), so it does after a gap long enough for an arm to turn anywhere (half a turn at the
// fastest speed): there the speed check says nothing about the new pose.
#pragma once

#include <string>

#include "armmimic/engines/measurement.h"

namespace armmimic {

// Turns `m` into a lost row: phase kLost, the angles and centres cleared, `why` as its note.
void LoseRow(ArmMeasurement* m, const std::string& why);

struct ArmGateOptions {
  double max_speed_deg_s = 600;  // segment turn rate no arm motion exceeds (upper and bend)
  double min_support = 0.3;      // below: the evidence does not carry an estimate
  int confirm_frames = 3;        // agreeing candidates before the gate trusts a new lock
  bool start_confirmed = true;   // the first candidate is trusted (a calibrated start pose)
  // After frames without a pose, over a time in which the arm could have turned anywhere, the
  // next candidate needs confirm_frames agreeing ones (an engine without a tracker of its own).
  // Frames that come slowly, each with a pose, are no gap.
  bool confirm_after_gap = false;
};

class ArmGate {
 public:
  explicit ArmGate(const ArmGateOptions& options = {}) : o_(options) { Reset(); }
  void Reset();
  // A known pose at `time_s` (the protocol's standstill pose): later candidates must be reachable
  // from it, and the gate is confirmed.
  void Anchor(double upper_deg, double fore_deg, double time_s);

  // `m` is kOk when the engine has a candidate; `support` in [0, 1] (nan: not rated). Leaves it
  // kOk, or turns it kLost (angles cleared, the reason in m->note).
  void Review(ArmMeasurement* m, double support);

  bool confirmed() const { return confirmed_; }

  // Whether Review would keep the candidate `m` (its angles and time) on speed alone, changing
  // nothing: the gate is confirmed and the pose is reachable from the last accepted one (the
  // support is judged elsewhere: a pose the engine itself withholds, for a second measurement).
  bool Reachable(const ArmMeasurement& m) const;

 private:
  struct Pose {
    double upper_deg = 0, bend_deg = 0, time_s = 0;
  };
  // The largest turn an arm makes in `dt_s` seconds (at least one frame's worth).
  double Reach(double dt_s) const;
  bool Consistent(const Pose& from, const Pose& to) const;
  static Pose PoseOf(const ArmMeasurement& m);
  // With confirm_after_gap: frames without a pose since the last accepted one, over a time in
  // which an arm could have turned anywhere, so the speed check says nothing about `now`.
  bool GapVouchesForNothing(const Pose& now) const;
  static void Lose(ArmMeasurement* m, const std::string& why);

  ArmGateOptions o_;
  bool confirmed_ = false;  // the last accepted pose is trusted
  bool have_last_ = false;
  Pose last_;               // last accepted pose
  Pose run_last_;           // last candidate of the current agreeing run (while unconfirmed)
  int run_length_ = 0;      // agreeing candidates so far
  double frame_dt_ = 0;     // smallest time step seen between candidates
  bool missed_ = false;     // a frame without a pose since the last accepted one
  double after_gap_s_ = 0;  // unconfirmed by a gap this long (0: by a jump, or at the start)
};

}  // namespace armmimic
