// Settings this version removed (removed_options.h) on the command line: --param refuses them
// with what replaced them, and --params-from on an old file that records them repeats the run
// and says once which it ignored.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "small_scene.h"

namespace armmimic {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::string& Scene() { return test::SmallScene(9, 30); }

std::vector<std::string> Analyze(const std::string& out) {
  std::vector<std::string> args = {"-q", "analyze", Scene() + "/scene.avi", "-o", out};
  const std::vector<std::string> flags = test::SmallSceneBgsubFlags(Scene());
  args.insert(args.end(), flags.begin(), flags.end());
  return args;
}

TEST(CliRemovedOptions, ParamRefusesThemNamingWhatReplacedThem) {
  test::TempDir dir;
  const struct {
    const char* key;
    const char* replaced_by;
  } removed[] = {
      {"bgsub.reject_shadow", "replaced by the per-pixel model's light matching"},
      {"bgsub.background_frames", "the run's own background_frames"},
  };
  for (const auto& c : removed) {
    std::vector<std::string> args = Analyze(dir.file("a.tsv"));
    args.push_back("--param");
    args.push_back(std::string(c.key) + "=1");
    const test::CliResult r = test::RunCli(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(Contains(r.err, std::string(c.key) + " was removed")) << r.err;
    EXPECT_TRUE(Contains(r.err, c.replaced_by)) << r.err;
    EXPECT_FALSE(Contains(r.err, "is no bgsub parameter")) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.tsv")));
  }
}

TEST(CliRemovedOptions, ParamsFromAnOldFileRepeatsTheRunAndSaysOnceWhatItIgnored) {
  test::TempDir dir;
  std::vector<std::string> first = Analyze(dir.file("new.tsv"));
  for (const char* f : {"--threshold", "40", "--param", "bgsub.closing_size=3"}) {
    first.push_back(f);
  }
  test::CliResult r = test::RunCli(first);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string made = test::ReadFile(dir.file("new.tsv"));
  EXPECT_FALSE(Contains(made, "bgsub.reject_shadow"));
  // The same run as a file written before the removal records it: its header also carries the
  // removed settings, one of them changed from its old default.
  std::istringstream in(made);
  std::string old, line;
  while (std::getline(in, line)) {
    if (line.rfind("# engine=", 0) == 0) {
      line += " bgsub.compensate_drift=true bgsub.reject_shadow=false bgsub.background_frames=45";
    }
    old += line + "\n";
  }
  test::WriteFile(dir.file("old.tsv"), old);
  AngleFile parsed;
  ASSERT_TRUE(ReadAngleFile(dir.file("old.tsv"), &parsed).ok());
  ASSERT_EQ(parsed.Meta("bgsub.reject_shadow"), "false");

  r = test::RunCli({"-q", "analyze", Scene() + "/scene.avi", "--params-from", dir.file("old.tsv"),
                    "-o", dir.file("again.tsv")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::ReadFile(dir.file("again.tsv")), made);
  // One line on stderr, naming each ignored key, why, and what replaced it.
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(Contains(r.err, dir.file("old.tsv") + ": ignored 3 recorded settings")) << r.err;
  EXPECT_TRUE(Contains(r.err, "removed: the default path no longer reads them")) << r.err;
  for (const char* says :
       {"bgsub.compensate_drift: replaced by the per-pixel model's light",
        "bgsub.reject_shadow: replaced by", "bgsub.background_frames: never read"}) {
    EXPECT_TRUE(Contains(r.err, says)) << says << ": " << r.err;
  }
}

}  // namespace
}  // namespace armmimic
