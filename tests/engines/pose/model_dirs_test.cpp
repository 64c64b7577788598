// Where the pose model is looked for: the --model folder alone when given; otherwise the
// environment's folder, the source tree (for this build folder's programs), the user's caches,
// then the installed folder beside the program and the packaged one. None of these needs the
// real model.
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "armmimic/engines/pose.h"
#include "test_util.h"

namespace armmimic {
namespace {

using test::TempDir;
using test::WriteFile;

// Sets (or unsets, with nullopt) an environment variable for the object's lifetime.
class EnvVar {
 public:
  EnvVar(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) {
      setenv(name, value->c_str(), 1);
    } else {
      unsetenv(name);
    }
  }
  ~EnvVar() {
    if (old_) {
      setenv(name_, old_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  EnvVar(const EnvVar&) = delete;
  EnvVar& operator=(const EnvVar&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(PoseModelDirsTest, TheSearchOrderStartsWithTheFlagThenTheEnvironment) {
  TempDir flag, env;
  WriteFile(env.file("movenet-lightning.json"), "{}");
  EnvVar model_dir("ARMMIMIC_MODEL_DIR", env.path());
  std::vector<std::string> tried;
  EXPECT_EQ(FindPoseModelDir("", &tried), env.path());
  EXPECT_EQ(FindPoseModelDir(flag.path(), &tried), "");  // --model is the only place looked in
  ASSERT_EQ(tried.size(), 1u);
  EXPECT_EQ(tried[0], flag.path());
}

TEST(PoseModelDirsTest, TheCachesComeBeforeTheInstalledFolderThenThePackagedOne) {
  TempDir home, xdg;
  EnvVar model_dir("ARMMIMIC_MODEL_DIR", std::nullopt);
  EnvVar home_var("HOME", home.path());
  EnvVar xdg_var("XDG_CACHE_HOME", xdg.path());
  const std::vector<std::string> dirs = PoseModelSearchPath("");
  ASSERT_GE(dirs.size(), 4u);
  // This test program runs from the build folder, so the source tree's cache comes first.
  EXPECT_EQ(dirs[0], test::SourcePath(".cache/armmimic"));
  EXPECT_EQ(dirs[1], xdg.path() + "/armmimic");
  EXPECT_EQ(dirs[2], home.path() + "/.cache/armmimic");
  EXPECT_EQ(dirs[3], InstalledPoseModelDir());
  EXPECT_EQ(dirs.back(), "/usr/share/armmimic/models");
}

TEST(PoseModelDirsTest, TheInstalledFolderIsBesideTheProgramsBinFolder) {
  // This program is BUILD/tests/engines/engines_tests, so its "prefix" is BUILD/tests.
  const std::string dir = InstalledPoseModelDir();
  ASSERT_FALSE(dir.empty());
  EXPECT_EQ(dir.front(), '/');
  const std::string tail = "/tests/share/armmimic/models";
  ASSERT_GE(dir.size(), tail.size());
  EXPECT_EQ(dir.substr(dir.size() - tail.size()), tail) << dir;
}

TEST(PoseModelDirsTest, AFolderNamedTwiceIsTriedOnce) {
  TempDir home;
  EnvVar model_dir("ARMMIMIC_MODEL_DIR", home.path() + "/.cache/armmimic");
  EnvVar home_var("HOME", home.path());
  EnvVar xdg_var("XDG_CACHE_HOME", home.path() + "/.cache");
  const std::vector<std::string> tried = PoseModelSearchPath("");
  int seen = 0;
  for (const std::string& d : tried) seen += d == home.path() + "/.cache/armmimic";
  EXPECT_EQ(seen, 1);
  EXPECT_EQ(tried.front(), home.path() + "/.cache/armmimic");
}

}  // namespace
}  // namespace armmimic
