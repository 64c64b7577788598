#include "armmimic/robot/val_program.h"

#include <algorithm>
#include <clocale>
#include <locale>
#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/robot/mapping.h"
#include "test_util.h"

namespace armmimic::robot {
namespace {

Trajectory Sample() {
  Trajectory tr;
  tr.keyframes.push_back({0.0, {0, -90, -10, 0, 0, 0}, 100});
  tr.keyframes.push_back({0.5, {10.004, -100.5, -20, 0, 0, 0}, 115});
  tr.keyframes.push_back({1.25, {-159.999, -199.996, 44.996, 265.5, -99.5, -266}, 137});
  tr.keyframes.back().time_s = 100;  // slow enough for the big last step
  return tr;
}

Status Parse(const std::string& text, ValProgram* p, int max_len = 80) {
  std::istringstream in(text);
  return ParseValProgram(in, "prog.val", max_len, p);
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string l;
  while (std::getline(in, l)) out.push_back(l);
  return out;
}

TEST(ValProgram, StreamModeTextReadsBackAndPassesTheSafetyCheck) {
  const ControllerProfile profile;
  const JointLimits limits;
  std::string text;
  ASSERT_TRUE(
      FormatValProgram(Sample(), profile, limits, {"source=a.tsv engine=bgsub"}, &text).ok());
  const auto lines = Lines(text);
  ASSERT_GE(lines.size(), 8u);
  EXPECT_EQ(lines[0], kValMagic);
  EXPECT_EQ(lines[1], "; source=a.tsv engine=bgsub");
  EXPECT_NE(std::find(lines.begin(), lines.end(), "SPEED 75"), lines.end());
  EXPECT_NE(
      std::find(lines.begin(), lines.end(), "DO MOVE #PPOINT(10.00,-100.50,-20.00,0.00,0.00,0.00)"),
      lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(),
                      "DO MOVE #PPOINT(-160.00,-200.00,45.00,265.50,-99.50,-266.00)"),
            lines.end());
  for (const auto& l : lines) {
    if (l[0] != ';') {
      EXPECT_LE(l.size(), 80u) << l;
    }
  }

  ValProgram p;
  ASSERT_TRUE(Parse(text, &p).ok());
  ASSERT_EQ(p.lines.size(), 4u);
  EXPECT_EQ(p.lines[0].text, "SPEED 75");
  EXPECT_TRUE(std::isnan(p.lines[0].time_s));
  EXPECT_DOUBLE_EQ(p.lines[1].time_s, 0);
  EXPECT_DOUBLE_EQ(p.lines[2].time_s, 0.5);
  EXPECT_EQ(p.header.at("source"), "a.tsv");
  ASSERT_TRUE(p.has_header_limits);
  EXPECT_EQ(p.header_limits.min_deg, limits.min_deg);
  EXPECT_EQ(p.header_limits.max_speed_deg_s, limits.max_speed_deg_s);

  SafetyState state = SafetyState::For(limits, profile);
  const Status s = CheckProgram(p, state);
  EXPECT_TRUE(s.ok()) << s.message();
  EXPECT_DOUBLE_EQ(state.last_deg[1], -200);
}

TEST(ValProgram, WrittenTimesNeverOutrunTheSpeedLimitsAfterRounding) {
  // Keyframes exactly at the speed limit: rounding angles to 0.01 and times to 1 ms must not
  // produce a file that the checker refuses.
  Trajectory tr;
  double t = 0, a = -90;
  for (int k = 0; k < 30; ++k) {
    tr.keyframes.push_back({t, {0, a, 0, 0, 0, 0}, k});
    const double step = 3.3337 + 0.01 * k;
    a -= step;
    t += step / 45.0;
  }
  std::string text;
  ASSERT_TRUE(FormatValProgram(tr, ControllerProfile(), JointLimits(), {}, &text).ok());
  ValProgram p;
  ASSERT_TRUE(Parse(text, &p).ok());
  SafetyState state = SafetyState::For(JointLimits(), ControllerProfile());
  state.tolerance_deg = 1e-9;  // exact: the writer must already have made room
  const Status s = CheckProgram(p, state);
  EXPECT_TRUE(s.ok()) << s.message();
}

TEST(ValProgram, ProgramModeUploadsThenExecutes) {
  ControllerProfile profile;
  profile.mode = SendMode::kProgram;
  profile.program_name = "ARM1";
  std::string text;
  ASSERT_TRUE(FormatValProgram(Sample(), profile, JointLimits(), {}, &text).ok());
  ValProgram p;
  ASSERT_TRUE(Parse(text, &p).ok());
  std::vector<std::string> sent;
  for (const auto& l : p.lines) sent.push_back(l.text);
  ASSERT_EQ(sent.size(), 7u);
  EXPECT_EQ(sent[0], "SPEED 75");
  EXPECT_EQ(sent[1], "EDIT ARM1");
  EXPECT_EQ(sent[2], "MOVE #PPOINT(0.00,-90.00,-10.00,0.00,0.00,0.00)");
  EXPECT_EQ(sent[5], "E");
  EXPECT_EQ(sent[6], "EXECUTE ARM1");
  SafetyState state = SafetyState::For(JointLimits(), profile);
  EXPECT_TRUE(CheckProgram(p, state).ok());
}

TEST(ValProgram, NumbersUseDotDecimalsUnderACommaLocale) {
  std::string text;
  Status s, r;
  ValProgram p;
  {
    const test::CommaDecimalLocale comma;
    ASSERT_TRUE(comma.active()) << comma.c_error();
    s = FormatValProgram(Sample(), ControllerProfile(), JointLimits(), {}, &text);
    r = Parse(text, &p);
  }
  ASSERT_TRUE(s.ok());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(p.lines[2].text, "DO MOVE #PPOINT(10.00,-100.50,-20.00,0.00,0.00,0.00)");
  EXPECT_DOUBLE_EQ(p.lines[2].time_s, 0.5);
}

// A global C++ locale with ',' decimals (as a GUI app may install) changes nothing either.
struct CommaDecimals : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

TEST(ValProgram, NumbersIgnoreAGlobalCommaLocale) {
  const std::locale saved =
      std::locale::global(std::locale(std::locale::classic(), new CommaDecimals));
  std::string text;
  const Status s = FormatValProgram(Sample(), ControllerProfile(), JointLimits(), {}, &text);
  ValProgram p;
  const Status r = Parse(text, &p);
  ControllerProfile profile;
  std::istringstream in("prompt_timeout_s = 2.5\n");
  const Status q = ParseProfile(in, "x.profile", &profile);
  JointMap jm;
  const std::string m = ParseJointMap("-1,-12.5", &jm);
  std::locale::global(saved);
  ASSERT_TRUE(s.ok());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(p.lines[2].text, "DO MOVE #PPOINT(10.00,-100.50,-20.00,0.00,0.00,0.00)");
  ASSERT_TRUE(q.ok()) << q.message();
  EXPECT_EQ(profile.prompt_timeout_s, 2.5);
  EXPECT_EQ(m, "");
  EXPECT_EQ(jm.offset_deg, -12.5);
}

TEST(ValProgram, RefusesToWriteLinesOverTheProfilesLimitOrTargetsOutsideLimits) {
  ControllerProfile profile;
  profile.max_line_length = 40;
  std::string text;
  Status s = FormatValProgram(Sample(), profile, JointLimits(), {}, &text);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("max_line_length of 40"), std::string::npos) << s.message();
  EXPECT_TRUE(text.empty());

  Trajectory tr = Sample();
  tr.keyframes[1].joint_deg[1] = 25;
  s = FormatValProgram(tr, ControllerProfile(), JointLimits(), {}, &text);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("frame 115"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("J2"), std::string::npos) << s.message();
}

TEST(ValProgram, ReaderErrorsNameTheLine) {
  ValProgram p;
  struct Case {
    std::string text;
    const char* expect;
  } cases[] = {
      {"SPEED 50\n" + std::string(81, 'X') + "\n", "prog.val:2: line is 81 characters"},
      {"SPEED 50\nDO MOVE\x01\n", "prog.val:2: non-ASCII or control character"},
      {"; t=abc\nSPEED 50\n", "prog.val:1: '; t=abc' is not a timing comment"},
      {"SPEED 50\n; t=1\n", "prog.val:2: timing comment not followed"},
      {"; only a comment\n", "prog.val: no command lines"},
      {"; armmimic VAL program v1\n; limits_min_deg=1,2\nSPEED 5\n", "header limits"},
  };
  for (const Case& c : cases) {
    const Status s = Parse(c.text, &p);
    ASSERT_FALSE(s.ok()) << c.text;
    EXPECT_NE(s.message().find(c.expect), std::string::npos) << s.message();
  }
  EXPECT_FALSE(ReadValProgram("/nonexistent/p.val", &p).ok());
  // CRLF files are read like LF files.
  ASSERT_TRUE(Parse("SPEED 50\r\n; t=0.5\r\nDO MOVE #PPOINT(0,0,0,0,0,0)\r\n", &p).ok());
  EXPECT_EQ(p.lines[1].text, "DO MOVE #PPOINT(0,0,0,0,0,0)");
  EXPECT_DOUBLE_EQ(p.lines[1].time_s, 0.5);
}

SafetyState Ready() {
  SafetyState s = SafetyState::For(JointLimits(), ControllerProfile());
  EXPECT_TRUE(CheckLine("SPEED 50", s).ok());
  return s;
}

TEST(SafetyCheck, RefusesTargetsOutsideTheLimits) {
  SafetyState s = Ready();
  Status r = CheckLine("DO MOVE #PPOINT(0,25,0,0,0,0)", s);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("J2 target 25 is outside the limit J2 [-200.00,20.00]"),
            std::string::npos)
      << r.message();
  EXPECT_FALSE(s.have_position);  // unchanged on refusal
  EXPECT_FALSE(CheckLine("MOVE #PPOINT(0,0,0,0,0,266.5)", s).ok());
  EXPECT_TRUE(CheckLine("do move #ppoint(0, -90, 0, 0, 0, 0)", s).ok());
  EXPECT_TRUE(s.have_position);
}

TEST(SafetyCheck, RefusesMotionBeforeASpeedAndSpeedsOverTheLimit) {
  SafetyState s = SafetyState::For(JointLimits(), ControllerProfile());
  Status r = CheckLine("DO MOVE #PPOINT(0,-90,0,0,0,0)", s);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("before any SPEED"), std::string::npos);
  r = CheckLine("SPEED 100", s);  // J1 60 deg/s at 100 > 45 deg/s
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("J1 move at 60 deg/s"), std::string::npos) << r.message();
  EXPECT_TRUE(CheckLine("SP 75", s).ok());          // unique prefix
  EXPECT_FALSE(CheckLine("DO SPEED 150", s).ok());  // 75% x 150% = 112.5%
  EXPECT_TRUE(CheckLine("DO SPEED 50", s).ok());
  EXPECT_DOUBLE_EQ(s.program_speed_pct, 50);
}

TEST(SafetyCheck, RefusesTimedStepsFasterThanTheSpeedLimit) {
  SafetyState s = Ready();
  ASSERT_TRUE(CheckLine("DO MOVE #PPOINT(0,-90,0,0,0,0)", 0.0, s).ok());
  ASSERT_TRUE(CheckLine("DO MOVE #PPOINT(0,-100,0,0,0,0)", 1.0, s).ok());
  const Status r = CheckLine("DO MOVE #PPOINT(0,-150,0,0,0,0)", 1.5, s);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("J2 moves 50 deg in 0.5 s (100 deg/s)"), std::string::npos)
      << r.message();
  EXPECT_FALSE(CheckLine("DO MOVE #PPOINT(0,-100,0,0,0,0)", 0.5, s).ok());  // time going back
}

TEST(SafetyCheck, ChecksDrivesAgainstTheTrackedPosition) {
  SafetyState s = Ready();
  EXPECT_FALSE(CheckLine("DO DRIVE 2,-10,50", s).ok());  // position unknown
  ASSERT_TRUE(CheckLine("DO MOVE #PPOINT(0,10,0,0,0,0)", s).ok());
  const Status r = CheckLine("DO DRIVE 2,15,50", s);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("J2 would reach 25"), std::string::npos) << r.message();
  EXPECT_TRUE(CheckLine("DO DRIVE 2,-10,50", s).ok());
  EXPECT_DOUBLE_EQ(s.last_deg[1], 0);
  EXPECT_FALSE(CheckLine("DO DRIVE 7,1,50", s).ok());
  EXPECT_FALSE(CheckLine("DO DRIVE 2,1,101", s).ok());
}

TEST(SafetyCheck, RefusesWhatItCannotVerify) {
  SafetyState s = Ready();
  for (const char* line :
       {"DO READY", "DO MOVE SAFE", "MOVES #PPOINT(0,0,0,0,0,0)", "DO MOVE #PPOINT(0,0,0,0,0)",
        "DO MOVE #PPOINT(0,0,0,0,0,0,0)", "HERE #A", "EXECUTE OTHER", "E", "; comment",
        "DO MOVE #PPOINT(0,0,0,0,0,0) extra", "DO MOVE #PPOINT(0,nan,0,0,0,0)",
        "DO MOVE #PPOINT(0,-1e1,0,0,0,0)", "DO MOVE #PPOINT(0,0x10,0,0,0,0)", "SPEED .",
        "SPEED inf", "SPEED 1e2"}) {
    EXPECT_FALSE(CheckLine(line, s).ok()) << line;
  }
  EXPECT_FALSE(CheckLine(std::string(81, ' ') + "SPEED 5", s).ok());
  EXPECT_TRUE(CheckLine("", s).ok());
}

TEST(SafetyCheck, HandEditedProgramIsRefusedAtTheOffendingLine) {
  ValProgram p;
  ASSERT_TRUE(Parse("; edited by hand\nSPEED 50\nEDIT P1\nMOVE #PPOINT(0,-90,0,0,0,0)\n"
                    "MOVE #PPOINT(0,-90,50,0,0,0)\nE\nEX P1\n",
                    &p)
                  .ok());
  SafetyState s = SafetyState::For(JointLimits(), ControllerProfile());
  const Status r = CheckProgram(p, s);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message().rfind("prog.val:5: ", 0), 0u) << r.message();
  EXPECT_NE(r.message().find("J3 target 50"), std::string::npos) << r.message();
}

TEST(ValProgram, SpeedSettingKeepsEveryJointUnderItsLimit) {
  JointLimits l;
  ControllerProfile p;
  EXPECT_EQ(SpeedSettingFor(l, p), 75);
  l.max_speed_deg_s[4] = 12;  // 12/120 -> 10%
  EXPECT_EQ(SpeedSettingFor(l, p), 10);
  l.max_speed_deg_s.fill(1000);
  EXPECT_EQ(SpeedSettingFor(l, p), 100);
}

TEST(Limits, ParsesOverridesAndSpeedLists) {
  JointLimits l;
  EXPECT_EQ(ParseLimitsOverride("J1=-90:90,j3=-200:0", &l), "");
  EXPECT_EQ(l.min_deg[0], -90);
  EXPECT_EQ(l.max_deg[2], 0);
  EXPECT_EQ(l.min_deg[1], -200);  // untouched
  EXPECT_NE(ParseLimitsOverride("J7=0:1", &l), "");
  EXPECT_NE(ParseLimitsOverride("J2=5:1", &l), "");
  EXPECT_NE(ParseLimitsOverride("J2=a:1", &l), "");
  EXPECT_NE(ParseLimitsOverride("", &l), "");
  EXPECT_EQ(ParseSpeedLimits("30", &l), "");
  EXPECT_EQ(l.max_speed_deg_s[5], 30);
  EXPECT_EQ(ParseSpeedLimits("1,2,3,4,5,6", &l), "");
  EXPECT_EQ(l.max_speed_deg_s[5], 6);
  EXPECT_NE(ParseSpeedLimits("1,2", &l), "");
  EXPECT_NE(ParseSpeedLimits("0", &l), "");
  JointLimits bad;
  bad.min_deg[3] = 300;
  EXPECT_NE(bad.Check().message().find("J4"), std::string::npos);
}

TEST(ValProgram, ReadsAByteOrderMarkAndCrlfLineEnds) {
  for (const std::string first : {"; armmimic VAL program v1\r\n", "SPEED 50\r\n"}) {
    ValProgram p;
    const std::string text =
        "\xEF\xBB\xBF" + first + "; t=0.5\r\nDO MOVE #PPOINT(0,-90,0,0,0,0)\r\n";
    const Status st = Parse(text, &p);
    ASSERT_TRUE(st.ok()) << st.message();
    EXPECT_EQ(p.lines.back().text, "DO MOVE #PPOINT(0,-90,0,0,0,0)");
    EXPECT_DOUBLE_EQ(p.lines.back().time_s, 0.5);
    if (first[0] == 'S') {
      EXPECT_EQ(p.lines[0].text, "SPEED 50");
    }
  }
}

}  // namespace
}  // namespace armmimic::robot
