// The robot layer's option tables against their structs: documented defaults equal the structs'
// own, every value written reads back the same, and Check() refuses an out-of-range value with
// the key of its row, repeating the value.
#include "armmimic/robot/option_tables.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>

namespace armmimic::robot {
namespace {

template <typename O>
void CheckDefaultsAndRoundTrip(const std::vector<OptionField<O>>& fields, const std::string& table,
                               const O& changed) {
  const O defaults;
  std::set<std::string> keys;
  for (const OptionField<O>& f : fields) {
    EXPECT_TRUE(keys.insert(f.key).second) << table << "." << f.key << " listed twice";
    EXPECT_FALSE(f.label.empty() || f.help.empty()) << f.key;
    if (f.kind == OptionKind::kText) {
      EXPECT_EQ(f.format(defaults), f.default_text) << table << "." << f.key;
    } else {
      EXPECT_EQ(f.get(defaults), f.default_value) << table << "." << f.key;
    }
    // The changed value's exact text, read into a default struct, gives the same text again.
    O back;
    const std::string text = OptionExactText(f, changed);
    ASSERT_TRUE(SetOptionText(f, table + "." + f.key, text, &back).ok()) << f.key << "=" << text;
    EXPECT_EQ(OptionExactText(f, back), text) << f.key;
  }
}

TEST(RobotOptionTablesTest, DefaultsAreTheStructsAndValuesReadBack) {
  PlannerOptions p;
  p.cutoff_hz = 1.0 / 3;
  p.gap = GapMode::kHold;
  p.clamp = true;
  p.speed = SpeedPolicy::kRefuse;
  p.max_interval_s = 2.5;
  CheckDefaultsAndRoundTrip(PlannerOptionFields(), "planner", p);
  MappingOptions m;
  m.j1 = {-1, 12.25};
  m.mirror = true;
  m.j3_flexion = false;
  m.hold_deg = {0, 0, 0, 1.5, -2, 3};
  CheckDefaultsAndRoundTrip(MappingOptionFields(), "mapping", m);
  JointLimits l;
  l.min_deg[2] = -100.125;
  l.max_speed_deg_s = {10, 20, 30, 40, 50, 60};
  CheckDefaultsAndRoundTrip(LimitsOptionFields(), "limits", l);
  LinkSettings k;
  k.wake_attempts = 5;
  k.prompt_settle_s = 0.25;
  CheckDefaultsAndRoundTrip(LinkOptionFields(), "link", k);
  SendSettings s;
  s.profile_path = "docs/profiles/slow controller.profile";
  s.prompt_timeout_s = 2.5;
  s.motion_timeout_s = 90;
  CheckDefaultsAndRoundTrip(SendOptionFields(), "send", s);
  LiveStreamOptions live;
  live.stale_after_s = 0.35;
  CheckDefaultsAndRoundTrip(LiveStreamOptionFields(), "live", live);
  ControllerProfile profile;
  profile.mode = SendMode::kProgram;
  profile.program_name = "ARM2";
  CheckDefaultsAndRoundTrip(ProfileOptionFields(), "profile", profile);
}

TEST(RobotOptionTablesTest, SendAndLiveChecksAreTheirTablesRanges) {
  SendSettings s;
  EXPECT_TRUE(s.Check().ok());  // 0: the profile's timeouts
  s.motion_timeout_s = -1;
  EXPECT_EQ(s.Check().key(), "send.motion_timeout_s");
  EXPECT_EQ(s.Check().message(), "motion timeout is -1 s; it must be >= 0 s");
  LiveStreamOptions live;
  EXPECT_TRUE(live.Check().ok());
  live.stale_after_s = 0;
  EXPECT_EQ(live.Check().key(), "live.stale_after_s");
  EXPECT_EQ(live.Check().message(), "stale-frame timeout is 0 s; it must be > 0 s");
}

TEST(RobotOptionTablesTest, CheckNamesTheKeyOfTheRowOutOfRange) {
  PlannerOptions o;
  EXPECT_TRUE(o.Check().ok());
  o.cutoff_hz = -1;
  EXPECT_EQ(o.Check().key(), "planner.cutoff_hz");
  EXPECT_EQ(o.Check().message(), "cutoff is -1 Hz; it must be >= 0 Hz");
  o = PlannerOptions();
  o.max_jump_deg_s = 0;
  EXPECT_EQ(o.Check().key(), "planner.max_jump_deg_s");
  EXPECT_EQ(o.Check().message(), "max jump speed is 0 deg/s; it must be > 0 deg/s");
  o = PlannerOptions();
  o.min_interval_s = 2;  // above the max interval (1)
  EXPECT_EQ(o.Check().key(), "planner.max_interval_s");
  EXPECT_EQ(o.Check().message(), "max interval is 1 s; it must not be below the min interval 2 s");
  o = PlannerOptions();
  o.limits.max_speed_deg_s[4] = 0;
  EXPECT_EQ(o.Check().key(), "limits.max_speed_deg_s");
  o = PlannerOptions();
  o.mapping.j2.sign = 0.5;
  EXPECT_EQ(o.Check().key(), "mapping.j2");
}

TEST(RobotOptionTablesTest, SettingsLineReadsBackThroughSetPlannerSetting) {
  PlannerOptions o;
  o.deadband_deg = 0.7;
  o.mapping.j2 = {-1, -90};
  o.limits.max_deg[1] = 15;
  const std::string line = DescribePlannerSettings(o);
  ASSERT_EQ(line.rfind("settings ", 0), 0u);
  PlannerOptions back;
  std::istringstream in(line.substr(9));
  std::string item;
  while (in >> item) ASSERT_TRUE(SetPlannerSetting(item, &back).ok()) << item;
  EXPECT_EQ(DescribePlannerSettings(back), line);
  const Status bad = SetPlannerSetting("planner.cutoff_hz=-2", &back);
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(bad.key(), "planner.cutoff_hz");
  EXPECT_FALSE(SetPlannerSetting("planner.nothing=1", &back).ok());
  EXPECT_FALSE(SetPlannerSetting("mapping.j1=2,0", &back).ok());
}

}  // namespace
}  // namespace armmimic::robot
