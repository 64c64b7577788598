// An installed armmimic-cli finds the pose model without flags. The program is put into a folder
// laid out as an install (PREFIX/bin/armmimic-cli, the model in PREFIX/share/armmimic/models/, as
// the armmimic-models package lays it out under /usr) and run with an empty home: with no model
// anywhere it names every folder it tried and what provides the model; with the model installed
// it runs the pose engine on a generated scene. The run with the model is compiled in only when
// the model is in the source tree (tests/cli/CMakeLists.txt).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "test_util.h"

namespace armmimic {
namespace {

namespace fs = std::filesystem;

class CliInstalled : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir();
    const test::CliResult r =
        test::RunCli({"synth", "arm", dir_->file("scene"), "--seed", "2", "--frames", "12", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    fs::create_directories(dir_->file("home"));
    test::LinkOrCopy(ARMMIMIC_CLI_PATH, Program());
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::string Program() { return dir_->file("prefix/bin/armmimic-cli"); }
  // The installed models folder as the program derives it (from its own resolved path).
  static std::string ModelsDir() {
    return fs::canonical(dir_->file("prefix")).string() + "/share/armmimic/models";
  }
  // `analyze --engine pose` by the installed program, with no model folder in the environment
  // and an empty home, from the scene's frame 105 on.
  static test::CliResult AnalyzeInstalled(const std::string& out) {
    std::vector<std::string> env =
        test::EnvironmentWithout({"ARMMIMIC_MODEL_DIR", "HOME", "XDG_CACHE_HOME"});
    env.push_back("HOME=" + dir_->file("home"));
    return test::RunProgram({Program(), "analyze", dir_->file("scene/scene.avi"), "-o", out,
                             "--engine", "pose", "--side", "left", "--start", "105", "-q"},
                            env);
  }
  static test::TempDir* dir_;
};
test::TempDir* CliInstalled::dir_ = nullptr;

TEST_F(CliInstalled, WithNoModelAnywhereTheMessageNamesTheFoldersTriedAndThePackage) {
  if (fs::exists("/usr/share/armmimic/models/movenet-lightning.json")) {
    GTEST_SKIP() << "the armmimic-models package is installed on this machine, so a model is "
                    "always found";
  }
  fs::remove_all(dir_->file("prefix/share"));
  const std::string out = dir_->file("none.tsv");
  const test::CliResult r = AnalyzeInstalled(out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err,
            "armmimic-cli analyze: --model: the pose model (movenet-lightning.json) is in "
            "none of " +
                dir_->file("home") + "/.cache/armmimic, " + ModelsDir() +
                ", /usr/share/armmimic/models; install the package armmimic-models, or "
                "fetch the model with scripts/deps.sh --with-model in armmimic's source "
                "tree, or name the folder holding it\n");
  EXPECT_FALSE(fs::exists(out));
}

#ifdef ARMMIMIC_HAVE_POSE_MODEL
TEST_F(CliInstalled, TheInstalledProgramFindsTheModelBesideItWithoutFlags) {
  fs::create_directories(ModelsDir());
  for (const char* name : {"movenet-lightning.json", "movenet-lightning.bin"}) {
    fs::remove(ModelsDir() + "/" + name);
    fs::create_symlink(test::SourcePath(std::string(".cache/armmimic/") + name),
                       ModelsDir() + "/" + name);
  }
  const std::string out = dir_->file("installed.tsv");
  const test::CliResult r = AnalyzeInstalled(out);
  fs::remove_all(dir_->file("prefix/share"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(out, &f).ok());
  EXPECT_EQ(f.Meta("engine"), "pose");
  ASSERT_EQ(f.rows.size(), 12u);
  for (const AngleRow& row : f.rows) EXPECT_TRUE(row.ok()) << row.frame;
  // The same model, so the same angles as the build folder's program with the source tree's.
  const std::string ref = dir_->file("build-tree.tsv");
  const test::CliResult b =
      test::RunCli({"analyze", dir_->file("scene/scene.avi"), "-o", ref, "--engine", "pose",
                    "--side", "left", "--start", "105", "-q"});
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(test::ReadFile(out), test::ReadFile(ref));
}
#endif

}  // namespace
}  // namespace armmimic
