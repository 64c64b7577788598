// A truncated video is incomplete: analyze marks its angle file complete=no with the reason and
// exits 1, a batch records it as incomplete, plan and send warn on such a file and refuse it
// with --strict; the run such a file records still repeats (--params-from).
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "small_scene.h"

namespace armmimic {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::string& Scene() { return test::SmallScene(11, 140); }

std::vector<std::string> BgsubFlags() { return test::SmallSceneBgsubFlags(Scene()); }

class CliTruncated : public ::testing::Test {
 protected:
  void SetUp() override {
    // The first quarter of the scene's bytes: the header still announces every frame.
    const std::string whole = Scene() + "/scene.avi";
    truncated_ = dir_.file("quarter.avi");
    std::filesystem::copy_file(whole, truncated_);
    std::filesystem::resize_file(truncated_, std::filesystem::file_size(whole) / 4);
  }
  test::CliResult Analyze(const std::string& video, const std::string& out) {
    std::vector<std::string> a = {"--no-progress", "analyze", video, "-o", out};
    for (const std::string& f : BgsubFlags()) a.push_back(f);
    return test::RunCli(a);
  }
  test::TempDir dir_;
  std::string truncated_;
};

TEST_F(CliTruncated, AnalyzeMarksTheFileIncompleteWithTheReasonAndExitsOne) {
  const test::CliResult r = Analyze(truncated_, dir_.file("q.tsv"));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, "quarter.avi")) << r.err;
  EXPECT_TRUE(Contains(r.err, "complete=no")) << r.err;
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(dir_.file("q.tsv"), &angles).ok());
  EXPECT_FALSE(angles.complete);
  EXPECT_TRUE(Contains(angles.Meta("incomplete"), "only")) << angles.Meta("incomplete");
  EXPECT_FALSE(angles.rows.empty()) << "the rows read are kept";
  // The whole video still gives a complete file and exit 0.
  const test::CliResult whole = Analyze(Scene() + "/scene.avi", dir_.file("w.tsv"));
  EXPECT_EQ(whole.exit_code, 0) << whole.err;
  AngleFile w;
  ASSERT_TRUE(ReadAngleFile(dir_.file("w.tsv"), &w).ok());
  EXPECT_TRUE(w.complete);
  EXPECT_EQ(w.Meta("incomplete"), "");
}

TEST_F(CliTruncated, ABatchRecordsTheTruncatedVideoAsIncomplete) {
  std::vector<std::string> a = {"-q",       "analyze",      Scene() + "/scene.avi",
                                truncated_, "--output-dir", dir_.file("out")};
  for (const std::string& f : BgsubFlags()) a.push_back(f);
  const test::CliResult r = test::RunCli(a);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  std::istringstream summary(test::ReadFile(dir_.file("out/summary.tsv")));
  std::string header, whole, quarter;
  std::getline(summary, header);
  std::getline(summary, whole);
  std::getline(summary, quarter);
  EXPECT_TRUE(Contains(whole, "\tok\t")) << whole;
  EXPECT_TRUE(Contains(quarter, "quarter.avi")) << quarter;
  EXPECT_TRUE(Contains(quarter, "\tincomplete\t")) << quarter;
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(dir_.file("out/quarter.tsv"), &angles).ok());
  EXPECT_FALSE(angles.complete);
}

// complete=no and incomplete=REASON say what happened to the run, not how it was made: the
// run an incomplete file records repeats on the whole video as the run made directly does.
TEST_F(CliTruncated, TheRunAnIncompleteFileRecordsRepeats) {
  ASSERT_EQ(Analyze(truncated_, dir_.file("q.tsv")).exit_code, 1);
  ASSERT_EQ(Analyze(Scene() + "/scene.avi", dir_.file("w.tsv")).exit_code, 0);
  const test::CliResult r = test::RunCli({"-q", "analyze", Scene() + "/scene.avi", "--params-from",
                                          dir_.file("q.tsv"), "-o", dir_.file("again.tsv")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::ReadFile(dir_.file("again.tsv")), test::ReadFile(dir_.file("w.tsv")));
}

TEST_F(CliTruncated, PlanAndSendWarnOnAnIncompleteFileAndRefuseItWithStrict) {
  ASSERT_EQ(Analyze(truncated_, dir_.file("q.tsv")).exit_code, 1);
  test::CliResult r = test::RunCli({"plan", dir_.file("q.tsv"), "-o", dir_.file("q.val")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "warning")) << r.err;
  EXPECT_TRUE(Contains(r.err, "complete=no")) << r.err;
  EXPECT_TRUE(std::ifstream(dir_.file("q.val")).good());

  r = test::RunCli({"plan", dir_.file("q.tsv"), "-o", dir_.file("strict.val"), "--strict"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, "q.tsv")) << r.err;
  EXPECT_TRUE(Contains(r.err, "--strict")) << r.err;
  EXPECT_FALSE(std::ifstream(dir_.file("strict.val")).good()) << "nothing written";

  r = test::RunCli({"send", dir_.file("q.tsv"), "--dry-run"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "complete=no")) << r.err;
  r = test::RunCli({"send", dir_.file("q.tsv"), "--dry-run", "--strict"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, "--strict")) << r.err;
  EXPECT_EQ(r.out, "") << "no line printed";
}

}  // namespace
}  // namespace armmimic
