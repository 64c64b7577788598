// The test suite's temporary folders (tests/common): each test process has a TMPDIR of its own,
// a TempDir goes with everything in it, and a SharedTempDir is made once and removed after the
// last test; whatever is still in TMPDIR then fails the run (test_main.cpp).
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "test_util.h"

namespace armmimic {
namespace {

namespace fs = std::filesystem;

TEST(TestTempFolders, EveryTestProcessWritesUnderItsOwnTmpdir) {
  const char* tmpdir = std::getenv("TMPDIR");
  ASSERT_NE(tmpdir, nullptr);
  EXPECT_EQ(fs::path(tmpdir).filename().string().rfind("armmimic-tests-", 0), 0u) << tmpdir;
  test::TempDir dir;
  EXPECT_EQ(fs::path(dir.path()).parent_path(), fs::path(tmpdir));
  // World-writable with the sticky bit, as /tmp is: the tests that run the program as another
  // user reach their folders through it.
  struct stat st {};
  ASSERT_EQ(stat(tmpdir, &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 01777u);
}

TEST(TestTempFolders, ATempDirGoesWithEverythingInIt) {
  std::string path;
  {
    test::TempDir dir;
    path = dir.path();
    fs::create_directories(dir.file("a/b"));
    test::WriteFile(dir.file("a/b/c.txt"), "x");
    test::WriteFile(dir.file("top.txt"), "y");
    ASSERT_TRUE(fs::exists(dir.file("a/b/c.txt")));
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(TestTempFolders, ASharedTempDirIsMadeOnceAndKeptUntilRemoved) {
  bool created = false;
  const std::string path = test::SharedTempDir("temp-dir-test", &created).path();
  EXPECT_TRUE(created);
  EXPECT_TRUE(fs::is_directory(path));
  test::WriteFile(path + "/kept.txt", "z");
  EXPECT_EQ(test::SharedTempDir("temp-dir-test", &created).path(), path);
  EXPECT_FALSE(created);
  EXPECT_EQ(test::ReadFile(path + "/kept.txt"), "z");
  EXPECT_NE(test::SharedTempDir("temp-dir-test-other").path(), path);
}

}  // namespace
}  // namespace armmimic
