#include "armmimic/robot/stream_planner.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "angle_rows.h"

#include "armmimic/core/angles.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::robot {
namespace {

constexpr double kFps = 30;

AngleRow Row(int frame, double upper, double bend, double yaw = 0, bool lost = false) {
  return test::MakeRow(frame, kFps, upper, bend, yaw, lost);
}

StreamPlanner Begin(PlannerOptions o = {}) {
  StreamPlanner p;
  const Status s = p.Begin(o, SourceKind::kArm, kFps);
  EXPECT_TRUE(s.ok()) << s.message();
  return p;
}

// Frames arrive at the frame rate; the link is free at every frame; what goes out is sent.
std::vector<StreamCommand> Follow(StreamPlanner& p, int first, int n,
                                  const std::function<AngleRow(int)>& row) {
  std::vector<StreamCommand> out;
  for (int f = first; f < first + n; ++f) {
    const double now = f / kFps;
    p.Push(row(f), now);
    StreamCommand c;
    if (p.Next(now, &c)) {
      p.Sent(c);
      out.push_back(c);
    }
  }
  return out;
}

TEST(StreamPlanner, AStillArmIsCommandedOnceAtItsMappedPose) {
  StreamPlanner p = Begin();
  const auto cmds = Follow(p, 0, 60, [](int f) { return Row(f, 0, 90, 10); });
  ASSERT_EQ(cmds.size(), 1u);
  // upper 0: elevation 90 -> J2 -90; bend 90: flexion 90 -> J3 -90; yaw 10 -> J1 10.
  EXPECT_NEAR(cmds[0].joint_deg[0], 10, 1e-9);
  EXPECT_NEAR(cmds[0].joint_deg[1], -90, 1e-9);
  EXPECT_NEAR(cmds[0].joint_deg[2], -90, 1e-9);
  EXPECT_EQ(cmds[0].frame, 0);
  EXPECT_EQ(p.holding(2.0), HoldReason::kNone);
}

TEST(StreamPlanner, LostFramesHoldAndNothingIsExtrapolated) {
  StreamPlanner p = Begin();
  // The arm rises steadily, then the engine loses it for 20 frames, then finds it again.
  auto rise = [](int f) { return Row(f, -90 + 2.0 * f, 0, 0, f >= 30 && f < 50); };
  const auto cmds = Follow(p, 0, 70, rise);
  for (const StreamCommand& c : cmds) {
    EXPECT_FALSE(c.frame >= 30 && c.frame < 50) << "a command from lost frame " << c.frame;
    EXPECT_FALSE(c.time_s >= 30 / kFps && c.time_s < 50 / kFps)
        << "a command while the newest frame was lost, at " << c.time_s;
  }
  StreamPlanner q = Begin();
  Follow(q, 0, 31, rise);
  EXPECT_EQ(q.holding(31 / kFps), HoldReason::kLost);
  StreamCommand c;
  EXPECT_FALSE(q.Next(40 / kFps, &c));
}

TEST(StreamPlanner, NoFrameForLongerThanTheTimeoutHolds) {
  StreamPlanner p = Begin();
  Follow(p, 0, 10, [](int f) { return Row(f, -90 + 3.0 * f, 0); });
  EXPECT_EQ(p.holding(9 / kFps + 0.1), HoldReason::kNone);
  EXPECT_EQ(p.holding(9 / kFps + p.stale_after_s() + 0.01), HoldReason::kStale);
  StreamCommand c;
  EXPECT_FALSE(p.Next(9 / kFps + 1.0, &c));
}

TEST(StreamPlanner, AnImpossibleJumpIsTreatedAsLost) {
  StreamPlanner p = Begin();
  Follow(p, 0, 30, [](int f) { return Row(f, -90, 0); });
  const JointArray before = p.target();
  p.Push(Row(30, 90, 0), 30 / kFps);  // 180 degrees in one frame: a flipped measurement
  EXPECT_EQ(p.holding(30 / kFps), HoldReason::kJump);
  EXPECT_EQ(p.target(), before);
  EXPECT_EQ(p.stats().flagged_jumps, 1);
}

TEST(StreamPlanner, ATargetOutsideTheLimitsHoldsOrIsClamped) {
  PlannerOptions o;
  o.limits.min_deg[1] = -60;  // J2 may not go below -60 (elevation above 60)
  StreamPlanner p = Begin(o);
  const auto cmds = Follow(p, 0, 90, [](int f) { return Row(f, -90 + 1.5 * f, 0); });
  for (const StreamCommand& c : cmds) EXPECT_GE(c.joint_deg[1], -60) << "frame " << c.frame;
  EXPECT_GT(p.stats().limit_holds, 0);
  EXPECT_EQ(p.holding(90 / kFps), HoldReason::kLimits);

  o.clamp = true;
  StreamPlanner q = Begin(o);
  Follow(q, 0, 90, [](int f) { return Row(f, -90 + 1.5 * f, 0); });
  EXPECT_EQ(q.holding(90 / kFps), HoldReason::kNone);
  EXPECT_DOUBLE_EQ(q.target()[1], -60);
}

TEST(StreamPlanner, StepsNeverExceedTheSpeedLimitAndTheGateAgrees) {
  PlannerOptions o;
  o.max_jump_deg_s = 5000;  // let the wild input through to the speed limit
  StreamPlanner p = Begin(o);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> any(-180, 180);
  double upper = -90, bend = 0;
  SafetyState gate = SafetyState::For(o.limits, ControllerProfile());
  ASSERT_TRUE(CheckLine("SPEED 75", gate).ok());
  int checked = 0;
  for (int f = 0; f < 600; ++f) {
    if (f % 20 == 0) {  // the input jumps somewhere else every 20 frames
      upper = any(rng);
      bend = any(rng) * 0.8;
    }
    const double now = f / kFps;
    p.Push(Row(f, upper, bend, std::abs(any(rng)) / 4), now);
    StreamCommand c;
    if (!p.Next(now, &c)) continue;
    const Status s = CheckLine(FormatMoveLine(c.joint_deg, ControllerProfile()), c.time_s, gate);
    ASSERT_TRUE(s.ok()) << "frame " << f << ": " << s.message();
    p.Sent(c);
    ++checked;
  }
  EXPECT_GT(checked, 50);
  EXPECT_GT(p.stats().rate_limited, 0);
}

// A command that reached the port later than it was planned for (a loaded machine): the next
// step is limited from the write, so two writes are never closer than their step allows.
TEST(StreamPlanner, TheNextStepIsLimitedFromTheLastWriteNotItsPlan) {
  PlannerOptions o;
  o.max_jump_deg_s = 5000;
  o.cutoff_hz = 0;
  StreamPlanner p = Begin(o);
  p.Push(Row(0, -90, 0), 0);
  StreamCommand c;
  ASSERT_TRUE(p.Next(0, &c));
  p.Sent(c);
  p.Written(0.1);  // planned at 0, written 0.1 s later
  for (int f = 1; f <= 10; ++f) p.Push(Row(f, 0, 0), f / kFps);  // the arm swings up to level
  const double now = 0.35;
  ASSERT_TRUE(p.Next(now, &c));
  const double step = std::abs(c.joint_deg[1] - 0.0);
  EXPECT_GT(step, 0);
  EXPECT_LE(step, o.limits.max_speed_deg_s[1] * (now - 0.1) + 0.01);
  EXPECT_LT(step, o.limits.max_speed_deg_s[1] * now - 1);  // what the plan's time would allow
  p.Written(std::nan(""));  // a write time that cannot be read changes nothing
  p.Written(-1);            // nor an earlier one
  StreamCommand again;
  ASSERT_TRUE(p.Next(now, &again));
  EXPECT_EQ(again.joint_deg, c.joint_deg);
}

TEST(StreamPlanner, TheDeadbandAndMinIntervalThinTheCommands) {
  StreamPlanner p = Begin();
  // 1 degree a frame for 3 s: 30 deg/s, under every speed limit.
  const auto cmds = Follow(p, 0, 90, [](int f) { return Row(f, -90 + 1.0 * f, 0); });
  ASSERT_GT(cmds.size(), 5u);
  for (std::size_t i = 1; i < cmds.size(); ++i) {
    EXPECT_GE(cmds[i].time_s - cmds[i - 1].time_s, 0.2 - 1e-9);
    double moved = 0;
    for (int j = 0; j < kJoints; ++j) {
      moved = std::max(moved, std::abs(cmds[i].joint_deg[j] - cmds[i - 1].joint_deg[j]));
    }
    EXPECT_GT(moved, 2.0);
  }
  EXPECT_LE(cmds.size(), 16u);  // at most 5 a second
}

TEST(StreamPlanner, TheCausalFilterLagsByItsStatedDelay) {
  PlannerOptions o;
  o.deadband_deg = 0;
  o.min_interval_s = 0;
  StreamPlanner p = Begin(o);
  const double rate = 20;  // elevation rises 20 deg/s: J2 falls 20 deg/s
  Follow(p, 0, 90, [&](int f) { return Row(f, -90 + rate * f / kFps, 0); });
  const double unfiltered = -(rate * 89 / kFps);
  const double lag_s = (p.target()[1] - unfiltered) / rate;
  EXPECT_NEAR(lag_s, p.FilterDelayS(), 0.1 * p.FilterDelayS());
  EXPECT_NEAR(p.FilterDelayS(), 0.075, 0.001);
}

// Live marker rows: J1 follows the signed yaw, and a row whose sign the engine could not tell
// holds J1 instead of turning it by the unsigned yaw_deg.
TEST(StreamPlanner, AMarkerRowWhoseYawSignIsUnknownHoldsJ1) {
  PlannerOptions o;
  o.mapping = MappingOptions::Default(SourceKind::kMarker);
  StreamPlanner p;
  ASSERT_TRUE(p.Begin(o, SourceKind::kMarker, kFps).ok());
  auto row = [](int f) {
    AngleRow r = test::MakeRow(f, kFps, kNaN, 20, 5, false);
    r.file = "view.png";
    r.yaw_signed_deg = f < 30 ? -5 : kNaN;  // then: size known, sign not
    return r;
  };
  const auto cmds = Follow(p, 0, 90, row);
  ASSERT_FALSE(cmds.empty());
  for (const StreamCommand& c : cmds) EXPECT_NEAR(c.joint_deg[0], -5, 1e-9) << c.frame;
}

TEST(StreamPlanner, AnArmsThreeDColumnsTurnTheWaistByTheAzimuthOnly) {
  // The person's left arm (image right), live from the pose engine with BlazePose: 1 s hanging
  // with an azimuth that jumps about, 1 s raising it level in the image plane, then swung
  // forwards to 40 degrees.
  PlannerOptions o;
  o.mapping = MappingOptions::Default(SourceKind::kArm);
  o.mapping.image_side = 1;
  o.cutoff_hz = 0;
  StreamPlanner p;
  ASSERT_TRUE(p.Begin(o, SourceKind::kArm, kFps).ok());
  auto row = [](int f) {
    AngleRow r = test::MakeRow(f, kFps, -90, 0, kNaN, false);
    r.upper_el_deg = f < 30 ? -85 : std::min(0.0, -85 + (f - 30) * 85.0 / 30);
    r.upper_az_deg = f < 30 ? (f % 2 ? 120 : -60) : std::min(40.0, std::max(0, f - 60) * 1.0);
    r.elbow_deg = 170;
    return r;
  };
  const auto cmds = Follow(p, 0, 150, row);
  ASSERT_FALSE(cmds.empty());
  double last_j1 = 0;
  for (const StreamCommand& c : cmds) {
    if (c.frame < 30) {
      EXPECT_NEAR(c.joint_deg[0], 0, 1e-9) << c.frame;  // held: no azimuth yet
    }
    EXPECT_NEAR(c.joint_deg[2], -10, 1e-9) << c.frame;  // 180 - elbow_deg
    last_j1 = c.joint_deg[0];
  }
  EXPECT_NEAR(last_j1, 40, 1);
}

TEST(StreamPlanner, BeginRefusesACutoffAboveHalfTheFrameRate) {
  PlannerOptions o;
  o.cutoff_hz = 20;
  StreamPlanner p;
  const Status s = p.Begin(o, SourceKind::kArm, kFps);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cutoff"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace armmimic::robot
