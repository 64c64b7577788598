#include "armmimic/robot/kinematics.h"

#include <random>

#include <gtest/gtest.h>

namespace armmimic::robot {
namespace {

constexpr double kTol = 1e-9;

void ExpectAt(const Eigen::Vector3d& p, double x, double y, double z, const char* what) {
  EXPECT_NEAR(p.x(), x, kTol) << what;
  EXPECT_NEAR(p.y(), y, kTol) << what;
  EXPECT_NEAR(p.z(), z, kTol) << what;
}

// The link lengths of docs/robot.md: shoulder 1.12 m up, upper arm 0.65, offset 0.19, forearm
// 0.60.
TEST(Kinematics, GeometryIsThePuma760s) {
  const ArmGeometry g;
  EXPECT_DOUBLE_EQ(g.shoulder_height_m, 1.12);
  EXPECT_DOUBLE_EQ(g.upper_arm_m, 0.65);
  EXPECT_DOUBLE_EQ(g.shoulder_offset_m, 0.19);
  EXPECT_DOUBLE_EQ(g.forearm_m, 0.60);
}

TEST(Kinematics, ZeroHangsTheArmStraightDown) {
  const ArmPose p = ForwardKinematics({0, 0, 0, 0, 0, 0});
  ExpectAt(p.shoulder, 0, 0, 1.12, "shoulder");
  ExpectAt(p.elbow, 0, 0.19, 1.12 - 0.65, "elbow");
  ExpectAt(p.wrist, 0, 0.19, 1.12 - 1.25, "wrist");
  ExpectAt(p.flange, 0, 0.19, 1.12 - 1.35, "flange");
}

TEST(Kinematics, J2RaisesTheArmForwardThenUp) {
  ExpectAt(ForwardKinematics({0, -90, 0, 0, 0, 0}).wrist, 1.25, 0.19, 1.12, "level");
  ExpectAt(ForwardKinematics({0, -180, 0, 0, 0, 0}).wrist, 0, 0.19, 1.12 + 1.25, "raised");
  // J2's positive end of the range swings the arm back behind the column.
  EXPECT_LT(ForwardKinematics({0, 20, 0, 0, 0, 0}).elbow.x(), 0);
}

TEST(Kinematics, J3FlexesTheElbowTheWayJ2RaisesTheArm) {
  const ArmPose p = ForwardKinematics({0, -90, -90, 0, 0, 0});
  ExpectAt(p.elbow, 0.65, 0.19, 1.12, "elbow");
  ExpectAt(p.wrist, 0.65, 0.19, 1.12 + 0.60, "wrist");
}

TEST(Kinematics, J1TurnsTheArmCounterClockwiseSeenFromAbove) {
  const ArmPose p = ForwardKinematics({90, -90, 0, 0, 0, 0});
  ExpectAt(p.wrist, -0.19, 1.25, 1.12, "wrist");
}

TEST(Kinematics, TheWristJointsMoveOnlyWhatComesAfterThem) {
  const JointArray q = {30, -70, -40, 0, 0, 0};
  const ArmPose a = ForwardKinematics(q);
  JointArray r = q;
  r[3] = 75;  // J4 rolls the wrist: the centre stays, the flange stays on the forearm's line
  const ArmPose b = ForwardKinematics(r);
  EXPECT_NEAR((a.wrist - b.wrist).norm(), 0, kTol);
  EXPECT_NEAR((a.flange - b.flange).norm(), 0, kTol);
  r[4] = 60;  // J5 bends: the flange moves on a sphere about the wrist centre
  const ArmPose c = ForwardKinematics(r);
  EXPECT_NEAR((c.wrist - a.wrist).norm(), 0, kTol);
  EXPECT_GT((c.flange - a.flange).norm(), 0.05);
  EXPECT_NEAR((c.flange - c.wrist).norm(), 0.10, kTol);
  r[5] = 120;  // J6 only rolls the flange
  const ArmPose d = ForwardKinematics(r);
  EXPECT_NEAR((d.flange - c.flange).norm(), 0, kTol);
  EXPECT_GT((d.rotation[6] - c.rotation[6]).norm(), 0.5);
}

TEST(Kinematics, LinksKeepTheirLengthsInEveryPose) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> deg(-300, 300);
  for (int i = 0; i < 200; ++i) {
    JointArray q;
    for (double& v : q) v = deg(rng);
    const ArmPose p = ForwardKinematics(q);
    EXPECT_NEAR((p.elbow - p.shoulder_side).norm(), 0.65, kTol);
    EXPECT_NEAR((p.wrist - p.elbow).norm(), 0.60, kTol);
    EXPECT_NEAR((p.shoulder_side - p.shoulder).norm(), 0.19, kTol);
    EXPECT_NEAR(p.shoulder_side.z(), 1.12, kTol);  // the J2 axis is level whatever J1 is
    for (const Eigen::Matrix3d& r : p.rotation) {
      EXPECT_NEAR((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-9);
    }
  }
}

TEST(Kinematics, PartsFollowTheirJointsAndOnlyViolatingOnesAreMarked) {
  const JointLimits limits;
  const JointArray q = {0, -90, 60, 0, 0, 0};  // J3 above its 45 degree limit
  const std::array<bool, kJoints> out = JointsOutside(limits, q);
  EXPECT_EQ(out, (std::array<bool, kJoints>{false, false, true, false, false, false}));
  const std::vector<ArmPart> parts = ArmParts(ForwardKinematics(q));
  int forearm_parts = 0;
  for (const ArmPart& part : parts) {
    EXPECT_GE(part.joint, -1);
    EXPECT_LT(part.joint, kJoints);
    EXPECT_GT(part.radius_m, 0);
    if (part.joint == 2) ++forearm_parts;
  }
  EXPECT_EQ(parts.front().joint, -1);  // the pedestal, on the base plane
  EXPECT_NEAR(parts.front().from.z(), 0, kTol);
  EXPECT_EQ(forearm_parts, 2);  // elbow knuckle and forearm turn red with J3
  // The limits are inclusive: a joint exactly at its end is inside.
  EXPECT_EQ(JointsOutside(limits, {160, -200, 45, -266, 100, 266}), (std::array<bool, kJoints>{}));
}

// A row of the 3-D columns with both segments along (az, el).
AngleRow Arm3d(double az, double el) {
  AngleRow r;
  r.status = RowStatus::kOk;
  r.upper_az_deg = r.fore_az_deg = az;
  r.upper_el_deg = r.fore_el_deg = el;
  r.elbow_deg = 180;
  return r;
}

TEST(Kinematics, ThePersonsArmPointsWhereTheDefaultMappingTurnsTheRobot) {
  PersonArm a;
  const ArmGeometry g;
  // On the image's right, level in the image plane: outward, as J1 = 0 and J2 = -90 hold the
  // robot's upper arm (+x), beside the robot at its shoulder height.
  ASSERT_TRUE(PersonArmFromRow(Arm3d(0, 0), 1, &a));
  EXPECT_TRUE(a.shoulder.isApprox(Eigen::Vector3d(0, -0.9, g.shoulder_height_m)));
  EXPECT_TRUE((a.elbow - a.shoulder).isApprox(Eigen::Vector3d(g.upper_arm_m, 0, 0)));
  EXPECT_TRUE((a.wrist - a.elbow).isApprox(Eigen::Vector3d(g.forearm_m, 0, 0)));
  // The same arm on the image's left points outward at azimuth 180: +x again.
  ASSERT_TRUE(PersonArmFromRow(Arm3d(180, 0), -1, &a));
  EXPECT_NEAR((a.elbow - a.shoulder).x(), g.upper_arm_m, 1e-12);
  // Reaching at the camera (azimuth 90): +y, where J1 = +90 turns the robot.
  ASSERT_TRUE(PersonArmFromRow(Arm3d(90, 0), 1, &a));
  EXPECT_NEAR((a.elbow - a.shoulder).y(), g.upper_arm_m, 1e-12);
  // Hanging: straight down; raised: straight up.
  ASSERT_TRUE(PersonArmFromRow(Arm3d(0, -90), 1, &a));
  EXPECT_NEAR((a.elbow - a.shoulder).z(), -g.upper_arm_m, 1e-12);
  ASSERT_TRUE(PersonArmFromRow(Arm3d(0, 90), 1, &a));
  EXPECT_NEAR((a.elbow - a.shoulder).z(), g.upper_arm_m, 1e-12);
  // No side, a lost row or a missing column: nothing to draw.
  EXPECT_FALSE(PersonArmFromRow(Arm3d(0, 0), 0, &a));
  AngleRow lost = Arm3d(0, 0);
  lost.status = RowStatus::kLost;
  EXPECT_FALSE(PersonArmFromRow(lost, 1, &a));
  AngleRow partial = Arm3d(0, 0);
  partial.fore_el_deg = kNaN;
  EXPECT_FALSE(PersonArmFromRow(partial, 1, &a));
}

}  // namespace
}  // namespace armmimic::robot
