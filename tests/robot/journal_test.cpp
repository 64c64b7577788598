#include "armmimic/robot/journal.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace armmimic::robot {
namespace {

TEST(SendJournal, RecordsSentAndAcknowledgedLines) {
  test::TempDir dir;
  const std::string path = SendJournal::PathFor(dir.file("p.val"));
  EXPECT_EQ(path, dir.file("p.val.journal"));
  const std::string hash = SendJournal::Hash({"SPEED 50", "DO MOVE #PPOINT(1,2,3,4,5,6)"});
  {
    SendJournal j;
    ASSERT_TRUE(j.Open(path, hash, 2, "my p.val", false).ok());
    ASSERT_TRUE(j.Sent(1, 4).ok());
    ASSERT_TRUE(j.Acked(1, 4).ok());
    ASSERT_TRUE(j.Sent(2, 6).ok());
  }
  JournalState s;
  ASSERT_TRUE(SendJournal::Read(path, &s).ok());
  EXPECT_TRUE(s.exists);
  EXPECT_EQ(s.hash, hash);
  EXPECT_EQ(s.lines, 2);
  EXPECT_EQ(s.acknowledged, 1);
  EXPECT_EQ(s.sent, 2);
  EXPECT_EQ(s.sent_line_no, 6);
  EXPECT_TRUE(s.uncertain());
  EXPECT_FALSE(s.done);
  {
    SendJournal j;
    ASSERT_TRUE(j.Open(path, hash, 2, "p.val", true).ok());
    ASSERT_TRUE(j.Acked(2, 6, "where").ok());
    ASSERT_TRUE(j.Acked(1, 4).ok());  // a setup line sent again on resume
    ASSERT_TRUE(j.Done().ok());
  }
  ASSERT_TRUE(SendJournal::Read(path, &s).ok());
  EXPECT_EQ(s.acknowledged, 2);
  EXPECT_FALSE(s.uncertain());
  EXPECT_TRUE(s.done);
}

TEST(SendJournal, MissingJournalIsNotAnError) {
  test::TempDir dir;
  JournalState s;
  ASSERT_TRUE(SendJournal::Read(dir.file("none.journal"), &s).ok());
  EXPECT_FALSE(s.exists);
  EXPECT_EQ(s.acknowledged, 0);
}

TEST(SendJournal, HashDependsOnEveryLineAndTheirOrder) {
  EXPECT_EQ(SendJournal::Hash({"A", "B"}), SendJournal::Hash({"A", "B"}));
  EXPECT_NE(SendJournal::Hash({"A", "B"}), SendJournal::Hash({"B", "A"}));
  EXPECT_NE(SendJournal::Hash({"AB"}), SendJournal::Hash({"A", "B"}));
  EXPECT_EQ(SendJournal::Hash({"A"}).size(), 16u);
}

TEST(SendJournal, DamagedJournalNamesTheLine) {
  test::TempDir dir;
  const std::string path = dir.file("p.val.journal");
  test::WriteFile(path, "not a journal\n");
  JournalState s;
  Status st = SendJournal::Read(path, &s);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("p.val.journal:1"), std::string::npos) << st.message();

  test::WriteFile(path, "# armmimic send journal v1\nprogram sha=00 lines=2\nack x 3\nsent 1 2\n");
  st = SendJournal::Read(path, &s);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("p.val.journal:3"), std::string::npos) << st.message();
}

TEST(SendJournal, ARecordCutShortByACrashIsIgnored) {
  test::TempDir dir;
  const std::string path = dir.file("p.val.journal");
  test::WriteFile(path,
                  "# armmimic send journal v1\nprogram sha=ab lines=3\nsent 1 2\nack 1 2\nse");
  JournalState s;
  ASSERT_TRUE(SendJournal::Read(path, &s).ok());
  EXPECT_EQ(s.acknowledged, 1);
  EXPECT_FALSE(s.uncertain());
}

}  // namespace
}  // namespace armmimic::robot
