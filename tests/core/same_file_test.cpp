#include "armmimic/core/same_file.h"

#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "test_util.h"

namespace armmimic {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(SameFile, CatchesTheSameFileUnderEverySpelling) {
  test::TempDir dir;
  const std::string a = dir.file("a.tsv");
  test::WriteFile(a, "x");
  ASSERT_EQ(symlink(a.c_str(), dir.file("link.tsv").c_str()), 0);
  ASSERT_EQ(link(a.c_str(), dir.file("hard.tsv").c_str()), 0);
  const std::string cwd = std::filesystem::current_path().string();
  ASSERT_EQ(chdir(dir.path().c_str()), 0);
  for (const std::string& out :
       {a, dir.path() + "/./a.tsv", dir.path() + "//a.tsv", std::string("a.tsv"),
        std::string("./a.tsv"), dir.file("link.tsv"), dir.file("hard.tsv")}) {
    const Status st = CheckOutputsAreNotInputs({{"ANGLES.tsv", "a.tsv"}}, {{"-o", out}});
    ASSERT_FALSE(st.ok()) << out;
    // Both names appear, with what each one is.
    EXPECT_TRUE(Contains(st.message(), "-o " + out)) << st.message();
    EXPECT_TRUE(Contains(st.message(), "ANGLES.tsv a.tsv")) << st.message();
    EXPECT_TRUE(Contains(st.message(), "same file")) << st.message();
  }
  ASSERT_EQ(chdir(cwd.c_str()), 0);
}

TEST(SameFile, OtherAndNewFilesPass) {
  test::TempDir dir;
  test::WriteFile(dir.file("a.tsv"), "x");
  test::WriteFile(dir.file("b.tsv"), "x");  // same content, another file
  EXPECT_TRUE(CheckOutputsAreNotInputs({{"ANGLES.tsv", dir.file("a.tsv")}},
                                       {{"-o", dir.file("b.tsv")}, {"-o", dir.file("new.tsv")}})
                  .ok());
  // Inputs that are no file (a camera, a missing path) match nothing.
  EXPECT_TRUE(CheckOutputsAreNotInputs({{"INPUT", "camera:0"}, {"INPUT", dir.file("gone.avi")}},
                                       {{"-o", dir.file("b.tsv")}})
                  .ok());
}

TEST(SameFile, AFolderInputStandsForItsFiles) {
  test::TempDir dir;
  std::filesystem::create_directory(dir.file("views"));
  test::WriteFile(dir.file("views/v_000.png"), "png");
  const Status st = CheckOutputsAreNotInputs({{"INPUT", dir.file("views")}},
                                             {{"-o", dir.file("views/v_000.png")}});
  ASSERT_FALSE(st.ok());
  EXPECT_TRUE(Contains(st.message(), "v_000.png (in INPUT " + dir.file("views") + ")"))
      << st.message();
  EXPECT_TRUE(CheckOutputsAreNotInputs({{"INPUT", dir.file("views")}},
                                       {{"-o", dir.file("views/angles.tsv")}})
                  .ok());
}

TEST(SameFile, TwoOutputsMayNotBeOneFile) {
  test::TempDir dir;
  test::WriteFile(dir.file("old.tsv"), "x");
  ASSERT_EQ(symlink(dir.file("old.tsv").c_str(), dir.file("alias.tsv").c_str()), 0);
  EXPECT_FALSE(
      CheckOutputsAreDistinct({{"a", dir.file("x/v.tsv")}, {"b", dir.file("x/../x/v.tsv")}}).ok());
  const Status st =
      CheckOutputsAreDistinct({{"first", dir.file("old.tsv")}, {"second", dir.file("alias.tsv")}});
  ASSERT_FALSE(st.ok());
  EXPECT_TRUE(Contains(st.message(), "first " + dir.file("old.tsv"))) << st.message();
  EXPECT_TRUE(CheckOutputsAreDistinct({{"a", dir.file("v.tsv")}, {"b", dir.file("w.tsv")}}).ok());
}

}  // namespace
}  // namespace armmimic
