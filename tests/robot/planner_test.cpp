// The planner from angle rows to keyframes: decimation, unwrapping, jumps, gaps, lost frames and
// the low-pass filter. Limits, speed, mapping and the safety check: planner_limits_test.cpp.
#include "armmimic/robot/planner.h"

#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "planner_scene.h"

namespace armmimic::robot {
namespace {

using planner_scene::ExpectKeyframesNearTruth;
using planner_scene::kFps;
using planner_scene::MakeFile;
using planner_scene::Options;
using planner_scene::Pose;

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

}  // namespace
}  // namespace armmimic::robot
