// The summary shown before a send moves the arm: counts, duration, start pose and ranges, for a
// fresh send and for the rest of a resumed one.
#include "armmimic/robot/send_summary.h"

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/robot/journal.h"
#include "test_util.h"

namespace armmimic::robot {
namespace {

const char* kText =
    "SPEED 50\n"
    "; t=0.000\n"
    "DO MOVE #PPOINT(0.00,-90.00,0.00,0.00,0.00,0.00)\n"
    "; t=1.500\n"
    "DO MOVE #PPOINT(20.00,-60.00,-30.00,0.00,0.00,0.00)\n"
    "; t=3.000\n"
    "DO MOVE #PPOINT(-10.00,-75.00,-45.00,0.00,0.00,0.00)\n";

ValProgram Program(const std::string& text) {
  std::istringstream in(text);
  ValProgram p;
  EXPECT_TRUE(ParseValProgram(in, "p.val", 80, &p).ok());
  return p;
}

TEST(SendSummary, FreshSendShowsDurationStartPoseAndRanges) {
  test::TempDir dir;
  SendSession session;
  SendStart start;
  start.journal = false;
  ASSERT_TRUE(session
                  .Prepare(Program(kText), ControllerProfile::Default(), JointLimits(),
                           dir.file("p.val"), start)
                  .ok());
  const SendSummary s = SummarizeSend(session);
  EXPECT_EQ(s.lines, 4);
  EXPECT_EQ(s.moves, 3);
  EXPECT_DOUBLE_EQ(s.duration_s, 3.0);
  ASSERT_TRUE(s.has_start);
  EXPECT_EQ(s.start_deg[1], -90);
  EXPECT_EQ(s.min_deg[0], -10);
  EXPECT_EQ(s.max_deg[0], 20);
  EXPECT_EQ(s.min_deg[2], -45);
  EXPECT_EQ(s.max_deg[2], 0);
  EXPECT_TRUE(s.resumed_at.empty());
  const std::string text = FormatSendSummary(s);
  EXPECT_NE(text.find("4 lines (3 motion), about 3.0 s"), std::string::npos) << text;
  EXPECT_NE(text.find("J1 0.0 J2 -90.0 J3 0.0"), std::string::npos) << text;
  EXPECT_NE(text.find("J1     -10.0 ..     20.0   (limits -160 .. 160)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("J3     -45.0 ..      0.0   (limits -225 .. 45)"), std::string::npos) << text;
}

TEST(SendSummary, AResumeSummarisesOnlyTheRest) {
  test::TempDir dir;
  const ValProgram program = Program(kText);
  std::vector<std::string> texts;
  for (const ValLine& l : program.lines) texts.push_back(l.text);
  {
    SendJournal j;
    ASSERT_TRUE(
        j.Open(dir.file("p.val.journal"), SendJournal::Hash(texts), 4, "p.val", false).ok());
    for (int i = 1; i <= 2; ++i) {
      ASSERT_TRUE(j.Sent(i, program.lines[i - 1].line_no).ok());
      ASSERT_TRUE(j.Acked(i, program.lines[i - 1].line_no).ok());
    }
  }
  SendSession session;
  SendStart start;
  start.mode = SendStart::Mode::kResume;
  ASSERT_TRUE(
      session
          .Prepare(program, ControllerProfile::Default(), JointLimits(), dir.file("p.val"), start)
          .ok());
  const SendSummary s = SummarizeSend(session);
  EXPECT_EQ(s.lines, 3);  // SPEED again, then the two moves left
  EXPECT_EQ(s.moves, 2);
  EXPECT_DOUBLE_EQ(s.duration_s, 3.0);  // from the last acknowledged move at t=0
  ASSERT_TRUE(s.has_start);
  EXPECT_EQ(s.start_deg[0], 20);  // the first target still to go
  EXPECT_EQ(s.min_deg[1], -75);
  EXPECT_EQ(s.max_deg[1], -60);
  EXPECT_EQ(s.resumed_at, "p.val:5");
  EXPECT_NE(FormatSendSummary(s).find("resuming at p.val:5"), std::string::npos);
  // What is left of the program, and where the two acknowledged lines left the arm.
  EXPECT_EQ(s.remaining_lines, 2);
  EXPECT_EQ(s.total_lines, 4);
  ASSERT_TRUE(s.has_resume_pose);
  EXPECT_EQ(s.resume_pose_deg[0], 0);
  EXPECT_EQ(s.resume_pose_deg[1], -90);
  const std::string text = FormatSendSummary(s);
  EXPECT_NE(text.find("2 of 4 program lines still to send"), std::string::npos) << text;
  EXPECT_NE(text.find("left it: J1 0.0 J2 -90.0 J3 0.0"), std::string::npos) << text;
}

TEST(SendSummary, AnUntimedProgramSaysSo) {
  test::TempDir dir;
  SendSession session;
  SendStart start;
  start.journal = false;
  ASSERT_TRUE(session
                  .Prepare(Program("SPEED 20\nDO MOVE #PPOINT(5,-90,0,0,0,0)\n"),
                           ControllerProfile::Default(), JointLimits(), dir.file("q.val"), start)
                  .ok());
  const SendSummary s = SummarizeSend(session);
  EXPECT_TRUE(std::isnan(s.duration_s));
  EXPECT_NE(FormatSendSummary(s).find("no planned times"), std::string::npos);
}

TEST(SendSummary, RangesNeverSayMinusZero) {
  SendSummary s;
  s.has_start = s.has_range = true;
  s.min_deg[1] = -151.7;
  s.max_deg[1] = -0.0;   // the arm hanging, reached from below
  s.max_deg[2] = -0.02;  // rounds to zero
  s.start_deg[2] = -0.04;
  const std::string text = FormatSendSummary(s);
  EXPECT_EQ(text.find("-0.0"), std::string::npos) << text;
  EXPECT_NE(text.find("-151.7 ..      0.0"), std::string::npos) << text;
}

}  // namespace
}  // namespace armmimic::robot
