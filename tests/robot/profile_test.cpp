#include "armmimic/robot/profile.h"

#include <sstream>

#include <gtest/gtest.h>

#include "test_util.h"

namespace armmimic::robot {
namespace {

Status Parse(const std::string& text, ControllerProfile* p) {
  std::istringstream in(text);
  return ParseProfile(in, "my.profile", p);
}

TEST(Profile, DefaultsFollowTheContract) {
  const ControllerProfile p = ControllerProfile::Default();
  EXPECT_EQ(p.terminator, "\r");
  EXPECT_EQ(p.prompt_top, ".");
  EXPECT_EQ(p.prompt_running, "*");
  EXPECT_EQ(p.error_prefix, "*");
  EXPECT_EQ(p.max_line_length, 80);
  EXPECT_EQ(p.move_template, "DO MOVE #PPOINT({j1},{j2},{j3},{j4},{j5},{j6})");
  EXPECT_EQ(p.mode, SendMode::kStream);
  EXPECT_TRUE(p.Check().ok());
}

TEST(Profile, ReadsKeysKeepsDefaultsAndDecodesEscapes) {
  ControllerProfile p;
  const Status s = Parse(
      "# a test controller\n"
      "\n"
      "terminator = \\r\\n\n"
      "echo = no\n"
      "mode = program\n"
      "program_name = ARM1\n"
      "  max_line_length=72  \n"
      "joint_speed_at_100_deg_s = 50, 50, 50, 100, 100, 100\n",
      &p);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(p.terminator, "\r\n");
  EXPECT_FALSE(p.echo);
  EXPECT_EQ(p.mode, SendMode::kProgram);
  EXPECT_EQ(p.program_name, "ARM1");
  EXPECT_EQ(p.max_line_length, 72);
  EXPECT_EQ(p.joint_speed_at_100_deg_s[3], 100);
  EXPECT_EQ(p.prompt_top, ".");  // default kept
}

TEST(Profile, ErrorsNameTheFileAndLine) {
  ControllerProfile p;
  struct Case {
    const char* text;
    const char* expect;
  } cases[] = {
      {"echo = yes\nbogus = 1\n", "my.profile:2: unknown key 'bogus'"},
      {"echo = yes\necho = no\n", "my.profile:2: 'echo' given twice"},
      {"just words\n", "my.profile:1: expected 'key = value'"},
      {"max_line_length = 8x\n", "my.profile:1: max_line_length: '8x' is not a whole number"},
      {"mode = fast\n", "my.profile:1: mode: 'fast' is not stream or program"},
      {"terminator = \\q\n", "my.profile:1: terminator: bad escape"},
      {"move_template = DO MOVE #PPOINT({j1},{j2})\n", "move_template: missing placeholder {j3}"},
      {"speed_template = SPEED {sped}\n", "speed_template: unknown placeholder {sped}"},
      {"joint_speed_at_100_deg_s = 1,2,3\n", "is not six comma-separated speeds"},
      {"max_line_length = 5\n", "max_line_length: must be in 20..1024"},
      {"program_name = A B\n", "program_name"},
  };
  for (const Case& c : cases) {
    const Status s = Parse(c.text, &p);
    ASSERT_FALSE(s.ok()) << c.text;
    EXPECT_NE(s.message().find(c.expect), std::string::npos) << s.message();
  }
  const Status missing = ReadProfile("/nonexistent/x.profile", &p);
  EXPECT_NE(missing.message().find("/nonexistent/x.profile"), std::string::npos);
}

TEST(Profile, FormatReadsBackIdentically) {
  ControllerProfile p;
  p.terminator = "\r\n";
  p.mode = SendMode::kProgram;
  p.echo = false;
  p.prompt_timeout_s = 2.5;
  ControllerProfile q;
  ASSERT_TRUE(Parse(FormatProfile(p), &q).ok());
  EXPECT_EQ(q.terminator, p.terminator);
  EXPECT_EQ(q.mode, p.mode);
  EXPECT_EQ(q.echo, p.echo);
  EXPECT_EQ(q.prompt_timeout_s, 2.5);
  EXPECT_EQ(q.move_template, p.move_template);
}

TEST(Profile, ShippedExampleProfileIsTheDefault) {
  ControllerProfile p;
  const Status s = ReadProfile(test::SourcePath("docs/profiles/default.profile"), &p);
  ASSERT_TRUE(s.ok()) << s.message();
  const ControllerProfile d;
  EXPECT_EQ(FormatProfile(p), FormatProfile(d));
}

TEST(Profile, ReadsAByteOrderMarkAndCrlfLineEnds) {
  for (const std::string first : {"# my controller\r\n", "prompt_timeout_s = 2.5\r\n"}) {
    ControllerProfile p;
    const std::string text = "\xEF\xBB\xBF" + first + "motion_timeout_s = 40\r\nmode = program\r\n";
    const Status st = Parse(text, &p);
    ASSERT_TRUE(st.ok()) << st.message();
    EXPECT_EQ(p.motion_timeout_s, 40);
    EXPECT_EQ(p.mode, SendMode::kProgram);
    if (first[0] == 'p') {
      EXPECT_EQ(p.prompt_timeout_s, 2.5);
    }
  }
}

}  // namespace
}  // namespace armmimic::robot
