// Inputs the fuzz targets (tests/fuzz) found to break a property, kept as regression tests.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "armmimic/robot/profile.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::robot {
namespace {

// fuzz_profile: "joint_speed_at_100_deg_s = 60,60,60,120,120,.0012" was accepted, but
// FormatProfile wrote J6 as "0.0", which the reader then refused (speeds must be > 0).
TEST(FuzzRegression, ProfileWithSmallValuesReadsBackUnchanged) {
  std::istringstream in(
      "joint_speed_at_100_deg_s = 60.0,60.0,60.0,120.0,120.0,.0012\n"
      "prompt_timeout_s = 0.00025\n");
  ControllerProfile p;
  const Status s = ParseProfile(in, "small.profile", &p);
  ASSERT_TRUE(s.ok()) << s.message();
  std::istringstream again(FormatProfile(p));
  ControllerProfile q;
  const Status back = ParseProfile(again, "again.profile", &q);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(q.joint_speed_at_100_deg_s, p.joint_speed_at_100_deg_s);
  EXPECT_EQ(q.prompt_timeout_s, 0.00025);
  // Ordinary values keep their usual fixed decimals.
  EXPECT_NE(FormatProfile(q).find("joint_speed_at_100_deg_s = 60.0,60.0,60.0,120.0,120.0,0.0012"),
            std::string::npos);
}

// fuzz_val_program (UBSan): "DRIVE 5555...554,-10,50" converted the joint number to int before
// checking its range, which is undefined for a value outside int's range.
TEST(FuzzRegression, DriveWithHugeJointNumberIsRefused) {
  SafetyState st = SafetyState::For(JointLimits(), ControllerProfile());
  ASSERT_TRUE(CheckLine("SPEED 50", st).ok());
  ASSERT_TRUE(CheckLine("DO MOVE #PPOINT(0,-90,0,0,0,0)", st).ok());
  const Status s =
      CheckLine("DO DRIVE 5555555555555555555555555555555555555555555555555554,-10,50", st);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("joint must be 1..6"), std::string::npos) << s.message();
  EXPECT_FALSE(CheckLine("DO DRIVE -1e300,-10,50", st).ok());
  EXPECT_TRUE(CheckLine("DO DRIVE 2,-10,50", st).ok());
}

}  // namespace
}  // namespace armmimic::robot
