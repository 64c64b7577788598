// LiveStream driving the real LinkProtocol against a scripted controller in simulated time:
// what reaches the "port" is checked independently of the stream's own gate.
#include "armmimic/robot/live_stream.h"

#include <cmath>
#include <functional>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "angle_rows.h"

#include "armmimic/core/angles.h"
#include "test_util.h"

namespace armmimic::robot {
namespace {

constexpr double kFps = 30;
constexpr double kStep = 0.005;  // simulated seconds per protocol tick

// Echoes every line and prompts; a DO MOVE's prompt comes when the motion has ended (at the
// limits' speed, as SPEED 75 gives with the default profile), as the emulator does.
struct Controller {
  JointArray pos{};  // the arm hanging, as the stream's first target
  JointArray target{};
  double busy_until = -1;
  bool prompt_due = false;
  std::string rx;
  std::vector<std::pair<double, std::string>> lines;  // time received, text
  std::vector<std::pair<double, JointArray>> moves;   // time started, target

  std::string Feed(const std::string& bytes, double now) {
    std::string out;
    for (char c : bytes) {
      if (c != '\r') {
        rx += c;
        continue;
      }
      const std::string line = rx;
      rx.clear();
      if (line.empty()) {
        out += "\r\n.";
        continue;
      }
      lines.push_back({now, line});
      out += line + "\r\n";
      if (ParsePpointTarget(line, &target)) {
        double longest = 0;
        for (int j = 0; j < kJoints; ++j) longest = std::max(longest, std::abs(target[j] - pos[j]));
        busy_until = now + longest / 45.0 + 0.05;
        prompt_due = true;
        moves.push_back({now, target});
      } else {
        out += ".";
      }
    }
    return out;
  }
  std::string Tick(double now) {
    if (!prompt_due || now < busy_until) return "";
    prompt_due = false;
    pos = target;
    return ".";
  }
};

struct Rig {
  LinkProtocol protocol;
  Controller controller;
  LiveStream stream;
  double now = 0;

  Status Begin(LiveStreamOptions o) {
    const Status s = stream.Begin(o);
    if (!s.ok()) return s;
    stream.SetClock([this] { return now; });
    stream.Attach(&protocol, [this](const LinkLine& l) { protocol.Append(l, now); });
    protocol.StartStream("mimic", now);
    stream.SendOpening();
    return Status::Ok();
  }
  void Advance(double until) {
    while (now < until - 1e-12) {
      now = std::min(until, now + kStep);
      const std::string out = protocol.TakeOutput();
      if (!out.empty()) protocol.OnBytes(controller.Feed(out, now), now);
      const std::string later = controller.Tick(now);
      if (!later.empty()) protocol.OnBytes(later, now);
      protocol.OnTick(now);
    }
  }
  void Frame(const AngleRow& row) {
    Advance(row.time_s);
    stream.OnFrame(row, row.time_s, row.time_s, now);
    Advance(now + kStep);  // the command (if any) reaches the controller
  }
};

AngleRow Row(int frame, double upper, double bend, bool lost = false) {
  return test::MakeRow(frame, kFps, upper, bend, 0, lost);
}

TEST(LiveStream, LostFramesHoldTheRobot) {
  test::TempDir dir;
  Rig rig;
  LiveStreamOptions o;
  o.journal_path = dir.file("a.tsv.journal");
  o.latency_path = dir.file("a.tsv.latency.tsv");
  ASSERT_TRUE(rig.Begin(o).ok());
  // The arm rises 1 degree a frame; frames 40..69 are lost.
  for (int f = 0; f < 100; ++f) rig.Frame(Row(f, -90 + f, 0, f >= 40 && f < 70));
  const double lost_from = 40 / kFps, lost_to = 70 / kFps;
  int during = 0;
  for (const auto& [t, target] : rig.controller.moves) {
    if (t > lost_from + kStep && t < lost_to) ++during;
  }
  EXPECT_EQ(during, 0) << "the robot was sent a move while the arm was lost";
  EXPECT_GT(rig.controller.moves.size(), 5u);
  // Every lost frame's latency row says why nothing went out.
  rig.stream.Stop("");
  rig.protocol.EndStream();
  rig.Advance(rig.now + 3);
  ASSERT_TRUE(rig.stream.Close().ok());
  const std::string log = test::ReadFile(o.latency_path);
  std::istringstream in(log);
  std::string line;
  int lost_rows = 0;
  while (std::getline(in, line)) {
    if (line.find("\tlost\t") == std::string::npos) continue;
    ++lost_rows;
    EXPECT_EQ(line.substr(line.rfind('\t')), "\tlost") << line;  // the hold column says why
  }
  EXPECT_EQ(lost_rows, 30);
  EXPECT_EQ(rig.protocol.state(), LinkState::kDone);
}

TEST(LiveStream, AStopWaitsForTheMoveInFlightAndTheJournalNamesTheLastAcknowledged) {
  test::TempDir dir;
  Rig rig;
  LiveStreamOptions o;
  o.journal_path = dir.file("b.tsv.journal");
  ASSERT_TRUE(rig.Begin(o).ok());
  for (int f = 0; f < 45; ++f) rig.Frame(Row(f, -90 + 3.0 * f, 0));
  ASSERT_NE(rig.protocol.in_flight(), nullptr) << "a move should be under way";
  const std::size_t moves_at_stop = rig.controller.moves.size();
  rig.stream.Stop("interrupted (SIGINT, Ctrl-C)");
  rig.protocol.EndStream();
  for (int f = 45; f < 90; ++f) rig.Frame(Row(f, -90 + 3.0 * f, 0));
  rig.Advance(rig.now + 3);
  EXPECT_EQ(rig.controller.moves.size(), moves_at_stop) << "a move went out after the stop";
  EXPECT_EQ(rig.protocol.state(), LinkState::kDone);
  ASSERT_TRUE(rig.stream.Close().ok());
  const std::string journal = test::ReadFile(o.journal_path);
  EXPECT_NE(journal.find("\nstop interrupted (SIGINT, Ctrl-C)\n"), std::string::npos) << journal;
  const std::string last = FormatMoveLine(rig.controller.moves.back().second, ControllerProfile());
  EXPECT_NE(journal.find("\nlast-ack " + std::to_string(rig.stream.last_acked_seq()) + " "),
            std::string::npos)
      << journal;
  EXPECT_NE(journal.find(" " + last + "\n", journal.find("last-ack")), std::string::npos)
      << journal;
}

// After a signal stops the stream, the latency log's hold column names the signal for every
// frame that still arrives, not an operator who never held anything.
TEST(LiveStream, FramesAfterASignalNameItAsTheHoldReason) {
  test::TempDir dir;
  Rig rig;
  LiveStreamOptions o;
  o.latency_path = dir.file("c.tsv.latency.tsv");
  ASSERT_TRUE(rig.Begin(o).ok());
  for (int f = 0; f < 30; ++f) rig.Frame(Row(f, -90 + f, 0));
  rig.stream.Stop("interrupted (SIGTERM)");
  rig.protocol.EndStream();
  for (int f = 30; f < 35; ++f) rig.Frame(Row(f, -90 + f, 0));
  rig.Advance(rig.now + 3);
  ASSERT_TRUE(rig.stream.Close().ok());
  std::istringstream in(test::ReadFile(o.latency_path));
  std::string line;
  int after = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("frame\t", 0) == 0) continue;
    const int frame = std::stoi(line.substr(0, line.find('\t')));
    const std::string hold = line.substr(line.rfind('\t') + 1);
    EXPECT_NE(hold, "held by the operator") << line;
    if (frame < 30) continue;
    ++after;
    EXPECT_EQ(hold, "interrupted (SIGTERM)") << line;
  }
  EXPECT_EQ(after, 5);
}

TEST(LiveStream, NoOutOfLimitOrOverSpeedLineReachesThePortWhenTheInputJumps) {
  Rig rig;
  LiveStreamOptions o;
  o.planner.max_jump_deg_s = 20000;  // let the jumps through to the limits and the speed check
  o.planner.limits.min_deg[1] = -120;
  o.planner.limits.max_deg[2] = 0;
  o.planner.limits.min_deg[2] = -100;
  ASSERT_TRUE(rig.Begin(o).ok());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> any(-180, 180);
  double upper = -90, bend = 0;
  for (int f = 0; f < 450; ++f) {
    if (f % 9 == 0) {
      upper = any(rng);
      bend = any(rng);
    }
    rig.Frame(Row(f, upper, bend, f % 31 == 0));
  }
  const JointLimits& lim = o.planner.limits;
  ASSERT_GT(rig.controller.moves.size(), 10u);
  for (std::size_t i = 0; i < rig.controller.moves.size(); ++i) {
    const auto& [t, q] = rig.controller.moves[i];
    for (int j = 0; j < kJoints; ++j) {
      EXPECT_TRUE(lim.Inside(j, q[j])) << "move " << i << " J" << j + 1 << " = " << q[j];
      if (i == 0) continue;
      const auto& [t0, q0] = rig.controller.moves[i - 1];
      EXPECT_LE(std::abs(q[j] - q0[j]), lim.max_speed_deg_s[j] * (t - t0) + 0.011)
          << "move " << i << " J" << j + 1 << " too fast";
    }
  }
  EXPECT_GT(rig.stream.planner().stats().limit_holds, 0);
  EXPECT_GT(rig.stream.planner().stats().rate_limited, 0);
  EXPECT_FALSE(rig.protocol.finished()) << rig.protocol.error_message();
}

TEST(LiveStream, ADryRunWritesTheSpeedLineFirstAndChecksEveryLine) {
  LiveStream stream;
  LiveStreamOptions o;
  ASSERT_TRUE(stream.Begin(o).ok());
  std::vector<std::string> lines;
  stream.SetWriter([&](const LinkLine& l) { lines.push_back(l.text); });
  stream.SendOpening();
  for (int f = 0; f < 60; ++f)
    stream.OnFrame(Row(f, -90 + 2.0 * f, 0), f / kFps, f / kFps, f / kFps);
  ASSERT_GT(lines.size(), 3u);
  EXPECT_EQ(lines[0], "SPEED 75");
  EXPECT_EQ(lines[1].rfind("DO MOVE #PPOINT(", 0), 0u) << lines[1];
  EXPECT_FALSE(stream.stopped()) << stream.stop_reason();
}

}  // namespace
}  // namespace armmimic::robot
