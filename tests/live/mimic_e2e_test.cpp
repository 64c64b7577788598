// armmimic-cli mimic end to end over a real pseudo-terminal: a paced synthetic video is analysed
// live and streamed to the emulator's pty server running in this process; the emulator's move
// log, the journal and the latency log prove what the arm did.
#include <signal.h>

#include <chrono>
#include <cmath>
#include <set>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>
#include <opencv2/videoio.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/image_io.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/sim/pty_server.h"
#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

namespace armmimic {
namespace {

using robot::JointArray;
using Clock = std::chrono::steady_clock;

constexpr int kBackground = 10;
constexpr int kStandstill = 20;

// A scene rendered into a folder: frames chosen by `frame_of(i)` (-1: the empty room), plus the
// background and arm-length images for bgsub.
struct Scene {
  std::string dir;
  std::string video;
  int frames = 0;
  synth::ArmTruth start;  // the truth of the first frame after the standstill
};

Scene Render(const test::TempDir& dir, const std::string& name, int frames, synth::ArmMotion motion,
             const std::function<int(int)>& frame_of) {
  synth::ArmSceneOptions so;
  so.seed = 5;
  so.size = {240, 180};
  so.background_frames = kBackground;
  so.standstill_frames = kStandstill;
  so.motion_frames = 200;
  so.motion = motion;
  synth::ArmSceneRenderer r(so);
  Scene s;
  s.dir = dir.path();
  s.video = dir.file(name + ".avi");
  s.frames = frames;
  cv::VideoWriter w(s.video, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30, so.size);
  EXPECT_TRUE(w.isOpened());
  const cv::Mat empty = r.EmptyBackground();
  for (int i = 0; i < frames; ++i) {
    const int f = frame_of(i);
    w.write(f < 0 ? empty : r.Render(f));
  }
  s.start = r.Truth(so.first_motion_frame());
  EXPECT_TRUE(WriteImageAtomically(dir.file("background.png"), empty).ok());
  EXPECT_TRUE(WriteImageAtomically(dir.file("armlength.png"), r.ArmLengthImage()).ok());
  return s;
}

// The bgsub flags for a scene made by Render.
std::vector<std::string> BgsubFlags(const test::TempDir& dir) {
  return {"--engine",
          "bgsub",
          "--background",
          dir.file("background.png"),
          "--arm-length",
          dir.file("armlength.png"),
          "--start",
          std::to_string(kBackground),
          "--standstill-frames",
          std::to_string(kStandstill)};
}

std::string Point(const cv::Point2d& p) {
  return std::to_string(static_cast<int>(std::lround(p.x))) + "," +
         std::to_string(static_cast<int>(std::lround(p.y)));
}

// The lk flags with the joints clicked in the first motion frame.
std::vector<std::string> LkFlags(const Scene& s) {
  return {"--engine",   "lk",
          "--start",    std::to_string(kBackground + kStandstill),
          "--shoulder", Point(s.start.shoulder_px),
          "--elbow",    Point(s.start.elbow_px),
          "--wrist",    Point(s.start.wrist_px)};
}

struct JournalRecord {
  std::string kind;  // sent, ack, stop, end, last-ack
  int seq = 0;
  double time_s = 0;
  int frame = -1;
  std::string text;
};

std::vector<JournalRecord> ReadJournal(const std::string& path) {
  std::vector<JournalRecord> out;
  std::istringstream in(test::ReadFile(path));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    JournalRecord r;
    f >> r.kind;
    if (r.kind == "sent") {
      std::string frame;
      f >> r.seq >> r.time_s >> frame;
      r.frame = frame == "-" ? -1 : std::stoi(frame);
      std::getline(f, r.text);
      r.text = r.text.substr(1);
    } else if (r.kind == "ack") {
      f >> r.seq >> r.time_s;
    } else if (r.kind == "last-ack") {
      std::string seq, frame;
      f >> seq;
      r.seq = seq == "none" ? 0 : std::stoi(seq);
      if (r.seq > 0) {
        f >> frame;
        std::getline(f, r.text);
        r.text = r.text.substr(1);
      }
    } else {
      std::getline(f, r.text);
    }
    out.push_back(r);
  }
  return out;
}

// Every move the emulator ran is inside `limits`, no faster between two consecutive moves than
// the speed limits allow over the time between their writes, and was written by the stream.
void ExpectSafe(const std::vector<sim::LoggedMove>& moves,
                const std::vector<JournalRecord>& journal, const robot::JointLimits& limits) {
  std::vector<JournalRecord> sent;
  for (const JournalRecord& r : journal) {
    if (r.kind == "sent" && robot::IsMotionLine(r.text)) sent.push_back(r);
  }
  ASSERT_EQ(moves.size(), sent.size()) << "every move the robot ran was written and journaled";
  for (std::size_t i = 0; i < moves.size(); ++i) {
    EXPECT_EQ(moves[i].source, sent[i].text);
    for (int j = 0; j < robot::kJoints; ++j) {
      EXPECT_TRUE(limits.Inside(j, moves[i].target_deg[j]))
          << "move " << i + 1 << " J" << j + 1 << " " << moves[i].target_deg[j];
      if (i == 0) continue;
      const double dt = sent[i].time_s - sent[i - 1].time_s;
      EXPECT_LE(std::abs(moves[i].target_deg[j] - moves[i - 1].target_deg[j]),
                limits.max_speed_deg_s[j] * dt + 0.011 + limits.max_speed_deg_s[j] * 0.001)
          << "move " << i + 1 << " J" << j + 1 << " faster than its limit";
    }
  }
}

class MimicE2E : public ::testing::Test {
 protected:
  void SetUp() override {
    sim::EmulatorOptions o;
    o.time_scale = 0.25;  // motions four times faster than a real arm: short tests
    server_ = std::make_unique<sim::PtyServer>(o);
    ASSERT_TRUE(server_->Start(dir_.file("puma")).ok());
  }
  std::vector<std::string> Args(const Scene& s, const std::vector<std::string>& engine,
                                std::vector<std::string> extra = {}) {
    std::vector<std::string> a = {"--no-progress", "mimic",           s.video, "--realtime",
                                  "--port",        dir_.file("puma"), "-o",    angles_};
    a.insert(a.end(), engine.begin(), engine.end());
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }
  int Acks() const {
    int n = 0;
    for (const JournalRecord& r : ReadJournal(angles_ + ".journal")) n += r.kind == "ack";
    return n;
  }
  test::TempDir dir_;
  std::string angles_ = dir_.file("live.tsv");
  std::unique_ptr<sim::PtyServer> server_;
};

TEST_F(MimicE2E, APacedVideoStreamsEveryMoveWithinTheLimitsAndPrintsTheLatency) {
  const Scene s = Render(dir_, "swing", kBackground + kStandstill + 75, synth::ArmMotion::kSwing,
                         [](int i) { return i; });
  const test::CliResult r = test::RunCli(Args(s, LkFlags(s)));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("p95"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" ms"), std::string::npos) << r.out;
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(angles_, &angles).ok());
  EXPECT_TRUE(angles.complete);
  EXPECT_EQ(angles.rows.size(), 75u);
  const auto journal = ReadJournal(angles_ + ".journal");
  ExpectSafe(server_->log(), journal, robot::JointLimits());
  EXPECT_GE(server_->log().size(), 3u);
  ASSERT_FALSE(journal.empty());
  EXPECT_EQ(journal[journal.size() - 2].kind, "end");
  EXPECT_EQ(journal.back().kind, "last-ack");
  EXPECT_EQ(journal.back().text, server_->log().back().source);
  // One latency row per angle-file row.
  std::istringstream latency(test::ReadFile(angles_ + ".latency.tsv"));
  std::string line;
  int rows = 0;
  while (std::getline(latency, line)) rows += !line.empty() && line[0] != '#';
  EXPECT_EQ(rows, 75 + 1);  // and the header
}

TEST_F(MimicE2E, LostFramesHoldTheRobot) {
  // The arm swings; frames 30..49 of the motion show the empty room: the engine loses the arm.
  const int first = kBackground + kStandstill;
  const Scene s = Render(dir_, "gap", first + 80, synth::ArmMotion::kSwing,
                         [&](int i) { return i >= first + 30 && i < first + 50 ? -1 : i; });
  const test::CliResult r = test::RunCli(Args(s, BgsubFlags(dir_)));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // From the latency log: which frames were lost, and the first ok frame after them.
  std::istringstream latency(test::ReadFile(angles_ + ".latency.tsv"));
  std::string line;
  std::set<int> lost_frames;
  int first_lost = -1, next_ok = -1;
  while (std::getline(latency, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("frame", 0) == 0) continue;
    std::istringstream f(line);
    int frame = 0;
    std::string status;
    f >> frame >> status;
    if (status == "lost") {
      lost_frames.insert(frame);
      EXPECT_EQ(line.substr(line.rfind('\t')), "\tlost") << line;
      if (first_lost < 0) first_lost = frame;
    } else if (first_lost >= 0 && next_ok < 0) {
      next_ok = frame;
    }
  }
  ASSERT_GE(lost_frames.size(), 15u) << "the empty frames should be lost";
  ASSERT_GT(next_ok, first_lost);
  // Every command names the frame it was planned from: none comes from a lost frame, and none
  // planned inside the gap at all (a command planned just before it may still be on its way).
  const auto journal = ReadJournal(angles_ + ".journal");
  int sent = 0;
  for (const JournalRecord& rec : journal) {
    if (rec.kind != "sent" || rec.frame < 0) continue;
    ++sent;
    EXPECT_EQ(lost_frames.count(rec.frame), 0u)
        << "command " << rec.seq << " was planned from lost frame " << rec.frame;
    EXPECT_FALSE(rec.frame > first_lost && rec.frame < next_ok)
        << "command " << rec.seq << " was planned from frame " << rec.frame
        << " while the arm was lost (" << first_lost << ".." << next_ok << ")";
  }
  EXPECT_GT(sent, 0);
  ExpectSafe(server_->log(), journal, robot::JointLimits());
}

TEST_F(MimicE2E, AnUnpluggedLinkStopsTheStreamWithExitOneAndAMessage) {
  const Scene s = Render(dir_, "long", kBackground + kStandstill + 180, synth::ArmMotion::kSwing,
                         [](int i) { return i; });
  test::BackgroundCli cli(Args(s, LkFlags(s)), dir_.file("out"), dir_.file("err"));
  ASSERT_TRUE(cli.started());
  const auto until = Clock::now() + std::chrono::seconds(20);
  while (Acks() < 3 && !cli.Exited() && Clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_GE(Acks(), 3) << test::ReadFile(dir_.file("err"));
  server_->Stop();  // the cable is pulled
  EXPECT_EQ(cli.Wait(20), 1);
  const std::string err = test::ReadFile(dir_.file("err"));
  EXPECT_NE(err.find("the connection was lost"), std::string::npos) << err;
  EXPECT_NE(err.find("--port: " + dir_.file("puma")), std::string::npos) << err;
  const auto journal = ReadJournal(angles_ + ".journal");
  ASSERT_GE(journal.size(), 2u);
  EXPECT_EQ(journal[journal.size() - 2].kind, "stop");
  EXPECT_EQ(journal.back().kind, "last-ack");
  AngleFile angles;
  ASSERT_TRUE(ReadAngleFile(angles_, &angles).ok());
  EXPECT_FALSE(angles.complete);
}

TEST_F(MimicE2E, CtrlCLeavesAValidAngleFileAndAJournalEndingAtTheLastAcknowledgedMove) {
  const Scene s = Render(dir_, "long", kBackground + kStandstill + 180, synth::ArmMotion::kSwing,
                         [](int i) { return i; });
  test::BackgroundCli cli(Args(s, LkFlags(s)), dir_.file("out"), dir_.file("err"));
  ASSERT_TRUE(cli.started());
  const auto until = Clock::now() + std::chrono::seconds(20);
  while (Acks() < 4 && !cli.Exited() && Clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_GE(Acks(), 4) << test::ReadFile(dir_.file("err"));
  cli.Signal(SIGINT);
  EXPECT_EQ(cli.Wait(20), 1);
  const std::string err = test::ReadFile(dir_.file("err"));
  EXPECT_NE(err.find("interrupted (SIGINT"), std::string::npos) << err;
  EXPECT_NE(test::ReadFile(dir_.file("out")).find("p95"), std::string::npos);
  AngleFile angles;
  const Status st = ReadAngleFile(angles_, &angles);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_FALSE(angles.complete);
  EXPECT_GT(angles.rows.size(), 5u);
  const auto journal = ReadJournal(angles_ + ".journal");
  ASSERT_GE(journal.size(), 2u);
  EXPECT_EQ(journal[journal.size() - 2].kind, "stop");
  EXPECT_NE(journal[journal.size() - 2].text.find("interrupted (SIGINT"), std::string::npos);
  // The journal's last acknowledged move is the last move the robot ran: no half-written line.
  ASSERT_EQ(journal.back().kind, "last-ack");
  ASSERT_FALSE(server_->log().empty());
  EXPECT_EQ(journal.back().text, server_->log().back().source);
  int sent = 0, acked = 0;
  for (const JournalRecord& r : journal) {
    sent += r.kind == "sent";
    acked += r.kind == "ack";
  }
  EXPECT_EQ(sent, acked) << "every line written was acknowledged before the stop";
  ExpectSafe(server_->log(), journal, robot::JointLimits());
  // The latency log's frames after the signal are held by it, not by an operator.
  const std::string latency = test::ReadFile(angles_ + ".latency.tsv");
  EXPECT_EQ(latency.find("held by the operator"), std::string::npos) << latency;
}

TEST_F(MimicE2E, NoOutOfLimitOrOverSpeedCommandIsWrittenWhenTheInputJumps) {
  // Every 6 frames the video cuts to another moment of a mixed motion: the arm jumps.
  const int first = kBackground + kStandstill;
  const Scene s = Render(dir_, "jumps", first + 90, synth::ArmMotion::kMixed, [&](int i) {
    if (i < first) return i;
    const int k = i - first;
    return first + ((k / 6) * 37) % 200 + k % 6;
  });
  robot::JointLimits narrow;
  narrow.min_deg[1] = -100;  // J2: the upper arm not above horizontal, a little
  narrow.max_deg[2] = 0;
  narrow.min_deg[2] = -60;  // J3: the elbow flexed at most 60 degrees
  narrow.max_speed_deg_s = {30, 30, 30, 60, 60, 60};
  const test::CliResult r = test::RunCli(Args(s, BgsubFlags(dir_),
                                              {"--limits", "J2=-100:20,J3=-60:0", "--speed-limit",
                                               "30,30,30,60,60,60", "--max-jump", "20000"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto journal = ReadJournal(angles_ + ".journal");
  ExpectSafe(server_->log(), journal, narrow);
  EXPECT_GE(server_->log().size(), 2u);
}

}  // namespace
}  // namespace armmimic
