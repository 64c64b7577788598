// Corrupt and mismatched inputs through armmimic-cli: every case ends with the contract's exit
// code, a message naming the file, line or flag, and no output file left behind.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

namespace armmimic {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A tiny scene (160x120: 10 empty, 10 standstill, 10 moving frames) and a 200x150 one whose
// images have the wrong size for the first; written once for the whole file.
struct Scenes {
  std::string dir;
  std::string small() const { return dir + "/small"; }
  std::string big() const { return dir + "/big"; }
};

Scenes Shared() {
  bool created = false;
  const Scenes s{test::SharedTempDir("cli-corrupt-input-scenes", &created).path()};
  if (created) {
    synth::ArmSceneOptions so;
    so.seed = 3;
    so.size = {160, 120};
    so.background_frames = 10;
    so.standstill_frames = 10;
    so.motion_frames = 10;
    so.motion = synth::ArmMotion::kSwing;
    Status st = synth::WriteArmScene(so, s.small(), {});
    if (!st.ok()) ADD_FAILURE() << st.message();
    so.size = {200, 150};
    so.background_frames = so.standstill_frames = so.motion_frames = 2;
    st = synth::WriteArmScene(so, s.big(), {});
    if (!st.ok()) ADD_FAILURE() << st.message();
  }
  return s;
}

class CorruptInput : public ::testing::Test {
 protected:
  std::string Scene() const { return Shared().small() + "/scene.avi"; }
  std::string ArmLength() const { return Shared().small() + "/armlength.png"; }

  // analyze VIDEO -o out with the bgsub engine and the tiny scene's protocol.
  test::CliResult Analyze(const std::string& video, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {
        "--no-progress",       "analyze", video,     "-o", out_, "--engine", "bgsub",
        "--standstill-frames", "10",      "--start", "10"};
    if (extra.empty()) extra = {"--background-frames", "10", "--arm-length", ArmLength()};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::RunCli(args);
  }

  // The failure contract: exit code, the named thing in the message, no output left behind,
  // and no temporary file either.
  void ExpectFailure(const test::CliResult& r, int code, const std::string& named,
                     const std::string& says) {
    EXPECT_EQ(r.exit_code, code) << r.err;
    EXPECT_TRUE(Contains(r.err, named)) << "message does not name " << named << ": " << r.err;
    EXPECT_TRUE(Contains(r.err, says)) << r.err;
    EXPECT_FALSE(fs::exists(out_)) << out_ << " was written";
    EXPECT_FALSE(fs::exists(png_)) << png_ << " was written";
    for (const auto& e : fs::directory_iterator(dir_.path())) {
      const std::string name = e.path().filename().string();
      EXPECT_FALSE(Contains(name, "angles.tsv.") || Contains(name, "bg.png."))
          << "left behind: " << name;
    }
  }

  test::TempDir dir_;
  std::string out_ = dir_.file("angles.tsv");
  std::string png_ = dir_.file("bg.png");  // the output of `background`
};

TEST_F(CorruptInput, ZeroByteVideo) {
  const std::string video = dir_.file("zero.avi");
  test::WriteFile(video, "");
  ExpectFailure(Analyze(video), 1, video, "empty file");
  ExpectFailure(test::RunCli({"background", video, "-o", png_}), 1, video, "empty file");
}

TEST_F(CorruptInput, VideoTruncatedInsideItsHeader) {
  const std::string video = dir_.file("trunc.avi");
  test::WriteFile(video, test::ReadFile(Scene()).substr(0, 3000));
  ExpectFailure(Analyze(video), 1, video, "cannot open as a video");
}

TEST_F(CorruptInput, VideoTruncatedMidStreamIsAnalysedUpToItsEndAndMarkedIncomplete) {
  // The frames that are there are analysed and kept; a quarter of the frames missing is more
  // than an estimated frame count explains, so the file is marked complete=no and exit is 1.
  const std::string full = test::ReadFile(Scene());
  const std::string video = dir_.file("half.avi");
  test::WriteFile(video, full.substr(0, full.size() * 3 / 4));
  const test::CliResult r = Analyze(video);
  ASSERT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, "from half.avi")) << r.err;
  // ... and the operator is told the rows stop early, naming the file and the shortfall.
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(out_, &angles).ok());
  EXPECT_FALSE(angles.complete);
  EXPECT_GT(angles.rows.size(), 0u);
  const std::string reason = angles.Meta("incomplete");
  EXPECT_TRUE(Contains(reason, "the video announces 30 frames, only ")) << reason;
  EXPECT_TRUE(Contains(reason, "truncated or damaged")) << reason;
  EXPECT_TRUE(Contains(r.err, video + ": " + reason)) << r.err;
  EXPECT_TRUE(Contains(r.err, std::to_string(angles.rows.size()) + " rows kept in " + out_ +
                                  " (marked complete=no)"))
      << r.err;
  EXPECT_LT(angles.rows.size(), 10u);  // fewer than the 10 motion frames of the whole file
  for (std::size_t i = 0; i < angles.rows.size(); ++i) {
    EXPECT_EQ(angles.rows[i].frame, 20 + static_cast<int>(i));
  }
}

TEST_F(CorruptInput, RandomBytesVideo) {
  const std::string video = dir_.file("random.avi");
  std::string bytes(50000, '\0');
  uint32_t x = 12345;
  for (char& c : bytes) {
    x = x * 1664525u + 1013904223u;
    c = static_cast<char>(x >> 24);
  }
  test::WriteFile(video, bytes);
  ExpectFailure(Analyze(video), 1, video, "cannot open as a video");
  ExpectFailure(test::RunCli({"background", video, "-o", png_}), 1, video,
                "cannot open as a video");
}

TEST_F(CorruptInput, VideoWithAWrongExtension) {
  const std::string video = dir_.file("scene.txt");
  test::WriteFile(video, test::ReadFile(Scene()));
  ExpectFailure(Analyze(video), 1, video, "unsupported file type '.txt'");
}

TEST_F(CorruptInput, ImageNamedAsAVideoIsTooShortForTheBackground) {
  const std::string video = dir_.file("image.avi");
  test::WriteFile(video, test::ReadFile(ArmLength()));
  ExpectFailure(Analyze(video), 1, "--background-frames", video);
}

TEST_F(CorruptInput, AviWithZeroFrames) {
  const std::string video = dir_.file("empty.avi");
  {
    cv::VideoWriter w(video, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30, {160, 120});
    ASSERT_TRUE(w.isOpened());
  }
  ASSERT_TRUE(fs::exists(video));
  ASSERT_GT(fs::file_size(video), 0u);
  ExpectFailure(Analyze(video), 1, video, "no frame could be decoded");
  ExpectFailure(test::RunCli({"background", video, "-o", png_}), 1, video,
                "no frame could be decoded");
}

TEST_F(CorruptInput, BackgroundOfAnotherSize) {
  const std::string bg = Shared().big() + "/background.png";
  ExpectFailure(Analyze(Scene(), {"--background", bg, "--arm-length", ArmLength()}), 1,
                "--background: the background image " + bg, "must have the same size");
}

TEST_F(CorruptInput, ArmLengthImageOfAnotherSize) {
  const std::string arm = Shared().big() + "/armlength.png";
  ExpectFailure(Analyze(Scene(), {"--background-frames", "10", "--arm-length", arm}), 1,
                "--arm-length: the arm-length image " + arm, "must have the same size");
}

TEST_F(CorruptInput, ArmLengthImageThatIsNotAnImage) {
  const std::string arm = dir_.file("arm.png");
  test::WriteFile(arm, "not a png at all\n");
  ExpectFailure(Analyze(Scene(), {"--background-frames", "10", "--arm-length", arm}), 1,
                "--arm-length: " + arm, "not a readable image");
}

TEST_F(CorruptInput, MissingVideo) {
  const std::string video = dir_.file("missing.avi");
  ExpectFailure(Analyze(video), 1, video, "no such file");
  ExpectFailure(test::RunCli({"background", video, "-o", png_}), 1, video, "no such file");
}

TEST_F(CorruptInput, UnreadableVideo) {
  // As root every file is readable: the CLI then runs as nobody (setpriv).
  // setpriv is part of util-linux, which every Debian system has: a test never skips.
  ASSERT_TRUE(test::CanRunUnprivileged()) << "cannot drop root here (no /usr/bin/setpriv)";
  chmod(dir_.path().c_str(), 0777);
  const std::string video = dir_.file("locked.avi");
  const std::string arm = dir_.file("arm.png");
  test::WriteFile(video, test::ReadFile(Scene()));
  test::WriteFile(arm, test::ReadFile(ArmLength()));
  chmod(video.c_str(), 0);
  const std::vector<std::string> args = {"--no-progress",
                                         "analyze",
                                         video,
                                         "-o",
                                         out_,
                                         "--engine",
                                         "bgsub",
                                         "--standstill-frames",
                                         "10",
                                         "--start",
                                         "10",
                                         "--background-frames",
                                         "10",
                                         "--arm-length",
                                         arm};
  ExpectFailure(test::RunCliUnprivileged(args), 1, video, "Permission denied");
}

TEST_F(CorruptInput, VideoThatIsADirectory) {
  const std::string video = dir_.file("folder.avi");
  fs::create_directory(video);
  const test::CliResult r = Analyze(video);
  EXPECT_EQ(r.exit_code, 1) << r.err;  // read as an (empty) folder of images
  EXPECT_TRUE(Contains(r.err, video + ": no images in folder")) << r.err;
  EXPECT_FALSE(fs::exists(out_));
}

TEST_F(CorruptInput, OutputInAMissingDirectory) {
  const std::string out = dir_.file("nodir/angles.tsv");
  const test::CliResult r = Analyze(Scene());
  ASSERT_EQ(r.exit_code, 0) << r.err;  // the same run with a good output works
  fs::remove(out_);
  std::vector<std::string> args = {"analyze",
                                   Scene(),
                                   "-o",
                                   out,
                                   "--engine",
                                   "bgsub",
                                   "--standstill-frames",
                                   "10",
                                   "--background-frames",
                                   "10",
                                   "--arm-length",
                                   ArmLength()};
  const test::CliResult bad = test::RunCli(args);
  EXPECT_EQ(bad.exit_code, 1) << bad.err;
  EXPECT_TRUE(Contains(bad.err, out)) << bad.err;
  EXPECT_TRUE(Contains(bad.err, "does not exist")) << bad.err;
  EXPECT_FALSE(fs::exists(dir_.file("nodir")));

  const std::string bg = dir_.file("nodir/bg.png");
  const test::CliResult b = test::RunCli({"background", Scene(), "-o", bg, "--frames", "5"});
  EXPECT_EQ(b.exit_code, 1) << b.err;
  EXPECT_TRUE(Contains(b.err, bg)) << b.err;
}

// Angle files with a defect on one line: plan, score and send --dry-run all refuse them with
// exit 1 and "file:line".
class BadAngleFile : public CorruptInput {
 protected:
  static std::string Header() {
    return std::string(kAngleFileMagic) + "\n# engine=bgsub source=x.avi fps=30\n" +
           "frame\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\tupper_cx\t"
           "upper_cy\tfore_cx\tfore_cy\n";
  }
  // A row; a lost row carries nan angles as the contract says.
  static std::string Row(const std::string& frame, const std::string& time,
                         const std::string& status, const std::string& upper) {
    const std::string rest = status == "lost" ? "\tnan\tnan\tnan" : "\t-90\tnan\t0";
    return frame + "\t" + time + "\t" + status + "\t" + upper + rest + "\tnan\tnan\tnan\tnan\n";
  }
  // Writes the header and rows, then checks every reader names `line` and says `says`.
  void ExpectRejected(const std::string& rows, int line, const std::string& says) {
    const std::string file = dir_.file("bad.tsv");
    test::WriteFile(file, Header() + rows);
    const std::string where = file + ":" + std::to_string(line);
    const std::string val = dir_.file("p.val");
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"plan", file, "-o", val},
          std::vector<std::string>{"score", Shared().small() + "/truth.tsv", file},
          std::vector<std::string>{"send", file, "--dry-run"}}) {
      const test::CliResult r = test::RunCli(args);
      EXPECT_EQ(r.exit_code, 1) << args[0] << ": " << r.err;
      EXPECT_TRUE(Contains(r.err, where)) << args[0] << ": " << r.err;
      EXPECT_TRUE(Contains(r.err, says)) << args[0] << ": " << r.err;
      EXPECT_FALSE(fs::exists(val)) << args[0];
    }
  }
};

TEST_F(BadAngleFile, NanFrameIndex) {
  ExpectRejected(Row("0", "0", "ok", "-90") + Row("nan", "0.033", "ok", "-85"), 5, "frame \"nan\"");
}

TEST_F(BadAngleFile, InfFrameIndex) {
  ExpectRejected(Row("0", "0", "ok", "-90") + Row("inf", "0.033", "ok", "-85"), 5, "frame \"inf\"");
}

TEST_F(BadAngleFile, InfTime) {
  ExpectRejected(Row("0", "0", "ok", "-90") + Row("1", "inf", "ok", "-85"), 5, "time_s \"inf\"");
}

TEST_F(BadAngleFile, NanTime) {
  ExpectRejected(Row("0", "0", "ok", "-90") + Row("1", "nan", "ok", "-85"), 5, "time_s");
}

TEST_F(BadAngleFile, InfAngle) {
  ExpectRejected(Row("0", "0", "ok", "-90") + Row("1", "0.033", "ok", "inf"), 5,
                 "upper_deg \"inf\"");
}

TEST_F(BadAngleFile, MinusInfAngle) {
  ExpectRejected(Row("0", "0", "ok", "-90") + Row("1", "0.033", "ok", "-inf"), 5, "upper_deg");
}

TEST_F(BadAngleFile, DuplicateFrame) {
  ExpectRejected(
      Row("0", "0", "ok", "-90") + Row("1", "0.033", "ok", "-85") + Row("1", "0.033", "ok", "-80"),
      6, "frame 1 is repeated");
}

TEST_F(BadAngleFile, FramesOutOfOrder) {
  ExpectRejected(
      Row("0", "0", "ok", "-90") + Row("2", "0.066", "ok", "-85") + Row("1", "0.033", "ok", "-80"),
      6, "frame 1 is out of order");
}

TEST_F(BadAngleFile, TruncatedLastRow) {
  ExpectRejected(Row("0", "0", "ok", "-90") + "1\t0.033\tok\t-85\n", 5, "");
}

TEST_F(BadAngleFile, NumberInALostRow) {
  ExpectRejected(Row("0", "0", "ok", "-90") + Row("1", "0.033", "lost", "-85"), 5,
                 "status is lost but upper_deg is a number");
}

TEST_F(BadAngleFile, NanAngleInALostRowIsFine) {
  // The control case: nan where the contract allows it is read and planned.
  const std::string file = dir_.file("good.tsv");
  test::WriteFile(file, Header() + Row("0", "0", "ok", "-90") + Row("1", "0.033", "lost", "nan") +
                            Row("2", "0.066", "ok", "-80"));
  const test::CliResult r = test::RunCli({"plan", file, "-o", dir_.file("p.val")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_.file("p.val")));
}

TEST_F(BadAngleFile, PlanOutputInAMissingDirectory) {
  const std::string file = dir_.file("good.tsv");
  test::WriteFile(file, Header() + Row("0", "0", "ok", "-90") + Row("1", "0.033", "ok", "-80"));
  const std::string val = dir_.file("nodir/p.val");
  const test::CliResult r = test::RunCli({"plan", file, "-o", val});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.err, val)) << r.err;
  EXPECT_FALSE(fs::exists(dir_.file("nodir")));
}

}  // namespace
}  // namespace armmimic
