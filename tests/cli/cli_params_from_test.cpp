// analyze --params-from OLD.tsv through the real program: a run made in one folder with relative
// paths repeats from another folder, and after its folder moved; a header that names a key
// twice, or a key no version writes, is refused naming OLD.tsv and the line; CR-only line ends
// read as well as LF; a message never prints more than one line of the file.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "small_scene.h"

namespace armmimic {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::string& Scene() { return test::SmallScene(9, 30); }

// Runs armmimic-cli with `folder` as its working folder (the child inherits it).
test::CliResult RunCliIn(const std::string& folder, const std::vector<std::string>& args) {
  const fs::path before = fs::current_path();
  fs::current_path(folder);
  test::CliResult r = test::RunCli(args);
  fs::current_path(before);
  return r;
}

// The header line of `text` with `extra` appended.
std::string WithHeaderWords(const std::string& text, const std::string& extra) {
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line)) {
    if (line.rfind("# engine=", 0) == 0) line += extra;
    out += line + "\n";
  }
  return out;
}

class CliParamsFromFolders : public ::testing::Test {
 protected:
  // Folder x holds the scene; the first run is made inside it with relative paths only.
  void SetUp() override {
    fs::create_directory(x_);
    fs::create_directory(elsewhere_);
    for (const char* f : {"scene.avi", "background.png", "armlength.png"}) {
      fs::copy_file(Scene() + "/" + f, x_ + "/" + f);
    }
    const test::CliResult r =
        RunCliIn(x_, {"-q", "analyze", "scene.avi", "-o", "out.tsv", "--engine", "bgsub",
                      "--background", "background.png", "--arm-length", "armlength.png", "--start",
                      "10", "--standstill-frames", "10", "--threshold", "40"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_FALSE(test::DataRows(x_ + "/out.tsv").empty());
  }
  test::TempDir dir_;
  std::string x_ = dir_.file("x");
  std::string elsewhere_ = dir_.file("elsewhere");
};

TEST_F(CliParamsFromFolders, TheHeaderRecordsRelativePathsAsTypedAndAbsolute) {
  AngleFile old;
  ASSERT_TRUE(ReadAngleFile(x_ + "/out.tsv", &old).ok());
  EXPECT_EQ(old.Meta("background"), "background.png");
  EXPECT_EQ(old.Meta("background_abs"), fs::canonical(x_).string() + "/background.png");
  EXPECT_EQ(old.Meta("arm_length"), "armlength.png");
  EXPECT_EQ(old.Meta("arm_length_abs"), fs::canonical(x_).string() + "/armlength.png");
  // Each key once.
  std::vector<std::string> keys;
  for (const auto& [k, v] : old.meta) keys.push_back(k);
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());
}

TEST_F(CliParamsFromFolders, RepeatsFromAnotherFolderWithIdenticalRows) {
  const test::CliResult r = RunCliIn(
      elsewhere_,
      {"-q", "analyze", x_ + "/scene.avi", "--params-from", x_ + "/out.tsv", "-o", "again.tsv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::DataRows(elsewhere_ + "/again.tsv"), test::DataRows(x_ + "/out.tsv"));
  // Run again in the first folder, the header is the first run's, word for word.
  const test::CliResult same =
      RunCliIn(x_, {"-q", "analyze", "scene.avi", "--params-from", "out.tsv", "-o", "same.tsv"});
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(test::ReadFile(x_ + "/same.tsv"), test::ReadFile(x_ + "/out.tsv"));
}

TEST_F(CliParamsFromFolders, AMovedFolderIsSearchedBesideTheOldFile) {
  const std::string moved = dir_.file("moved");
  fs::rename(x_, moved);  // the recorded absolute paths lead nowhere now
  test::CliResult r = RunCliIn(elsewhere_, {"-q", "analyze", moved + "/scene.avi", "--params-from",
                                            moved + "/out.tsv", "-o", "again.tsv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::DataRows(elsewhere_ + "/again.tsv"), test::DataRows(moved + "/out.tsv"));

  // Found nowhere: the message names the old file, the recorded key and every path tried, and
  // no flag the user never typed.
  fs::remove(moved + "/armlength.png");
  r = RunCliIn(elsewhere_, {"analyze", moved + "/scene.avi", "--params-from", moved + "/out.tsv",
                            "-o", "none.tsv"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const std::string real_elsewhere = fs::canonical(elsewhere_).string();
  for (const std::string& part :
       {"--params-from " + moved + "/out.tsv: the recorded arm_length=armlength.png",
        fs::canonical(dir_.path()).string() + "/x/armlength.png", moved + "/armlength.png",
        real_elsewhere + "/armlength.png"}) {
    EXPECT_TRUE(Contains(r.err, part)) << part << "\n" << r.err;
  }
  EXPECT_FALSE(Contains(r.err, "--arm-length")) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(elsewhere_ + "/none.tsv"));

  // A flag given in its place: the recorded path is not needed.
  fs::copy_file(Scene() + "/armlength.png", elsewhere_ + "/arm.png");
  r = RunCliIn(elsewhere_, {"-q", "analyze", moved + "/scene.avi", "--params-from",
                            moved + "/out.tsv", "-o", "given.tsv", "--arm-length", "arm.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::DataRows(elsewhere_ + "/given.tsv"), test::DataRows(moved + "/out.tsv"));
}

TEST_F(CliParamsFromFolders, CrOnlyAndCrlfLineEndsRepeatTheRun) {
  const std::string text = test::ReadFile(x_ + "/out.tsv");
  for (const std::string end : {"\r", "\r\n"}) {
    std::string converted;
    for (char c : text) converted += c == '\n' ? end : std::string(1, c);
    test::WriteFile(dir_.file("converted.tsv"), converted);
    const test::CliResult r =
        test::RunCli({"-q", "analyze", x_ + "/scene.avi", "--params-from",
                      dir_.file("converted.tsv"), "-o", dir_.file("again.tsv")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(test::DataRows(dir_.file("again.tsv")), test::DataRows(x_ + "/out.tsv"));
  }
}

TEST_F(CliParamsFromFolders, AnIncompleteRunRepeatsAsWell) {
  // complete=no and incomplete=REASON say what happened to the run, not how it was made.
  test::WriteFile(dir_.file("cut.tsv"),
                  WithHeaderWords(test::ReadFile(x_ + "/out.tsv"),
                                  " complete=no incomplete=the%20video%20ended%20early"));
  const test::CliResult r = test::RunCli({"-q", "analyze", x_ + "/scene.avi", "--params-from",
                                          dir_.file("cut.tsv"), "-o", dir_.file("again.tsv")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::DataRows(dir_.file("again.tsv")), test::DataRows(x_ + "/out.tsv"));
}

TEST_F(CliParamsFromFolders, DuplicateAndUnknownKeysAreRefusedNamingTheLine) {
  const std::string text = test::ReadFile(x_ + "/out.tsv");
  const struct {
    const char* extra;
    const char* says;
  } cases[] = {
      {" start=200", ":2: the key start appears twice (start=10 and start=200)"},
      {" bgsub.threshold=50", ":2: the key bgsub.threshold appears twice"},
      {" colour=red", ":2: unknown key colour=red"},
      {" lk.max_corners=100",
       ":2: unknown key lk.max_corners=100 (not a setting of the recorded "
       "engine bgsub)"},
      {" bgsub.nope=1", ":2: unknown key bgsub.nope=1"},
  };
  for (const auto& c : cases) {
    test::WriteFile(dir_.file("bad.tsv"), WithHeaderWords(text, c.extra));
    const test::CliResult r = test::RunCli({"analyze", x_ + "/scene.avi", "--params-from",
                                            dir_.file("bad.tsv"), "-o", dir_.file("no.tsv")});
    EXPECT_EQ(r.exit_code, 2) << c.extra << "\n" << r.err;
    EXPECT_TRUE(Contains(r.err, "--params-from " + dir_.file("bad.tsv") + c.says))
        << c.extra << "\n"
        << r.err;
    EXPECT_FALSE(fs::exists(dir_.file("no.tsv")));
  }
  // A setting this version removed is no unknown key: skipped and named once (as before).
  test::WriteFile(dir_.file("old.tsv"), WithHeaderWords(text, " bgsub.reject_shadow=false"));
  const test::CliResult r = test::RunCli({"analyze", x_ + "/scene.avi", "--params-from",
                                          dir_.file("old.tsv"), "-o", dir_.file("old-again.tsv")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "ignored 1 recorded setting")) << r.err;
}

// The marker engine describes what it measured on the reference (N_px, radius_px, ...) in the
// header: known keys, skipped when the run is repeated.
TEST(CliParamsFrom, MarkerRunsRepeatInBothModes) {
  test::TempDir dir;
  const std::string scene = dir.file("scene");
  ASSERT_EQ(test::RunCli({"-q", "synth", "marker", scene, "--seed", "4", "--views", "6"}).exit_code,
            0);
  for (const std::vector<std::string>& mode :
       {std::vector<std::string>{}, std::vector<std::string>{"--thesis"}}) {
    std::vector<std::string> first = {"-q",     "analyze",           scene + "/views",
                                      "-o",     dir.file("old.tsv"), "--engine",
                                      "marker", "--reference",       scene + "/reference.png"};
    first.insert(first.end(), mode.begin(), mode.end());
    test::CliResult r = test::RunCli(first);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = test::RunCli({"-q", "analyze", scene + "/views", "--params-from", dir.file("old.tsv"), "-o",
                      dir.file("new.tsv")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(test::ReadFile(dir.file("new.tsv")), test::ReadFile(dir.file("old.tsv")));
  }
}

#ifdef ARMMIMIC_HAVE_POSE_MODEL
// A pose run given --model names the network once (model=) and the folder once (model_dir=),
// and repeats from another folder.
TEST(CliParamsFrom, APoseRunWithAModelFolderRepeats) {
  test::TempDir dir;
  ASSERT_EQ(
      test::RunCli({"-q", "synth", "arm", dir.path(), "--seed", "2", "--frames", "12"}).exit_code,
      0);
  fs::create_directory(dir.file("elsewhere"));
  const std::string model = test::SourcePath(".cache/armmimic");
  test::CliResult r = test::RunCli({"-q", "analyze", dir.file("scene.avi"), "-o",
                                    dir.file("old.tsv"), "--engine", "pose", "--model", model});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile old;
  ASSERT_TRUE(ReadAngleFile(dir.file("old.tsv"), &old).ok());
  int models = 0;
  for (const auto& [k, v] : old.meta) models += k == "model" ? 1 : 0;
  EXPECT_EQ(models, 1);
  EXPECT_EQ(old.Meta("model_dir"), model);
  r = RunCliIn(dir.file("elsewhere"), {"-q", "analyze", dir.file("scene.avi"), "--params-from",
                                       dir.file("old.tsv"), "-o", "new.tsv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::ReadFile(dir.file("elsewhere/new.tsv")), test::ReadFile(dir.file("old.tsv")));
}
#endif

TEST(CliParamsFrom, AHugeSingleLineFileGivesAOneLineMessage) {
  test::TempDir dir;
  const std::string video = Scene() + "/scene.avi";
  const struct {
    std::string text;
    std::string says;
  } cases[] = {
      // Longer than any line an angle file may hold, with no line end at all.
      {std::string(3'000'000, 'x'), ":1: line is longer than"},
      // A whole file's worth on one line, short enough to be read: only its start is quoted.
      {"# armmimic angles v2 " + std::string(40'000, 'y'), ":1: unsupported angle file version"},
      {std::string(kAngleFileMagic) + "\n# engine=bgsub\n" + std::string(40'000, 'z') + "\tb\n",
       ":3: bad column header: column 1 is \"zzz"},
  };
  for (const auto& c : cases) {
    test::WriteFile(dir.file("huge.tsv"), c.text);
    const test::CliResult r = test::RunCli(
        {"analyze", video, "--params-from", dir.file("huge.tsv"), "-o", dir.file("x.tsv")});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(Contains(r.err, dir.file("huge.tsv") + c.says)) << r.err.substr(0, 400);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err.substr(0, 400);
    EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 400);
    EXPECT_FALSE(fs::exists(dir.file("x.tsv")));
  }
}

}  // namespace
}  // namespace armmimic
