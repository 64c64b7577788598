// The planner against the robot's limits and kinds of file: targets outside the limits, speed
// stretching, yaw and marker mapping, still images, the mapping defaults, the safety check of
// every planned program and the options' check.
#include "armmimic/robot/planner.h"
#include "armmimic/robot/val_program.h"

#include <cmath>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "planner_scene.h"

namespace armmimic::robot {
namespace {

using planner_scene::MakeFile;
using planner_scene::Options;
using planner_scene::Pose;

TEST(Planner, RefusesTargetsOutsideTheLimitsListingFramesOrClamps) {
  auto truth = [](int i, double) {
    Pose p;
    p.upper = -90 + i;  // elevation 0..59
    return p;
  };
  PlannerOptions o = Options();
  o.cutoff_hz = 0;
  o.mapping.j2 = {1, -20};  // J2 = elevation - 20: over 20 from elevation 40 on
  Trajectory tr;
  PlanReport rep;
  const Status s = PlanTrajectory(MakeFile(60, truth), o, &tr, &rep);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("J2 [-200.00,20.00] exceeded in 19 frames: 141 (21.00)"),
            std::string::npos)
      << s.message();
  EXPECT_NE(s.message().find("and 14 more"), std::string::npos) << s.message();

  o.clamp = true;
  ASSERT_TRUE(PlanTrajectory(MakeFile(60, truth), o, &tr, &rep).ok());
  EXPECT_EQ(rep.clamped_rows, 19);
  EXPECT_DOUBLE_EQ(rep.max_deg[1], 20);
  for (const Keyframe& kf : tr.keyframes) EXPECT_LE(kf.joint_deg[1], 20);
}

TEST(Planner, StretchesTimeSoNoStepIsFasterThanTheSpeedLimit) {
  // A fast raise: 180 deg of elevation in 1 s, four times J2's 45 deg/s limit.
  auto truth = [](int i, double) {
    Pose p;
    p.upper = -90 + std::min(180.0, i * 6.0);
    return p;
  };
  PlannerOptions o = Options();
  o.cutoff_hz = 0;
  Trajectory tr;
  PlanReport rep;
  ASSERT_TRUE(PlanTrajectory(MakeFile(45, truth), o, &tr, &rep).ok());
  EXPECT_GT(rep.stretch_s, 2.5);
  EXPECT_GT(rep.stretched_steps, 0);
  for (std::size_t k = 1; k < tr.keyframes.size(); ++k) {
    const double dt = tr.keyframes[k].time_s - tr.keyframes[k - 1].time_s;
    for (int j = 0; j < kJoints; ++j) {
      const double d = std::abs(tr.keyframes[k].joint_deg[j] - tr.keyframes[k - 1].joint_deg[j]);
      EXPECT_LE(d, o.limits.max_speed_deg_s[j] * dt + 1e-9) << "step " << k;
    }
  }
  EXPECT_GE(tr.duration_s(), 180.0 / 45.0 - 1e-9);

  o.speed = SpeedPolicy::kRefuse;
  const Status s = PlanTrajectory(MakeFile(45, truth), o, &tr, &rep);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("J2 would move"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("speed limit of 45.0 deg/s"), std::string::npos) << s.message();
}

TEST(Planner, HoldsYawWhileTheArmIsBentAndMapsMarkerFiles) {
  auto truth = [](int i, double) {
    Pose p;
    p.yaw = i < 20 ? 30 : kNaN;
    p.bend = i < 20 ? 0 : std::min(60.0, (i - 20) * 3.0);
    return p;
  };
  PlannerOptions o = Options();
  o.cutoff_hz = 0;
  Trajectory tr;
  ASSERT_TRUE(PlanTrajectory(MakeFile(40, truth), o, &tr, nullptr).ok());
  for (const Keyframe& kf : tr.keyframes) EXPECT_NEAR(kf.joint_deg[0], 30, 1e-9);

  AngleFile marker = MakeFile(40, [](int i, double) {
    Pose p;
    p.upper = kNaN;
    p.bend = i;
    p.yaw = 10;
    return p;
  });
  for (auto& r : marker.rows) r.upper_deg = kNaN;
  marker.has_file_column = true;
  o.mapping = MappingOptions::Default(DetectSourceKind(marker));
  ASSERT_TRUE(PlanTrajectory(marker, o, &tr, nullptr).ok());
  EXPECT_NEAR(tr.keyframes.back().joint_deg[1], -90 - 39, 1e-9);
  EXPECT_NEAR(tr.keyframes.back().joint_deg[2], 0, 1e-9);
  EXPECT_NEAR(tr.keyframes.back().joint_deg[0], 10, 1e-9);
  // A marker file's signed yaw turns J1 the way the joint turned (yaw_deg is its magnitude).
  for (auto& r : marker.rows) r.yaw_signed_deg = -10;
  marker.has_signed_yaw_column = true;
  ASSERT_TRUE(PlanTrajectory(marker, o, &tr, nullptr).ok());
  EXPECT_NEAR(tr.keyframes.back().joint_deg[0], -10, 1e-9);
}

// A marker row whose yaw sign the engine could not tell (yaw_signed_deg nan, yaw_deg known)
// never turns J1 by the unsigned yaw: J1 holds where the last signed row left it.
TEST(Planner, HoldsJ1OnMarkerRowsWhoseYawSignIsUnknown) {
  AngleFile marker = MakeFile(40, [](int i, double) {
    Pose p;
    p.upper = kNaN;
    p.bend = 10;
    p.yaw = 5;
    return p;
  });
  marker.has_file_column = true;
  marker.has_signed_yaw_column = true;
  for (AngleRow& r : marker.rows) {
    r.yaw_signed_deg = r.frame < 120 ? -5 : kNaN;  // rows 20.. : size known, sign not
  }
  PlannerOptions o = Options();
  o.cutoff_hz = 0;
  o.mapping = MappingOptions::Default(DetectSourceKind(marker));
  Trajectory tr;
  PlanReport report;
  ASSERT_TRUE(PlanTrajectory(marker, o, &tr, &report).ok());
  ASSERT_FALSE(tr.keyframes.empty());
  for (const Keyframe& kf : tr.keyframes) EXPECT_NEAR(kf.joint_deg[0], -5, 1e-9);
  bool said = false;
  for (const auto& w : report.warnings) {
    said =
        said || w.text.find("20 rows with a yaw whose sign could not be told") != std::string::npos;
  }
  EXPECT_TRUE(said);
  // Without the signed column the same rows turn J1 by yaw_deg, as for any file.
  marker.has_signed_yaw_column = false;
  for (AngleRow& r : marker.rows) r.yaw_signed_deg = kNaN;
  ASSERT_TRUE(PlanTrajectory(marker, o, &tr, nullptr).ok());
  EXPECT_NEAR(tr.keyframes.back().joint_deg[0], 5, 1e-9);
}

// Marker views are still images: no frame rate, every time_s 0. With the default options they
// are planned unfiltered (the default cutoff cannot be below half of the 1 fps they are spaced
// at), and an unreadable view holds the last readable pose instead of refusing a "1 s gap".
TEST(Planner, StillImagesArePlannedUnfilteredAndHoldOverUnreadableViews) {
  AngleFile views;
  views.meta = {{"engine", "marker"}};
  views.has_file_column = true;
  const double bends[] = {0, 20, kNaN, kNaN, 40, 10, kNaN, 30};
  for (int i = 0; i < 8; ++i) {
    AngleRow r;
    r.frame = i;
    r.time_s = 0;
    r.file = "view" + std::to_string(i) + ".png";
    if (std::isnan(bends[i])) {
      r.status = RowStatus::kLost;
    } else {
      r.status = RowStatus::kOk;
      r.bend_deg = bends[i];
      r.yaw_deg = 5;
    }
    views.rows.push_back(r);
  }
  PlannerOptions o;  // all defaults, as `armmimic-cli plan VIEWS.tsv -o P.val`
  ASSERT_GT(o.cutoff_hz, 0.5 * o.fallback_fps);
  Trajectory tr;
  PlanReport report;
  const Status st = PlanTrajectory(views, o, &tr, &report);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(report.filter_cutoff_hz, 0);
  EXPECT_EQ(report.filled_rows, 3);
  bool said_unfiltered = false;
  for (const PlanIssue& w : report.warnings) {
    said_unfiltered = said_unfiltered || w.text.find("without the low-pass") != std::string::npos;
  }
  EXPECT_TRUE(said_unfiltered);
  // Each readable view's pose is reached exactly (no filter); the held views add no new pose.
  const MappingOptions m = MappingOptions::Default(SourceKind::kMarker);
  for (const Keyframe& kf : tr.keyframes) {
    const double b = std::isnan(bends[kf.frame]) ? kNaN : bends[kf.frame];
    if (std::isnan(b)) continue;
    EXPECT_NEAR(kf.joint_deg[1], m.Map(kNaN, b, 5)[1], 1e-9) << "view " << kf.frame;
  }
  const std::vector<std::string> header = DescribePlan("views.tsv", views, o, report, tr);
  ASSERT_GE(header.size(), 3u);
  EXPECT_NE(header[2].find("cutoff_hz=0.000"), std::string::npos) << header[2];
}

TEST(Planner, DefaultOptionsFollowTheFilesKindButACustomMappingMustMatch) {
  AngleFile marker = MakeFile(30, [](int i, double) {
    Pose p;
    p.bend = i;
    p.yaw = 5;
    return p;
  });
  for (auto& r : marker.rows) r.upper_deg = kNaN;
  marker.meta = {{"engine", "marker"}};
  PlannerOptions o;  // arm defaults, as send uses them
  o.cutoff_hz = 0;
  Trajectory tr;
  PlanReport rep;
  ASSERT_TRUE(PlanTrajectory(marker, o, &tr, &rep).ok());
  EXPECT_EQ(rep.mapping.rfind("marker j1=+yaw+0.00 j2=-bend-90.00", 0), 0u) << rep.mapping;
  EXPECT_NEAR(tr.keyframes.back().joint_deg[1], -90 - 29, 1e-9);
  o.mapping.j2 = {1, -100};
  const Status s = PlanTrajectory(marker, o, &tr, &rep);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("comes from the marker engine"), std::string::npos) << s.message();
  // A kind chosen by the user (a file whose header cannot tell) is used as given.
  AngleFile bare = marker;
  bare.meta.clear();
  o.mapping = MappingOptions::Default(SourceKind::kMarker);
  o.mapping.follow_file_kind = false;
  ASSERT_TRUE(PlanTrajectory(bare, o, &tr, &rep).ok());
  EXPECT_EQ(rep.mapping.rfind("marker", 0), 0u) << rep.mapping;
}

TEST(Planner, EveryPlannedProgramPassesSendsSafetyCheck) {
  // Fast, noisy, lossy motion on the left side: the planned text must pass the same check send
  // runs before each line, in both modes and with clamping.
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 1.5);
  std::vector<double> n(400);
  for (double& v : n) v = noise(rng);
  auto f = [&](int i, double t) {
    Pose p;
    p.upper = -90 - 170 * std::abs(std::sin(2 * kPi * 0.3 * t)) + n[i];
    p.bend = -140 * std::abs(std::sin(2 * kPi * 0.45 * t)) + n[(i + 7) % 400];
    p.yaw = std::abs(40 * std::sin(2 * kPi * 0.2 * t));
    p.lost = i % 37 == 5;
    return p;
  };
  for (SendMode mode : {SendMode::kStream, SendMode::kProgram}) {
    PlannerOptions o = Options();
    o.limits.max_speed_deg_s = {20, 30, 40, 90, 90, 90};
    o.limits.min_deg[2] = -120;  // tighter than the elbow's range: clamped
    o.clamp = true;
    Trajectory tr;
    PlanReport rep;
    ASSERT_TRUE(PlanTrajectory(MakeFile(400, f), o, &tr, &rep).ok());
    EXPECT_GT(rep.stretch_s, 0);
    EXPECT_GT(rep.clamped_rows, 0);
    ControllerProfile profile;
    profile.mode = mode;
    std::string text;
    ASSERT_TRUE(FormatValProgram(tr, profile, o.limits, {"source=x.tsv"}, &text).ok());
    std::istringstream in(text);
    ValProgram program;
    ASSERT_TRUE(ParseValProgram(in, "x.val", 80, &program).ok());
    SafetyState state = SafetyState::For(o.limits, profile);
    const Status s = CheckProgram(program, state);
    EXPECT_TRUE(s.ok()) << s.message();
  }
}

TEST(Planner, OptionsCheckNamesTheBadOption) {
  PlannerOptions o;
  o.max_interval_s = 0.1;
  EXPECT_NE(o.Check().message().find("max interval"), std::string::npos);
  o = PlannerOptions();
  o.cutoff_hz = -1;
  EXPECT_NE(o.Check().message().find("cutoff"), std::string::npos);
  o = PlannerOptions();
  o.cutoff_hz = 20;  // above 15 Hz Nyquist at 30 fps
  Trajectory tr;
  const Status s =
      PlanTrajectory(MakeFile(10, [](int, double) { return Pose(); }), o, &tr, nullptr);
  EXPECT_NE(s.message().find("half the frame rate"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace armmimic::robot
