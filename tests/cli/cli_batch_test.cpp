// analyze --params-from (a run repeated from an angle file's header) and batches (--output-dir,
// --list): one angle file per video, a summary table, a failing video that stops nothing.
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/text.h"
#include "small_scene.h"

namespace armmimic {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::string& Scene() { return test::SmallScene(9, 30); }

std::vector<std::string> BgsubFlags() { return test::SmallSceneBgsubFlags(Scene()); }

TEST(CliParamsFrom, RepeatsTheRunRowForRowAndFlagsOverrideIt) {
  test::TempDir dir;
  const std::string video = Scene() + "/scene.avi";
  std::vector<std::string> first = {"-q", "analyze", video, "-o", dir.file("old.tsv")};
  for (const std::string& f : BgsubFlags()) first.push_back(f);
  for (const char* f :
       {"--threshold", "40", "--param", "bgsub.closing_size=3", "--param", "bgsub.confirm_frames=4",
        "--param", "bgsub.min_support=0.45", "--param", "bgsub.upper_arm_fraction=0.55"}) {
    first.push_back(f);
  }
  test::CliResult r = test::RunCli(first);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The header names every setting under its --param name.
  AngleFile old;
  ASSERT_TRUE(ReadAngleFile(dir.file("old.tsv"), &old).ok());
  EXPECT_EQ(old.Meta("bgsub.threshold"), "40");
  EXPECT_EQ(old.Meta("bgsub.closing_size"), "3");
  EXPECT_EQ(old.Meta("bgsub.straight_ratio"), "0.3");  // unchanged ones too
  EXPECT_EQ(old.Meta("threshold"), "40");              // and the legacy names stay
  EXPECT_EQ(old.Meta("arm_length"), Scene() + "/armlength.png");

  r = test::RunCli(
      {"-q", "analyze", video, "--params-from", dir.file("old.tsv"), "-o", dir.file("new.tsv")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_FALSE(test::DataRows(dir.file("old.tsv")).empty());
  EXPECT_EQ(test::DataRows(dir.file("new.tsv")), test::DataRows(dir.file("old.tsv")));
  EXPECT_EQ(test::ReadFile(dir.file("new.tsv")), test::ReadFile(dir.file("old.tsv")));

  // The defaults give other rows, so the replay did carry the settings.
  std::vector<std::string> plain = {"-q", "analyze", video, "-o", dir.file("plain.tsv")};
  for (const std::string& f : BgsubFlags()) plain.push_back(f);
  ASSERT_EQ(test::RunCli(plain).exit_code, 0);
  EXPECT_NE(test::DataRows(dir.file("plain.tsv")), test::DataRows(dir.file("old.tsv")));

  // A flag given as well wins; the other recorded settings stay.
  r = test::RunCli({"-q", "analyze", video, "--params-from", dir.file("old.tsv"), "-o",
                    dir.file("over.tsv"), "--threshold", "50", "--param", "bgsub.closing_size=5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile over;
  ASSERT_TRUE(ReadAngleFile(dir.file("over.tsv"), &over).ok());
  EXPECT_EQ(over.Meta("bgsub.threshold"), "50");
  EXPECT_EQ(over.Meta("bgsub.closing_size"), "5");
  EXPECT_EQ(over.Meta("bgsub.confirm_frames"), "4");
  EXPECT_EQ(over.Meta("bgsub.min_support"), "0.45");
  EXPECT_EQ(over.Meta("bgsub.upper_arm_fraction"), "0.55");
}

TEST(CliParamsFrom, RepeatsAnLkRunFromClickedJoints) {
  test::TempDir dir;
  const std::string video = Scene() + "/scene.avi";
  test::CliResult r = test::RunCli({"-q", "analyze", video, "-o", dir.file("old.tsv"), "--engine",
                                    "lk", "--shoulder", "101.5,40", "--start", "20", "--roi",
                                    "40,0,120,120", "--param", "lk.max_corners=150"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = test::RunCli(
      {"-q", "analyze", video, "--params-from", dir.file("old.tsv"), "-o", dir.file("new.tsv")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::ReadFile(dir.file("new.tsv")), test::ReadFile(dir.file("old.tsv")));
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(dir.file("new.tsv"), &f).ok());
  EXPECT_EQ(f.Meta("shoulder"), "101.5,40");
  EXPECT_EQ(f.Meta("roi"), "40,0,120,120");
  EXPECT_EQ(f.Meta("start"), "20");
}

TEST(CliParamsFrom, BadRecordsAreNamed) {
  test::TempDir dir;
  const std::string video = Scene() + "/scene.avi";
  test::WriteFile(dir.file("bad.tsv"), std::string(kAngleFileMagic) +
                                           "\n# engine=bgsub bgsub.threshold=999\n" +
                                           "frame\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\t"
                                           "bend_deg\tupper_cx\tupper_cy\tfore_cx\tfore_cy\n");
  test::CliResult r = test::RunCli(
      {"analyze", video, "--params-from", dir.file("bad.tsv"), "-o", dir.file("x.tsv")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(Contains(r.err, "--params-from " + dir.file("bad.tsv") + ": bgsub.threshold '999'"))
      << r.err;
  r = test::RunCli(
      {"analyze", video, "--params-from", dir.file("none.tsv"), "-o", dir.file("x.tsv")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(Contains(r.err, dir.file("none.tsv"))) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.tsv")));
}

// A list saved with CR alone as its line end (old Mac editors) names one video per line.
TEST(CliBatch, AListWithCrAloneAsItsLineEndNamesOneVideoPerLine) {
  test::TempDir dir;
  test::WriteFile(dir.file("a.avi"), "not a video");
  test::WriteFile(dir.file("b.avi"), "not a video either");
  test::WriteFile(dir.file("list.txt"),
                  dir.file("a.avi") + "\r# a comment\r" + dir.file("b.avi") + "\r");
  std::vector<std::string> args = {"analyze", "--list", dir.file("list.txt"), "--output-dir",
                                   dir.file("out")};
  for (const std::string& f : BgsubFlags()) args.push_back(f);
  const test::CliResult r = test::RunCli(args);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, "[1/2] " + dir.file("a.avi") + ":")) << r.err;
  EXPECT_TRUE(Contains(r.err, "[2/2] " + dir.file("b.avi") + ":")) << r.err;
}

TEST(CliBatch, OneFilePerVideoASummaryAndAFailureStopsNothing) {
  test::TempDir dir;
  const std::string video = Scene() + "/scene.avi";
  std::filesystem::create_directory(dir.file("b"));
  test::WriteFile(dir.file("b/walk.avi"), test::ReadFile(video));
  test::WriteFile(dir.file("broken.avi"), "not a video");
  // A list as a spreadsheet saves it: a byte order mark, CRLF, a comment and a blank line.
  test::WriteFile(dir.file("list.txt"), "\xEF\xBB\xBF# today's takes\r\n" + video + "\r\n\r\n" +
                                            dir.file("broken.avi") + "\r\n" +
                                            dir.file("b/walk.avi") + "\r\n");
  std::vector<std::string> args = {"analyze", "--list", dir.file("list.txt"), "--output-dir",
                                   dir.file("out")};
  for (const std::string& f : BgsubFlags()) args.push_back(f);
  const test::CliResult r = test::RunCli(args);
  EXPECT_EQ(r.exit_code, 1) << r.err;  // one video failed
  // Progress per video, and the failure names the file.
  EXPECT_TRUE(Contains(r.err, "[1/3] " + video)) << r.err;
  EXPECT_TRUE(Contains(r.err, "[3/3] " + dir.file("b/walk.avi"))) << r.err;
  EXPECT_TRUE(Contains(r.err, "[2/3] " + dir.file("broken.avi") + ":")) << r.err;
  EXPECT_TRUE(Contains(r.err, "2 of 3 videos analysed, 1 failed")) << r.err;

  // Each angle file is what a single run gives.
  std::vector<std::string> single = {"-q", "analyze", video, "-o", dir.file("single.tsv")};
  for (const std::string& f : BgsubFlags()) single.push_back(f);
  ASSERT_EQ(test::RunCli(single).exit_code, 0);
  EXPECT_EQ(test::ReadFile(dir.file("out/scene.tsv")), test::ReadFile(dir.file("single.tsv")));
  EXPECT_EQ(test::DataRows(dir.file("out/walk.tsv")), test::DataRows(dir.file("single.tsv")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("out/broken.tsv")));

  std::istringstream summary(test::ReadFile(dir.file("out/summary.tsv")));
  std::vector<std::string> lines;
  for (std::string l; std::getline(summary, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "video\tangles\tframes\tok\tlost\tcoverage\tseconds\tstatus\terror");
  AngleFile a;
  ASSERT_TRUE(ReadAngleFile(dir.file("out/scene.tsv"), &a).ok());
  int ok = 0;
  for (const AngleRow& row : a.rows) ok += row.ok() ? 1 : 0;
  const std::string counts = std::to_string(a.rows.size()) + "\t" + std::to_string(ok) + "\t" +
                             std::to_string(a.rows.size() - ok) + "\t";
  EXPECT_EQ(lines[1].rfind(video + "\t" + dir.file("out/scene.tsv") + "\t" + counts, 0), 0u)
      << lines[1];
  EXPECT_TRUE(Contains(lines[1], "\tok\t")) << lines[1];
  EXPECT_TRUE(Contains(lines[2], "\tfailed\t" + dir.file("broken.avi"))) << lines[2];
  EXPECT_TRUE(Contains(lines[3], "\tok\t")) << lines[3];
}

// Names are escaped in the summary (\t, \n, \r, \\), never rewritten: a script reading it by
// TAB and line gets every video and angle file back as it was. A failed video wrote no file,
// and its angles column says so by being empty.
TEST(CliBatch, TheSummaryEscapesNamesAndListsNoFileForAFailedVideo) {
  test::TempDir dir;
  const std::string bytes = test::ReadFile(Scene() + "/scene.avi");
  const std::vector<std::string> names = {"my take \xC3\xBC.avi", "tab\there.avi", "new\nline.avi",
                                          "back\\slash.avi", "bro ken.avi"};
  std::vector<std::string> args = {"-q", "analyze"};
  for (const std::string& n : names) {
    test::WriteFile(dir.file(n), n == "bro ken.avi" ? std::string("not a video") : bytes);
    args.push_back(dir.file(n));
  }
  for (const std::string& f : {std::string("--output-dir"), dir.file("out")}) args.push_back(f);
  for (const std::string& f : BgsubFlags()) args.push_back(f);
  const test::CliResult r = test::RunCli(args);
  EXPECT_EQ(r.exit_code, 1) << r.err;  // one video failed

  std::istringstream summary(test::ReadFile(dir.file("out/summary.tsv")));
  std::vector<std::string> lines;
  for (std::string l; std::getline(summary, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), names.size() + 1) << "one line per video, whatever its name holds";
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::vector<std::string> f = SplitTabs(lines[i + 1]);
    ASSERT_EQ(f.size(), 9u) << lines[i + 1];
    EXPECT_EQ(UnescapeTsvField(f[0]), dir.file(names[i]));
    if (names[i] == "bro ken.avi") {
      EXPECT_EQ(f[7], "failed");
      EXPECT_EQ(f[1], "") << "no angle file was written";
      EXPECT_FALSE(std::filesystem::exists(dir.file("out/bro ken.tsv")));
      continue;
    }
    EXPECT_EQ(f[7], "ok") << lines[i + 1];
    const std::string stem = names[i].substr(0, names[i].size() - 4);
    EXPECT_EQ(UnescapeTsvField(f[1]), dir.file("out/" + stem + ".tsv"));
    EXPECT_EQ(test::DataRows(UnescapeTsvField(f[1])),
              test::DataRows(dir.file("out/my take \xC3\xBC.tsv")));
  }
  EXPECT_EQ(SplitTabs(lines[1])[0], dir.file("my take \xC3\xBC.avi"))
      << "spaces and UTF-8 as they are";
  EXPECT_EQ(SplitTabs(lines[2])[0], dir.file("tab\\there.avi"));
  EXPECT_EQ(SplitTabs(lines[4])[0], dir.file("back\\\\slash.avi"));
}

TEST(CliBatch, AllGoodExitsZeroAndClashesAreUsageErrors) {
  test::TempDir dir;
  const std::string video = Scene() + "/scene.avi";
  test::WriteFile(dir.file("two.avi"), test::ReadFile(video));
  std::vector<std::string> args = {
      "-q",           "analyze",       video,       dir.file("two.avi"),
      "--output-dir", dir.file("out"), "--summary", dir.file("s.tsv")};
  for (const std::string& f : BgsubFlags()) args.push_back(f);
  test::CliResult r = test::RunCli(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("out/two.tsv")));
  EXPECT_TRUE(Contains(test::ReadFile(dir.file("s.tsv")), "\tok\t"));
  EXPECT_FALSE(std::filesystem::exists(dir.file("out/summary.tsv")));

  // Two videos with one name would write one file: refused before anything runs.
  std::filesystem::create_directory(dir.file("other"));
  test::WriteFile(dir.file("other/two.avi"), test::ReadFile(video));
  args = {"analyze", dir.file("two.avi"), dir.file("other/two.avi"), "--output-dir",
          dir.file("out2")};
  for (const std::string& f : BgsubFlags()) args.push_back(f);
  r = test::RunCli(args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, dir.file("out2/two.tsv"))) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out2")));
  for (const auto& [extra, expect] :
       {std::pair<std::vector<std::string>, std::string>{{"-o", dir.file("x.tsv")},
                                                         "-o and --output-dir"},
        {{"--list", dir.file("list.txt")}, "either as INPUT or in --list"}}) {
    std::vector<std::string> a = {"analyze",  video, "--output-dir", dir.file("out3"),
                                  "--engine", "lk",  "--shoulder",   "100,40"};
    a.insert(a.end(), extra.begin(), extra.end());
    r = test::RunCli(a);
    EXPECT_EQ(r.exit_code, 2) << expect;
    EXPECT_TRUE(Contains(r.err, expect)) << r.err;
  }
  r = test::RunCli({"analyze", "--list", dir.file("list.txt"), "-o", dir.file("x.tsv"), "--engine",
                    "lk", "--shoulder", "100,40"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "--list needs --output-dir")) << r.err;
}

}  // namespace
}  // namespace armmimic
