// No command writes over one of its own inputs: analyze, background, plan and score --plot
// refuse (exit 2) before reading anything, naming both files, whatever the spelling of the path
// (another relative form, a symlink, a hard link); the input is left byte for byte.
#include <unistd.h>

#include <gtest/gtest.h>

#include "small_scene.h"

namespace armmimic {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::string& Scene() { return test::SmallScene(5, 10); }

// Runs `args`, expects the refusal naming `out` and `in`, and `victim` unchanged.
void ExpectRefused(const std::vector<std::string>& args, const std::string& out,
                   const std::string& in, const std::string& victim) {
  const std::string before = test::ReadFile(victim);
  ASSERT_FALSE(before.empty()) << victim;
  const test::CliResult r = test::RunCli(args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(Contains(r.err, out + " is the same file as " + in)) << r.err;
  EXPECT_EQ(test::ReadFile(victim), before) << "the input was changed";
}

TEST(CliSameFile, AnalyzeNeverWritesOverItsVideoOrImages) {
  test::TempDir dir;
  const std::string video = dir.file("v.avi");
  test::WriteFile(video, test::ReadFile(Scene() + "/scene.avi"));
  const std::string arm = dir.file("arm.png");
  test::WriteFile(arm, test::ReadFile(Scene() + "/armlength.png"));
  const std::vector<std::string> base = {
      "analyze",      video, "--engine", "bgsub", "--background-frames", "10",
      "--arm-length", arm,   "--start",  "10",    "--standstill-frames", "10"};
  auto with_output = [&](const std::string& out) {
    std::vector<std::string> a = base;
    a.insert(a.end(), {"-o", out});
    return a;
  };
  ExpectRefused(with_output(video), "-o " + video, "INPUT " + video, video);
  ExpectRefused(with_output(dir.path() + "/./v.avi"), "-o " + dir.path() + "/./v.avi",
                "INPUT " + video, video);
  ExpectRefused(with_output(arm), "-o " + arm, "--arm-length " + arm, arm);
  ASSERT_EQ(symlink(video.c_str(), dir.file("link.tsv").c_str()), 0);
  ExpectRefused(with_output(dir.file("link.tsv")), "-o " + dir.file("link.tsv"), "INPUT " + video,
                video);
  ASSERT_EQ(link(video.c_str(), dir.file("hard.tsv").c_str()), 0);
  ExpectRefused(with_output(dir.file("hard.tsv")), "-o " + dir.file("hard.tsv"), "INPUT " + video,
                video);
  // The run an earlier file records is an input as well.
  const test::CliResult ok = test::RunCli(with_output(dir.file("a.tsv")));
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  ExpectRefused({"analyze", video, "--params-from", dir.file("a.tsv"), "-o", dir.file("a.tsv")},
                "-o " + dir.file("a.tsv"), "--params-from " + dir.file("a.tsv"), dir.file("a.tsv"));
  // ... and so are the images it names (here the arm-length image, through the header).
  ExpectRefused({"analyze", video, "--params-from", dir.file("a.tsv"), "-o", arm}, "-o " + arm,
                "--arm-length " + arm, arm);
  // A batch's summary and angle files too.
  ExpectRefused({"analyze", video, "--output-dir", dir.path(), "--summary", video, "--engine", "lk",
                 "--shoulder", "100,40"},
                "--summary " + video, "INPUT " + video, video);
  test::WriteFile(dir.file("list.txt"), video + "\n");
  ExpectRefused({"analyze", "--list", dir.file("list.txt"), "--output-dir", dir.path(), "--summary",
                 dir.file("list.txt"), "--engine", "lk", "--shoulder", "100,40"},
                "--summary " + dir.file("list.txt"), "--list " + dir.file("list.txt"),
                dir.file("list.txt"));
}

TEST(CliSameFile, BackgroundPlanAndScoreRefuseToo) {
  test::TempDir dir;
  const std::string video = dir.file("v.avi");
  test::WriteFile(video, test::ReadFile(Scene() + "/scene.avi"));
  // An image name that is a link to the video.
  ASSERT_EQ(symlink(video.c_str(), dir.file("v.png").c_str()), 0);
  ExpectRefused({"background", video, "-o", dir.file("v.png")}, "-o " + dir.file("v.png"),
                "VIDEO " + video, video);

  const std::string angles = dir.file("a.tsv");
  const test::CliResult r = test::RunCli({"-q", "analyze", video, "-o", angles, "--engine", "lk",
                                          "--shoulder", "100,40", "--start", "20"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(chdir(dir.path().c_str()), 0);
  // The reported case: the measurement replaced by the VAL program. Also as ./a.tsv.
  ExpectRefused({"plan", "a.tsv", "-o", "a.tsv"}, "-o a.tsv", "ANGLES.tsv a.tsv", angles);
  ExpectRefused({"plan", "a.tsv", "-o", "./a.tsv"}, "-o ./a.tsv", "ANGLES.tsv a.tsv", angles);
  test::WriteFile(dir.file("my.profile"), "mode = stream\n");
  ExpectRefused({"plan", "a.tsv", "-o", "my.profile", "--profile", "my.profile"}, "-o my.profile",
                "--profile my.profile", dir.file("my.profile"));
  const std::string truth = Scene() + "/truth.tsv";
  // (An angle file may have any name, even an image's.)
  test::WriteFile(dir.file("angles.png"), test::ReadFile(angles));
  ExpectRefused({"score", truth, "angles.png", "--plot", "angles.png"}, "--plot angles.png",
                "ANGLES.tsv angles.png", dir.file("angles.png"));
  // Another output is fine.
  EXPECT_EQ(test::RunCli({"-q", "plan", "a.tsv", "-o", "a.val"}).exit_code, 0);
  // send's one output, the journal beside the program, may not be its profile.
  test::WriteFile(dir.file("a.val.journal"), "mode = stream\n");
  ExpectRefused({"send", "a.val", "--port", "/dev/null", "--profile", "a.val.journal"},
                "the journal a.val.journal", "--profile a.val.journal", dir.file("a.val.journal"));
}

}  // namespace
}  // namespace armmimic
