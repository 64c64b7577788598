// The arm engines' honest-status gate: weak evidence and impossible jumps are `lost`, and the
// arm is re-acquired once agreeing frames return.
#include "common/arm_gate.h"

#include <cmath>

#include <gtest/gtest.h>

namespace armmimic {
namespace {

constexpr double kFps = 30;

ArmMeasurement Candidate(int frame, double upper_deg, double fore_deg) {
  ArmMeasurement m;
  m.frame = frame;
  m.time_s = frame / kFps;
  m.phase = MeasurementPhase::kOk;
  m.upper_deg = upper_deg;
  m.fore_deg = fore_deg;
  return m;
}

bool Ok(ArmGate* gate, int frame, double upper_deg, double fore_deg, double support = 1) {
  ArmMeasurement m = Candidate(frame, upper_deg, fore_deg);
  gate->Review(&m, support);
  if (m.phase == MeasurementPhase::kLost) {
    EXPECT_TRUE(std::isnan(m.upper_deg)) << "a lost frame keeps no angle";
    EXPECT_FALSE(m.note.empty()) << "a lost frame says why";
  }
  return m.phase == MeasurementPhase::kOk;
}

// A frame without a pose (the engine found none, or refused it) at `frame`'s time.
void Lost(ArmGate* gate, int frame) {
  ArmMeasurement m = Candidate(frame, std::nan(""), std::nan(""));
  m.phase = MeasurementPhase::kLost;
  gate->Review(&m, std::nan(""));
}

TEST(ArmGate, SmoothMotionUpToTheSpeedLimitStaysOk) {
  ArmGate gate;  // 600 deg/s: 20 degrees a frame at 30 fps
  double upper = -90;
  for (int f = 0; f < 12; ++f, upper += 15) {
    EXPECT_TRUE(Ok(&gate, f, upper, upper + 0.5 * f)) << "frame " << f;
  }
}

TEST(ArmGate, AFlipFasterThanAnArmTurnsIsLost) {
  ArmGate gate;
  for (int f = 0; f < 5; ++f) ASSERT_TRUE(Ok(&gate, f, -90 + 2 * f, -90 + 2 * f));
  EXPECT_FALSE(Ok(&gate, 5, 60, 60)) << "150 degrees in one frame";
  // The forearm folding 120 degrees in a frame is as impossible as the upper arm flipping.
  ArmGate bend_gate;
  ASSERT_TRUE(Ok(&bend_gate, 0, -90, -90));
  EXPECT_FALSE(Ok(&bend_gate, 1, -90, 30));
}

TEST(ArmGate, ReacquiresAfterAgreeingFramesNotOnTheFirst) {
  ArmGateOptions o;
  o.confirm_frames = 3;
  ArmGate gate(o);
  ASSERT_TRUE(Ok(&gate, 0, -90, -90));
  EXPECT_FALSE(Ok(&gate, 1, 45, 45));  // the jump
  EXPECT_FALSE(Ok(&gate, 2, 47, 47));  // 2 of 3 agreeing
  EXPECT_TRUE(Ok(&gate, 3, 49, 49));   // 3 of 3: trusted again
  EXPECT_TRUE(Ok(&gate, 4, 51, 51));
}

TEST(ArmGate, DisagreeingCandidatesAreNeverTrusted) {
  ArmGate gate;
  ASSERT_TRUE(Ok(&gate, 0, -90, -90));
  // A candidate that flips back and forth between two readings never forms an agreeing run.
  for (int f = 1; f < 20; ++f) {
    EXPECT_FALSE(Ok(&gate, f, f % 2 ? 80 : -40, f % 2 ? 80 : -40)) << "frame " << f;
  }
}

TEST(ArmGate, WeakEvidenceIsLostAndStrongEvidenceReturns) {
  ArmGate gate;
  ASSERT_TRUE(Ok(&gate, 0, -90, -90));
  EXPECT_FALSE(Ok(&gate, 1, -88, -88, 0.1));
  EXPECT_TRUE(Ok(&gate, 2, -86, -86, 0.9));
  EXPECT_TRUE(Ok(&gate, 3, -84, -84, std::nan("")));  // not rated: the speed rule still applies
}

// Reachable answers for a pose the engine withholds (the gate's state unchanged): reachable
// from the last accepted pose at the speed limit, never while the gate is unconfirmed.
TEST(ArmGate, ReachableJudgesSpeedAloneAndChangesNothing) {
  ArmGateOptions o;
  o.confirm_frames = 3;
  ArmGate gate(o);
  ASSERT_TRUE(Ok(&gate, 0, -90, -90));
  EXPECT_TRUE(gate.Reachable(Candidate(1, -75, -75)));   // 15 degrees in a frame
  EXPECT_FALSE(gate.Reachable(Candidate(1, -60, -90)));  // 30: too fast
  EXPECT_FALSE(gate.Reachable(Candidate(1, std::nan(""), -90)));
  // Asking did not move the last accepted pose: -75 is still reachable, and a pose reachable
  // only from -75 (-57) is not.
  EXPECT_TRUE(gate.Reachable(Candidate(1, -75, -75)));
  EXPECT_FALSE(gate.Reachable(Candidate(1, -57, -57)));
  EXPECT_FALSE(Ok(&gate, 1, 45, 45));  // a jump: unconfirmed
  EXPECT_FALSE(gate.Reachable(Candidate(2, 46, 46)));
}

TEST(ArmGate, ALongGapAllowsAProportionallyLargerMove) {
  ArmGate gate;
  ASSERT_TRUE(Ok(&gate, 0, -90, -90));
  ArmMeasurement lost;
  lost.phase = MeasurementPhase::kLost;
  for (int f = 1; f < 6; ++f) gate.Review(&lost, std::nan(""));
  // 6 frames at 30 fps: up to 120 degrees of turn are reachable.
  EXPECT_TRUE(Ok(&gate, 6, 20, 20));
}

TEST(ArmGate, AfterAGapLongEnoughToTurnAnywhereAPoseNeedsAgreeingFrames) {
  ArmGateOptions o;
  o.confirm_frames = 3;
  o.confirm_after_gap = true;
  ArmGate gate(o);
  ASSERT_TRUE(Ok(&gate, 0, -90, -90));
  ASSERT_TRUE(Ok(&gate, 1, -89, -89));
  for (int f = 2; f < 12; ++f) Lost(&gate, f);
  // 11 frames at 30 fps since the last pose: 220 degrees at 600 deg/s, any pose. Even one next to
  // the last accepted pose is not vouched for by it.
  ArmMeasurement first = Candidate(12, -88, -88);
  gate.Review(&first, 1);
  EXPECT_EQ(first.phase, MeasurementPhase::kLost);
  EXPECT_EQ(first.note, "re-acquiring after 0.37 s without a pose (1/3 agreeing frames)");
  EXPECT_FALSE(Ok(&gate, 13, -87, -87));
  EXPECT_TRUE(Ok(&gate, 14, -86, -86));
  // A wrong reading that does not hold for the agreeing frames is never trusted.
  ArmGate other(o);
  ASSERT_TRUE(Ok(&other, 0, -90, -90));
  for (int f = 1; f < 12; ++f) Lost(&other, f);
  EXPECT_FALSE(Ok(&other, 12, 180, -88));
  Lost(&other, 13);
  EXPECT_FALSE(Ok(&other, 14, -60, -60));
  // Frames that come slowly (a live source falling behind) but each with a pose are no gap: the
  // speed check vouches for every one.
  ArmGate slow(o);
  for (int f = 0; f < 5; ++f) {
    ArmMeasurement m = Candidate(f, -90 + 5 * f, -90 + 5 * f);
    m.time_s = 0.4 * f;
    slow.Review(&m, 1);
    EXPECT_EQ(m.phase, MeasurementPhase::kOk) << "frame " << f << ": " << m.note;
  }
  // A tracker's gate (the tracker carries the arm through the gap) takes the pose as before.
  o.confirm_after_gap = false;
  ArmGate tracker(o);
  ASSERT_TRUE(Ok(&tracker, 0, -90, -90));
  for (int f = 1; f < 12; ++f) Lost(&tracker, f);
  EXPECT_TRUE(Ok(&tracker, 12, -88, -88));
}

TEST(ArmGate, AnUncalibratedStartNeedsAgreeingFrames) {
  ArmGateOptions o;
  o.start_confirmed = false;
  o.confirm_frames = 2;
  ArmGate gate(o);
  EXPECT_FALSE(Ok(&gate, 0, -90, -90));
  EXPECT_TRUE(Ok(&gate, 1, -89, -89));
}

TEST(ArmGate, StillImagesWithoutTimeHaveNoSpeedToCheck) {
  ArmGate gate;
  ArmMeasurement a = Candidate(0, -90, -90), b = Candidate(1, 60, 60);
  a.time_s = b.time_s = 0;
  gate.Review(&a, 1);
  gate.Review(&b, 1);
  EXPECT_EQ(b.phase, MeasurementPhase::kOk) << b.note;
}

}  // namespace
}  // namespace armmimic
