#include "armmimic/robot/planner.h"
#include "armmimic/robot/val_program.h"

#include <cmath>
#include <functional>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

namespace armmimic::robot {
namespace {

constexpr double kFps = 30;

struct Pose {
  double upper = -90, bend = 0, yaw = 0;
  bool lost = false;
};

AngleFile MakeFile(int n, const std::function<Pose(int, double)>& pose) {
  AngleFile f;
  f.meta = {{"engine", "bgsub"}, {"fps", "30"}};
  for (int i = 0; i < n; ++i) {
    const double t = i / kFps;
    const Pose p = pose(i, t);
    AngleRow r;
    r.frame = i + 100;
    r.time_s = t;
    r.status = p.lost ? RowStatus::kLost : RowStatus::kOk;
    if (!p.lost) {
      r.upper_deg = Wrap180(p.upper);
      r.bend_deg = Wrap180(p.bend);
      r.fore_deg = Wrap180(p.upper + p.bend);
      r.yaw_deg = p.yaw;
    }
    f.rows.push_back(r);
  }
  return f;
}

PlannerOptions Options() {
  PlannerOptions o;
  o.mapping = MappingOptions::Default(SourceKind::kArm);
  return o;
}

// The joints at the source frame of each keyframe must match the mapped truth within `tol`.
void ExpectKeyframesNearTruth(const Trajectory& tr, const MappingOptions& m,
                              const std::function<Pose(int, double)>& truth, double tol) {
  for (const Keyframe& kf : tr.keyframes) {
    const int i = kf.frame - 100;
    const Pose p = truth(i, i / kFps);
    const JointArray q = m.Map(p.upper, p.bend, p.yaw);
    for (int j = 0; j < kJoints; ++j) {
      EXPECT_NEAR(kf.joint_deg[j], q[j], tol) << "frame " << kf.frame << " J" << j + 1;
    }
  }
}

TEST(Planner, SlowSwingBecomesFewKeyframesCloseToTheTruth) {
  // 10 s raising and lowering the arm (0.1 Hz), elbow flexing 0..90, yaw 0..30.
  auto truth = [](int, double t) {
    Pose p;
    p.upper = -90 + 60 * (1 - std::cos(2 * kPi * 0.1 * t));  // peak 38 deg/s
    p.bend = 30 * (1 - std::cos(2 * kPi * 0.2 * t));         // peak 38 deg/s
    p.yaw = 15 * (1 - std::cos(2 * kPi * 0.1 * t));
    return p;
  };
  const AngleFile f = MakeFile(300, truth);
  Trajectory tr;
  PlanReport rep;
  ASSERT_TRUE(PlanTrajectory(f, Options(), &tr, &rep).ok());
  ExpectKeyframesNearTruth(tr, Options().mapping, truth, 0.5);
  // A 30 fps video must not become 30 moves a second.
  EXPECT_LE((tr.keyframes.size() - 1) / tr.duration_s(), 5.1);
  EXPECT_GE(tr.keyframes.size(), 10u);
  EXPECT_EQ(tr.keyframes.front().frame, 100);
  EXPECT_EQ(tr.keyframes.back().frame, 399);
  EXPECT_EQ(rep.stretch_s, 0);
  EXPECT_NEAR(tr.duration_s(), 299 / kFps, 1e-9);
}

TEST(Planner, DecimationHonoursDeadbandAndMaxInterval) {
  // Arm still for 3 s, then a slow move, then still.
  auto truth = [](int i, double) {
    Pose p;
    p.upper = i < 90 ? -90 : (i < 150 ? -90 + (i - 90) * 0.5 : -60);
    return p;
  };
  PlannerOptions o = Options();
  o.cutoff_hz = 0;
  o.deadband_deg = 2;
  o.max_interval_s = 1.0;
  Trajectory tr;
  ASSERT_TRUE(PlanTrajectory(MakeFile(240, truth), o, &tr, nullptr).ok());
  for (std::size_t k = 1; k < tr.keyframes.size(); ++k) {
    const Keyframe& a = tr.keyframes[k - 1];
    const Keyframe& b = tr.keyframes[k];
    double moved = 0;
    for (int j = 0; j < kJoints; ++j)
      moved = std::max(moved, std::abs(b.joint_deg[j] - a.joint_deg[j]));
    const double dt = b.time_s - a.time_s;
    const bool last = k + 1 == tr.keyframes.size();
    EXPECT_TRUE(moved > o.deadband_deg || dt >= o.max_interval_s - 1e-9 || last)
        << "keyframe " << k << " moved " << moved << " in " << dt;
    EXPECT_LE(dt, o.max_interval_s + 1e-9);
    if (!last) {
      EXPECT_GE(dt, o.min_interval_s - 1e-9);
    }
  }
  // Still for 3 s: about one keyframe a second, not 90.
  int still = 0;
  for (const Keyframe& kf : tr.keyframes) still += kf.frame < 190;
  EXPECT_LE(still, 4);
}

TEST(Planner, UnwrapsAcrossTheBranchCutWithASignedSource) {
  // The arm on the left side moving through horizontal: upper 150 -> 210 (-150 wrapped).
  auto truth = [](int i, double) {
    Pose p;
    p.upper = 150 + i * 0.5;
    return p;
  };
  PlannerOptions o = Options();
  o.mapping.j2_elevation = false;
  o.mapping.j2 = {1, -200};  // 150..210 -> -50..10
  Trajectory tr;
  PlanReport rep;
  const Status s = PlanTrajectory(MakeFile(121, truth), o, &tr, &rep);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(rep.flagged_jumps, 0);
  for (std::size_t k = 1; k < tr.keyframes.size(); ++k) {
    EXPECT_GT(tr.keyframes[k].joint_deg[1], tr.keyframes[k - 1].joint_deg[1]);
  }
  EXPECT_NEAR(tr.keyframes.back().joint_deg[1], 10, 0.5);
}

TEST(Planner, FlagsAnImpossibleJumpAndFillsIt) {
  // One frame where the upper arm's direction was resolved the wrong way round (180 off).
  auto truth = [](int, double t) {
    Pose p;
    p.upper = -60 + 10 * t;
    return p;
  };
  auto measured = [&](int i, double t) {
    Pose p = truth(i, t);
    if (i == 40) p.upper += 180;
    return p;
  };
  Trajectory tr;
  PlanReport rep;
  ASSERT_TRUE(PlanTrajectory(MakeFile(90, measured), Options(), &tr, &rep).ok());
  EXPECT_EQ(rep.flagged_jumps, 1);
  EXPECT_EQ(rep.filled_rows, 1);
  ASSERT_FALSE(rep.warnings.empty());
  ExpectKeyframesNearTruth(tr, Options().mapping, truth, 0.5);
}

TEST(Planner, RefusesWhenTheJumpPersists) {
  auto measured = [](int i, double) {
    Pose p;
    p.upper = i < 30 ? -60 : 120;
    return p;
  };
  Trajectory tr;
  const Status s = PlanTrajectory(MakeFile(90, measured), Options(), &tr, nullptr);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("impossible jump"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("frames 130-189"), std::string::npos) << s.message();
}

TEST(Planner, InterpolatesOrHoldsShortGapsAndRefusesLongOnes) {
  auto truth = [](int, double t) {
    Pose p;
    p.upper = -90 + 20 * t;
    return p;
  };
  auto lossy = [&](int i, double t) {
    Pose p = truth(i, t);
    p.lost = (i >= 30 && i < 36);  // 0.2 s
    return p;
  };
  PlannerOptions o = Options();
  o.cutoff_hz = 0;
  o.deadband_deg = 0;
  o.min_interval_s = 0;
  Trajectory tr;
  PlanReport rep;
  ASSERT_TRUE(PlanTrajectory(MakeFile(60, lossy), o, &tr, &rep).ok());
  EXPECT_EQ(rep.filled_rows, 6);
  ExpectKeyframesNearTruth(tr, o.mapping, truth, 1e-6);  // linear truth: exact

  o.gap = GapMode::kHold;
  ASSERT_TRUE(PlanTrajectory(MakeFile(60, lossy), o, &tr, &rep).ok());
  for (const Keyframe& kf : tr.keyframes) {
    if (kf.frame >= 130 && kf.frame < 136) {
      EXPECT_NEAR(kf.joint_deg[1], MappingOptions().Map(truth(29, 29 / kFps).upper, 0, 0)[1], 1e-6);
    }
  }

  auto long_gap = [&](int i, double t) {
    Pose p = truth(i, t);
    p.lost = (i >= 10 && i < 40) || (i >= 45 && i < 47);  // 1.0 s, then a short one
    return p;
  };
  o.gap = GapMode::kInterpolate;
  const Status s = PlanTrajectory(MakeFile(60, long_gap), o, &tr, &rep);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("frames 110-139"), std::string::npos) << s.message();
  EXPECT_EQ(s.message().find("145"), std::string::npos) << s.message();
}

TEST(Planner, DropsLostFramesAtTheStartAndEnd) {
  auto f = [](int i, double) {
    Pose p;
    p.lost = i < 10 || i >= 50;
    return p;
  };
  Trajectory tr;
  PlanReport rep;
  ASSERT_TRUE(PlanTrajectory(MakeFile(60, f), Options(), &tr, &rep).ok());
  EXPECT_EQ(tr.keyframes.front().frame, 110);
  EXPECT_EQ(tr.keyframes.back().frame, 149);
  EXPECT_EQ(rep.used_rows, 40);
  EXPECT_EQ(tr.keyframes.front().time_s, 0);
}

TEST(Planner, RefusesAnAllLostFile) {
  auto f = [](int, double) {
    Pose p;
    p.lost = true;
    return p;
  };
  Trajectory tr;
  const Status s = PlanTrajectory(MakeFile(20, f), Options(), &tr, nullptr);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("lost"), std::string::npos);
}

TEST(Planner, LowPassBringsNoisyMeasurementsCloserToTheTruth) {
  auto truth = [](int, double t) {
    Pose p;
    p.upper = -90 + 40 * (1 - std::cos(2 * kPi * 0.2 * t));
    p.bend = 30;
    return p;
  };
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0, 2.0);
  std::vector<double> n1(300), n2(300);
  for (int i = 0; i < 300; ++i) {
    n1[i] = noise(rng);
    n2[i] = noise(rng);
  }
  auto noisy = [&](int i, double t) {
    Pose p = truth(i, t);
    p.upper += n1[i];
    p.bend += n2[i];
    return p;
  };
  auto rms = [&](double cutoff) {
    PlannerOptions o = Options();
    o.cutoff_hz = cutoff;
    o.deadband_deg = 0;
    o.min_interval_s = 0;
    Trajectory tr;
    EXPECT_TRUE(PlanTrajectory(MakeFile(300, noisy), o, &tr, nullptr).ok());
    double sum = 0;
    for (const Keyframe& kf : tr.keyframes) {
      const int i = kf.frame - 100;
      const Pose p = truth(i, i / kFps);
      const JointArray q = o.mapping.Map(p.upper, p.bend, p.yaw);
      sum += std::pow(kf.joint_deg[1] - q[1], 2) + std::pow(kf.joint_deg[2] - q[2], 2);
    }
    return std::sqrt(sum / (2.0 * tr.keyframes.size()));
  };
  const double raw = rms(0);
  const double filtered = rms(2);
  EXPECT_GT(raw, 1.5);
  EXPECT_LT(filtered, 0.5 * raw);
}

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
