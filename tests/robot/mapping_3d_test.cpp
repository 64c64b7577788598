// The robot from the 3-D columns (docs/robot.md, "Mapping the 3-D columns"): the sources a 3-D row
// stands for, the planner turning the waist only as the upper arm's azimuth changes (and holding it
// while the arm hangs, where the azimuth is noise), and the refusals.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "armmimic/core/angles.h"
#include "armmimic/robot/mapping.h"
#include "armmimic/robot/planner.h"
#include "planner_scene.h"

namespace armmimic::robot {
namespace {

// An ok row whose upper arm points at azimuth `az` and elevation `el` with the elbow's 3-D angle
// `elbow`; its 2-D columns show what the camera sees of it (the elevation when in the image
// plane) and its thesis yaw column is empty.
AngleRow Row3d(int frame, double az, double el, double elbow) {
  AngleRow r;
  r.frame = frame;
  r.time_s = frame / planner_scene::kFps;
  r.status = RowStatus::kOk;
  r.upper_deg = el;
  r.bend_deg = 180 - elbow;
  r.fore_deg = Wrap180(r.upper_deg + r.bend_deg);
  r.upper_az_deg = az;
  r.upper_el_deg = el;
  r.fore_az_deg = az;
  r.fore_el_deg = el;
  r.elbow_deg = elbow;
  return r;
}

TEST(Mapping3d, SourcesAreTheElevationTheFlexionAndTheAzimuthFromTheImagePlane) {
  double u = 0, b = 0, y = 0;
  // The arm on the image's right (the person's left), level, straight and in the image plane.
  ASSERT_TRUE(SourcesFrom3d(Row3d(0, 0, 0, 180), 1, &u, &b, &y));
  EXPECT_DOUBLE_EQ(u, 0);
  EXPECT_DOUBLE_EQ(b, 0);
  EXPECT_DOUBLE_EQ(y, 0);
  // Reaching at the camera: no 2-D direction, but a yaw of 90.
  ASSERT_TRUE(SourcesFrom3d(Row3d(0, 90, 0, 180), 1, &u, &b, &y));
  EXPECT_DOUBLE_EQ(y, 90);
  // The same on the image's left, where the plane is azimuth 180.
  ASSERT_TRUE(SourcesFrom3d(Row3d(0, 180, 0, 180), -1, &u, &b, &y));
  EXPECT_DOUBLE_EQ(y, 0);
  ASSERT_TRUE(SourcesFrom3d(Row3d(0, 90, 10, 90), -1, &u, &b, &y));
  EXPECT_DOUBLE_EQ(y, 90);
  EXPECT_DOUBLE_EQ(u, 10);
  EXPECT_DOUBLE_EQ(b, 90);
  // Hanging: the azimuth is noise, J1 is held (nan); J2 and J3 still follow.
  ASSERT_TRUE(SourcesFrom3d(Row3d(0, 37, -80, 150), 1, &u, &b, &y));
  EXPECT_TRUE(std::isnan(y));
  EXPECT_DOUBLE_EQ(u, -80);
  EXPECT_DOUBLE_EQ(b, 30);
  // Without a side, or without the columns, there is nothing to turn by.
  EXPECT_FALSE(SourcesFrom3d(Row3d(0, 0, 0, 180), 0, &u, &b, &y));
  AngleRow flat = Row3d(0, 0, 0, 180);
  flat.elbow_deg = kNaN;
  EXPECT_FALSE(SourcesFrom3d(flat, 1, &u, &b, &y));
  // The default mapping then gives J1 the yaw, J2 the folded elevation, J3 the flexion.
  const JointArray q = MappingOptions::Default(SourceKind::kArm).Map(10, 90, 90);
  EXPECT_DOUBLE_EQ(q[0], 90);
  EXPECT_DOUBLE_EQ(q[1], -100);
  EXPECT_DOUBLE_EQ(q[2], -90);
}

AngleFile File3d(const char* side) {
  AngleFile f;
  f.meta = {{"engine", "pose"}, {"fps", "30"}};
  if (side) f.meta.emplace_back("pose.side", side);
  f.has_3d_columns = true;
  return f;
}

TEST(Mapping3d, TheWaistTurnsOnlyAsTheAzimuthChanges) {
  // The person's left arm (image right): 2 s hanging with an azimuth that jumps about (noise on
  // a vertical arm), 1 s raising it level in the image plane, then 4 s swinging it forwards to
  // 60 degrees and back at a constant elevation.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> noise(-180, 180);
  AngleFile f = File3d("left");
  for (int i = 0; i < 210; ++i) {
    const double t = i / planner_scene::kFps;
    double az = 0, el = -88;
    if (t < 2) {
      az = noise(rng);
    } else if (t < 3) {
      el = -88 + 88 * (t - 2);
    } else {
      el = 0;
      az = 30 * (1 - std::cos(2 * kPi * (t - 3) / 4));
    }
    f.rows.push_back(Row3d(100 + i, az, el, 170));
  }
  PlannerOptions o = planner_scene::Options();
  Trajectory tr;
  PlanReport rep;
  ASSERT_TRUE(PlanTrajectory(f, o, &tr, &rep).ok());
  EXPECT_NE(rep.mapping.find("from the 3-D columns"), std::string::npos) << rep.mapping;
  double j1_hanging_lo = 1e9, j1_hanging_hi = -1e9, j1_max = -1e9;
  for (const Keyframe& kf : tr.keyframes) {
    const double t = (kf.frame - 100) / planner_scene::kFps;
    if (t < 1.5) {
      j1_hanging_lo = std::min(j1_hanging_lo, kf.joint_deg[0]);
      j1_hanging_hi = std::max(j1_hanging_hi, kf.joint_deg[0]);
      EXPECT_NEAR(kf.joint_deg[1], -2, 1) << "frame " << kf.frame;  // J2: hanging
    }
    j1_max = std::max(j1_max, kf.joint_deg[0]);
    EXPECT_NEAR(kf.joint_deg[2], -10, 1) << "frame " << kf.frame;  // J3: 180 - 170
  }
  // While the arm hangs, J1 does not follow the azimuth's noise.
  EXPECT_LT(j1_hanging_hi - j1_hanging_lo, 1.0);
  // Swung forwards, it turns with the azimuth (the low-pass takes a little off the peak).
  EXPECT_NEAR(j1_max, 60, 4);
  // From the 2-D columns instead, the same file turns no waist (its thesis yaw is empty).
  o.mapping.arm_3d = false;
  ASSERT_TRUE(PlanTrajectory(f, o, &tr, &rep).ok());
  for (const Keyframe& kf : tr.keyframes) EXPECT_DOUBLE_EQ(kf.joint_deg[0], 0);
}

TEST(Mapping3d, ThePlanNamesWhatTheColumnsNeed) {
  AngleFile f = File3d(nullptr);
  for (int i = 0; i < 30; ++i) f.rows.push_back(Row3d(i, 0, 0, 180));
  Trajectory tr;
  Status st = PlanTrajectory(f, planner_scene::Options(), &tr, nullptr);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "mapping.arm_3d");
  EXPECT_NE(st.message().find("pose.side"), std::string::npos) << st.message();
  f = File3d("right");
  for (int i = 0; i < 30; ++i) f.rows.push_back(Row3d(i, 180, 0, 180));
  PlannerOptions o = planner_scene::Options();
  o.mapping.j3_flexion = false;
  st = PlanTrajectory(f, o, &tr, nullptr);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "mapping.arm_3d");
  o.mapping.arm_3d = false;
  EXPECT_TRUE(PlanTrajectory(f, o, &tr, nullptr).ok());
}

}  // namespace
}  // namespace armmimic::robot
