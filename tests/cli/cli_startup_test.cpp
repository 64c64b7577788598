// The process's start: armmimic-cli reads videos and PNG images without OpenCV's image codecs
// and video I/O, whose hundred libraries would cost a short run most of its start. They live in
// the armmimic-cvio module, loaded only by what needs it (writing images, other image formats,
// cameras), from beside the program when it is installed. Which files the dynamic loader opened
// is read from its own trace (LD_DEBUG=files).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "test_util.h"

namespace armmimic {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::vector<std::string> TracedEnvironment() {
  std::vector<std::string> env = test::EnvironmentWithout({"LD_DEBUG", "LD_DEBUG_OUTPUT"});
  env.emplace_back("LD_DEBUG=files");
  return env;
}

class CliStartup : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir();
    const test::CliResult r =
        test::RunCli({"synth", "arm", dir_->file("scene"), "--seed", "4", "--frames", "10", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static test::TempDir* dir_;
};
test::TempDir* CliStartup::dir_ = nullptr;

TEST_F(CliStartup, AnalyzingAVideoWithPngImagesLoadsNoImageCodecs) {
  const std::string scene = dir_->file("scene");
  const test::CliResult r = test::RunProgram(
      {ARMMIMIC_CLI_PATH, "analyze", scene + "/scene.avi", "-o", dir_->file("a.tsv"), "--engine",
       "bgsub", "--background", scene + "/background.png", "--arm-length", scene + "/armlength.png",
       "--start", "45", "--standstill-frames", "20", "-q"},
      TracedEnvironment());
  ASSERT_EQ(r.exit_code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
  // The trace is there (so its silence below means something), and FFmpeg is in it.
  EXPECT_TRUE(Contains(r.err, "libavcodec")) << "no loader trace";
  EXPECT_FALSE(Contains(r.err, "libopencv_imgcodecs"));
  EXPECT_FALSE(Contains(r.err, "libopencv_videoio"));
  EXPECT_FALSE(Contains(r.err, "armmimic-cvio"));
}

TEST_F(CliStartup, AnInstalledProgramLoadsTheCodecModuleFromBesideIt) {
  // PREFIX/bin/armmimic-cli and PREFIX/<libdir>/armmimic/armmimic-cvio.so, as installed.
  const std::string program = dir_->file("prefix/bin/armmimic-cli");
  const std::string module = dir_->file("prefix/bin/" ARMMIMIC_CVIO_RELATIVE);
  test::LinkOrCopy(ARMMIMIC_CLI_PATH, program);
  test::LinkOrCopy(ARMMIMIC_CVIO_BUILD_PATH, module);
  // Estimating an empty room writes a PNG: that needs the encoder, so the module.
  const std::string out = dir_->file("bg.png");
  const test::CliResult r = test::RunProgram(
      {program, "background", dir_->file("scene/scene.avi"), "-o", out, "--frames", "10", "-q"},
      TracedEnvironment());
  ASSERT_EQ(r.exit_code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
  EXPECT_TRUE(fs::exists(out));
  // The loader names the file as the program asked for it: its own folder, then the way on.
  const std::string asked =
      fs::canonical(dir_->file("prefix/bin")).string() + "/" + ARMMIMIC_CVIO_RELATIVE;
  EXPECT_TRUE(Contains(r.err, "file=" + asked))
      << "the module was not loaded from beside the program";
  EXPECT_TRUE(Contains(r.err, "libopencv_imgcodecs"));
}

}  // namespace
}  // namespace armmimic
