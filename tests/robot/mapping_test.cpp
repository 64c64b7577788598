#include "armmimic/robot/mapping.h"

#include <gtest/gtest.h>

#include "armmimic/core/angles.h"

namespace armmimic::robot {
namespace {

// The contract: every pose a human arm can take lands inside the default limits with the
// default mapping, for the arm on either side of the body and with or without mirroring.
TEST(Mapping, DefaultArmMappingKeepsEveryHumanPoseInsideDefaultLimits) {
  const JointLimits limits;
  for (bool mirror : {false, true}) {
    MappingOptions m = MappingOptions::Default(SourceKind::kArm);
    m.mirror = mirror;
    int checked = 0;
    // Upper arm: every direction (hanging -90, horizontal 0 or 180 on either side, raised 90),
    // also as unwrapped values a continuous recording produces.
    for (double upper = -450; upper <= 450; upper += 2.5) {
      // Elbow flexion 0..150 with the 2-D bend of either sign, also unwrapped.
      for (double flex = 0; flex <= 150; flex += 5) {
        for (double bend : {flex, -flex, flex + 360, -flex - 360}) {
          for (double yaw = 0; yaw <= 90; yaw += 15) {
            const JointArray q = m.Map(upper, bend, yaw);
            for (int j = 0; j < kJoints; ++j) {
              ASSERT_TRUE(limits.Inside(j, q[j]))
                  << "J" << j + 1 << "=" << q[j] << " for upper=" << upper << " bend=" << bend
                  << " yaw=" << yaw << " mirror=" << mirror;
            }
            ++checked;
          }
        }
      }
    }
    EXPECT_GT(checked, 100000);
  }
}

TEST(Mapping, DefaultArmMappingIsMonotonicInElevationAndFlexion) {
  const MappingOptions m = MappingOptions::Default(SourceKind::kArm);
  // Hanging, horizontal (both sides) and raised give distinct, ordered J2.
  const double hanging = m.Map(-90, 0, 0)[1];
  const double right = m.Map(0, 0, 0)[1];
  const double left = m.Map(180, 0, 0)[1];
  const double raised = m.Map(90, 0, 0)[1];
  EXPECT_DOUBLE_EQ(hanging, 0);
  EXPECT_DOUBLE_EQ(right, -90);
  EXPECT_DOUBLE_EQ(left, -90);
  EXPECT_DOUBLE_EQ(raised, -180);
  EXPECT_DOUBLE_EQ(m.Map(-90, 120, 0)[2], -120);
  EXPECT_DOUBLE_EQ(m.Map(-90, -120, 0)[2], -120);
  EXPECT_DOUBLE_EQ(m.Map(-90, 0, 30)[0], 30);
}

TEST(Mapping, MirrorTurnsTheWaistTheOtherWay) {
  MappingOptions m = MappingOptions::Default(SourceKind::kArm);
  m.mirror = true;
  EXPECT_DOUBLE_EQ(m.Map(-90, 0, 30)[0], -30);
  m.j2_elevation = false;
  m.j2 = {1, 0};
  EXPECT_DOUBLE_EQ(m.Map(10, 0, 0)[1], 170);
}

TEST(Mapping, DefaultMarkerMappingKeepsTheMarkersRangeInsideLimits) {
  const JointLimits limits;
  const MappingOptions m = MappingOptions::Default(SourceKind::kMarker);
  for (bool mirror : {false, true}) {
    MappingOptions mm = m;
    mm.mirror = mirror;
    for (double bend = -110; bend <= 110; bend += 1) {
      for (double yaw = 0; yaw <= 90; yaw += 5) {
        const JointArray q = mm.Map(kNaN, bend, yaw);
        for (int j = 0; j < kJoints; ++j) ASSERT_TRUE(limits.Inside(j, q[j])) << j << " " << bend;
        EXPECT_DOUBLE_EQ(q[2], 0);  // J3 kept aligned
      }
    }
  }
  EXPECT_DOUBLE_EQ(m.Map(kNaN, 0, 0)[1], -90);
}

TEST(Mapping, ParsesSignOffsetAndRejectsGarbage) {
  JointMap jm;
  EXPECT_EQ(ParseJointMap("-1,-90", &jm), "");
  EXPECT_EQ(jm.sign, -1);
  EXPECT_EQ(jm.offset_deg, -90);
  EXPECT_EQ(ParseJointMap("+,12.5", &jm), "");
  EXPECT_EQ(jm.sign, 1);
  EXPECT_EQ(jm.offset_deg, 12.5);
  EXPECT_NE(ParseJointMap("2,0", &jm), "");
  EXPECT_NE(ParseJointMap("-1", &jm), "");
  EXPECT_NE(ParseJointMap("-1,abc", &jm), "");
  EXPECT_NE(ParseJointMap("-1,nan", &jm), "");
}

TEST(Mapping, CheckRejectsBadSignsAndDetectsMarkerFiles) {
  MappingOptions m;
  m.j2.sign = 0.5;
  EXPECT_FALSE(m.Check().ok());
  EXPECT_NE(m.Check().message().find("J2"), std::string::npos);
  AngleFile f;
  EXPECT_EQ(DetectSourceKind(f), SourceKind::kArm);
  f.meta = {{"engine", "marker"}};
  EXPECT_EQ(DetectSourceKind(f), SourceKind::kMarker);
}

}  // namespace
}  // namespace armmimic::robot
