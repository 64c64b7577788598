// armmimic-cli mimic checks every input before it opens the port: with a bad video, model or
// image the emulator on the pseudo-terminal receives nothing and no file is created.
#include <dirent.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/videoio.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/image_io.h"
#include "armmimic/sim/pty_server.h"
#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

namespace armmimic {
namespace {

constexpr int kBackground = 10;
constexpr int kStandstill = 20;

std::set<std::string> Listing(const std::string& dir) {
  std::set<std::string> names;
  DIR* d = ::opendir(dir.c_str());
  if (!d) return names;
  while (const dirent* e = ::readdir(d)) names.insert(e->d_name);
  ::closedir(d);
  return names;
}

class MimicInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    sim::EmulatorOptions o;
    o.time_scale = 0.25;
    server_ = std::make_unique<sim::PtyServer>(o);
    ASSERT_TRUE(server_->Start(dir_.file("puma")).ok());
    synth::ArmSceneOptions so;
    so.seed = 5;
    so.size = {160, 120};
    so.background_frames = kBackground;
    so.standstill_frames = kStandstill;
    synth::ArmSceneRenderer r(so);
    WriteVideo("scene.avi", kBackground + kStandstill + 10, r);
    WriteVideo("one.avi", 1, r);
    ASSERT_TRUE(WriteImageAtomically(dir_.file("background.png"), r.EmptyBackground()).ok());
    ASSERT_TRUE(WriteImageAtomically(dir_.file("armlength.png"), r.ArmLengthImage()).ok());
  }
  void WriteVideo(const std::string& name, int frames, synth::ArmSceneRenderer& r) {
    cv::VideoWriter w(dir_.file(name), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30,
                      cv::Size(160, 120));
    ASSERT_TRUE(w.isOpened());
    for (int i = 0; i < frames; ++i) w.write(r.Render(i));
  }
  // Runs mimic with `video` and `flags`, and expects a failure naming `input` that left the
  // controller and the folder untouched.
  void ExpectUntouched(const std::string& video, const std::vector<std::string>& flags,
                       const std::string& input) {
    const std::set<std::string> before = Listing(dir_.path());
    std::vector<std::string> args = {
        "--no-progress", "mimic",           video, "--realtime",
        "--port",        dir_.file("puma"), "-o",  dir_.file("live.tsv")};
    args.insert(args.end(), flags.begin(), flags.end());
    const test::CliResult r = test::RunCli(args);
    EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 2) << r.exit_code << " " << r.err;
    EXPECT_NE(r.err.find(input), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "") << "no summary for a run that never started";
    EXPECT_EQ(server_->lines_received(), 0) << "the controller received a line";
    EXPECT_TRUE(server_->log().empty());
    EXPECT_EQ(Listing(dir_.path()), before) << "a file was created or removed";
  }
  std::vector<std::string> Bgsub(const std::string& background) {
    return {"--engine",
            "bgsub",
            "--background",
            background,
            "--arm-length",
            dir_.file("armlength.png"),
            "--start",
            std::to_string(kBackground),
            "--standstill-frames",
            std::to_string(kStandstill)};
  }
  test::TempDir dir_;
  std::unique_ptr<sim::PtyServer> server_;
};

TEST_F(MimicInputs, AMissingBackgroundTouchesNothing) {
  ExpectUntouched(dir_.file("scene.avi"), Bgsub(dir_.file("nowhere.png")), "--background");
}

TEST_F(MimicInputs, ATextFileNamedAviTouchesNothing) {
  std::ofstream(dir_.file("notes.avi")) << "not a video\n";
  ExpectUntouched(dir_.file("notes.avi"), Bgsub(dir_.file("background.png")), "notes.avi");
}

TEST_F(MimicInputs, AOneFrameVideoTouchesNothing) {
  // The standstill needs 5 frames from frame 0; the video ends after one.
  ExpectUntouched(dir_.file("one.avi"),
                  {"--engine", "bgsub", "--background", dir_.file("background.png"), "--arm-length",
                   dir_.file("armlength.png"), "--standstill-frames", "5"},
                  "one.avi");
}

TEST_F(MimicInputs, ACorruptModelTouchesNothing) {
  const std::string model = dir_.file("model");
  ASSERT_EQ(::mkdir(model.c_str(), 0755), 0);
  std::ofstream(model + "/movenet-lightning.json") << "{ not a model";
  ExpectUntouched(dir_.file("scene.avi"), {"--engine", "pose", "--model", model}, "--model");
}

TEST_F(MimicInputs, AnUnwritableOutputFolderTouchesNothing) {
  ExpectUntouched(dir_.file("scene.avi"),
                  {"--engine", "lk", "--shoulder", "80,40", "-o", dir_.file("missing/live.tsv")},
                  "missing/");
}

TEST_F(MimicInputs, AGoodInputStillReachesTheController) {
  const test::CliResult r =
      test::RunCli({"--no-progress", "mimic", dir_.file("scene.avi"), "--realtime", "--port",
                    dir_.file("puma"), "-o", dir_.file("live.tsv"), "--engine", "lk", "--shoulder",
                    "80,40", "--start", std::to_string(kBackground + kStandstill)});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(server_->lines_received(), 0);
  EXPECT_TRUE(std::ifstream(dir_.file("live.tsv")).good());
}

TEST_F(MimicInputs, ATruncatedVideoEndsTheRunWithExitOneAndAnIncompleteFile) {
  synth::ArmSceneOptions so;
  so.seed = 5;
  so.size = {160, 120};
  so.background_frames = kBackground;
  so.standstill_frames = kStandstill;
  synth::ArmSceneRenderer r(so);
  WriteVideo("long.avi", kBackground + kStandstill + 90, r);
  const std::string video = dir_.file("long.avi");
  std::filesystem::resize_file(video, std::filesystem::file_size(video) / 2);
  std::vector<std::string> args = {
      "--no-progress", "mimic",           video, "--realtime",
      "--port",        dir_.file("puma"), "-o",  dir_.file("live.tsv")};
  for (const std::string& f : Bgsub(dir_.file("background.png"))) args.push_back(f);
  const test::CliResult result = test::RunCli(args);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.err.find("long.avi: the video announces"), std::string::npos) << result.err;
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(dir_.file("live.tsv"), &angles).ok());
  EXPECT_FALSE(angles.complete);
  EXPECT_FALSE(angles.rows.empty());
}

// send reads its program, profile, limits and journal before it opens the port too.
constexpr const char* kProgram =
    "; armmimic VAL program v1\n"
    "SPEED 50\n"
    "; t=0.000\n"
    "DO MOVE #PPOINT(0.00,-90.00,0.00,0.00,0.00,0.00)\n"
    "; t=1.000\n"
    "DO MOVE #PPOINT(12.00,-80.00,-6.00,0.00,0.00,0.00)\n";

TEST_F(MimicInputs, SendWithABadProgramProfileOrLimitTouchesNothing) {
  test::WriteFile(dir_.file("p.val"), kProgram);
  test::WriteFile(dir_.file("far.val"), std::string(kProgram) + "DO MOVE #PPOINT(0,0,0,0,0,999)\n");
  test::WriteFile(dir_.file("bad.profile"), "no_such_key = 1\n");
  const struct {
    std::vector<std::string> args;
    std::string named;
  } cases[] = {
      {{dir_.file("far.val")}, "far.val"},
      {{dir_.file("p.val"), "--profile", dir_.file("bad.profile")}, "bad.profile"},
      {{dir_.file("p.val"), "--limits", "J2=-100:-95"}, "p.val"},
      {{dir_.file("p.val"), "--resume"}, "p.val.journal"},
  };
  for (const auto& c : cases) {
    const std::set<std::string> before = Listing(dir_.path());
    std::vector<std::string> args = {"-q", "send"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.insert(args.end(), {"--port", dir_.file("puma")});
    const test::CliResult r = test::RunCli(args);
    EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 2) << r.exit_code << " " << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << r.err;
    EXPECT_EQ(server_->lines_received(), 0) << c.named;
    EXPECT_EQ(Listing(dir_.path()), before) << c.named;
  }
  // The good program reaches the controller.
  const test::CliResult r =
      test::RunCli({"-q", "send", dir_.file("p.val"), "--port", dir_.file("puma")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(server_->lines_received(), 0);
}

}  // namespace
}  // namespace armmimic
