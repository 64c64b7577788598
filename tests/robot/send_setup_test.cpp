// The send settings both shells fill: the profile with its timeouts, the start mode, and the
// unfinished send a journal records.
#include "armmimic/robot/send_setup.h"

#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/robot/journal.h"
#include "test_util.h"

namespace armmimic::robot {
namespace {

ValProgram Program(const std::string& text) {
  std::istringstream in(text);
  ValProgram p;
  EXPECT_TRUE(ParseValProgram(in, "p.val", 80, &p).ok());
  return p;
}

const char* kText =
    "SPEED 50\n"
    "; t=0.000\n"
    "DO MOVE #PPOINT(0.00,-90.00,0.00,0.00,0.00,0.00)\n"
    "; t=1.000\n"
    "DO MOVE #PPOINT(10.00,-80.00,-5.00,0.00,0.00,0.00)\n";

TEST(SendSetup, ProfileFileAndTimeoutsAreApplied) {
  test::TempDir dir;
  test::WriteFile(dir.file("slow.profile"), "name = slow\nmode = program\nmotion_timeout_s = 90\n");
  SendSettings settings;
  ControllerProfile profile;
  ASSERT_TRUE(LoadSendProfile(settings, &profile).ok());
  EXPECT_EQ(profile.name, ControllerProfile::Default().name);
  EXPECT_EQ(profile.prompt_timeout_s, ControllerProfile::Default().prompt_timeout_s);

  settings.profile_path = dir.file("slow.profile");
  settings.prompt_timeout_s = 2.5;
  ASSERT_TRUE(LoadSendProfile(settings, &profile).ok());
  EXPECT_EQ(profile.name, "slow");
  EXPECT_EQ(profile.mode, SendMode::kProgram);
  EXPECT_EQ(profile.prompt_timeout_s, 2.5);  // the override
  EXPECT_EQ(profile.motion_timeout_s, 90);   // the file's

  settings.motion_timeout_s = -1;
  const Status bad = LoadSendProfile(settings, &profile);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("motion timeout"), std::string::npos) << bad.message();
}

TEST(SendSetup, ABadProfileFileIsNamedWithItsLine) {
  test::TempDir dir;
  test::WriteFile(dir.file("bad.profile"), "name = x\nno_such_key = 1\n");
  SendSettings settings;
  settings.profile_path = dir.file("bad.profile");
  ControllerProfile profile;
  const Status s = LoadSendProfile(settings, &profile);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("bad.profile:2"), std::string::npos) << s.message();
}

TEST(SendSetup, StartModesFollowTheSwitches) {
  EXPECT_EQ(StartFor(false, false).mode, SendStart::Mode::kFresh);
  EXPECT_EQ(StartFor(true, false).mode, SendStart::Mode::kResume);
  EXPECT_EQ(StartFor(false, true).mode, SendStart::Mode::kRestart);
  EXPECT_TRUE(StartFor(true, false).journal);
}

TEST(SendSetup, AnUnfinishedSendIsFoundOnlyForTheSameLines) {
  test::TempDir dir;
  const std::string input = dir.file("p.val");
  const ValProgram program = Program(kText);
  UnfinishedSend u;
  ASSERT_TRUE(FindUnfinishedSend(program, input, &u).ok());
  EXPECT_FALSE(u.found);  // no journal
  EXPECT_FALSE(u.journal_exists);
  EXPECT_EQ(u.journal_path, input + ".journal");

  std::vector<std::string> texts;
  for (const ValLine& l : program.lines) texts.push_back(l.text);
  {
    SendJournal j;
    ASSERT_TRUE(j.Open(u.journal_path, SendJournal::Hash(texts), 3, "p.val", false).ok());
    ASSERT_TRUE(j.Sent(1, 1).ok());
    ASSERT_TRUE(j.Acked(1, 1).ok());
    ASSERT_TRUE(j.Sent(2, 3).ok());
  }
  ASSERT_TRUE(FindUnfinishedSend(program, input, &u).ok());
  EXPECT_TRUE(u.found);
  EXPECT_EQ(u.acknowledged, 1);
  EXPECT_EQ(u.total, 3);

  // Another program with the same input name: its journal is not this program's.
  const ValProgram other = Program("SPEED 40\nDO MOVE #PPOINT(0,-90,0,0,0,0)\n");
  ASSERT_TRUE(FindUnfinishedSend(other, input, &u).ok());
  EXPECT_FALSE(u.found);
  EXPECT_TRUE(u.journal_exists);
  EXPECT_FALSE(u.same_program);

  {
    SendJournal j;
    ASSERT_TRUE(j.Open(u.journal_path, SendJournal::Hash(texts), 3, "p.val", true).ok());
    ASSERT_TRUE(j.Done().ok());
  }
  ASSERT_TRUE(FindUnfinishedSend(program, input, &u).ok());
  EXPECT_FALSE(u.found);  // finished
  EXPECT_TRUE(u.done);

  test::WriteFile(u.journal_path, "not a journal\n");
  const Status bad = FindUnfinishedSend(program, input, &u);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("p.val.journal"), std::string::npos) << bad.message();
}

}  // namespace
}  // namespace armmimic::robot
