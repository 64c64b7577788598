// End to end over a real pseudo-terminal: armmimic-cli send talks to the emulator's pty server
// running in this process, and the emulator's log proves what the arm did.
#include <chrono>
#include <cmath>
#include <future>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/sim/pty_server.h"
#include "test_program.h"
#include "test_util.h"

namespace armmimic {
namespace {

using robot::JointArray;

using test::Fast;
using test::Program;

// SPEED 50 and `moves` timed moves, each target distinct. Move i is on line 5 + 2 i.
Program MakeProgram(int moves) {
  return test::MakeTimedProgram(moves, "test", [](int i) -> JointArray {
    return {std::round(std::sin(i * 0.7) * 2000) / 100, -90 + i * 3.0, -i * 2.0, 0, 0, 0};
  });
}

void ExpectJointsNear(const JointArray& got, const JointArray& want, const std::string& what) {
  for (int j = 0; j < robot::kJoints; ++j)
    EXPECT_NEAR(got[j], want[j], 0.006) << what << " J" << j + 1;
}

// Every planned target executed exactly once, in order.
void ExpectExactlyOnce(const std::vector<sim::LoggedMove>& log, const Program& p) {
  ASSERT_EQ(log.size(), p.targets.size());
  for (std::size_t i = 0; i < log.size(); ++i) {
    ExpectJointsNear(log[i].target_deg, p.targets[i], "move " + std::to_string(i + 1));
  }
}

class SendE2E : public ::testing::Test {
 protected:
  void Write(const Program& p) { test::WriteFile(val_, p.text); }
  test::CliResult Send(const std::string& port, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"--no-progress", "send", val_, "--port", port};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::RunCli(args);
  }
  test::TempDir dir_;
  std::string val_ = dir_.file("prog.val");
};

TEST_F(SendE2E, StreamReachesTheLastTargetWithEveryMoveOnce) {
  const Program p = MakeProgram(12);
  Write(p);
  sim::PtyServer server(Fast());
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  const test::CliResult r = Send(dir_.file("puma"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectExactlyOnce(server.log(), p);
  ExpectJointsNear(server.joints(), p.targets.back(), "final");
  EXPECT_NE(test::ReadFile(val_ + ".journal").find("\ndone\n"), std::string::npos);
}

TEST_F(SendE2E, ErrorReplyMidStreamExitsOneNamingTheLine) {
  const Program p = MakeProgram(6);
  Write(p);
  sim::EmulatorOptions o = Fast();
  o.fail_after = 3;  // SPEED + 2 moves pass, the third move is refused
  sim::PtyServer server(o);
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  const test::CliResult r = Send(dir_.file("puma"));
  EXPECT_EQ(r.exit_code, 1);
  // Line 9 of prog.val is the third move.
  EXPECT_NE(r.err.find("prog.val:9"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("*Servo error*"), std::string::npos) << r.err;
  EXPECT_EQ(server.log().size(), 2u);
  // Resuming asks WHERE (the arm is still at move 2), sends move 3 again and finishes.
  const test::CliResult again = Send(dir_.file("puma"), {"--resume"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("sending this line again"), std::string::npos) << again.err;
  ExpectExactlyOnce(server.log(), p);
}

TEST_F(SendE2E, SilentControllerTimesOutThenResumeRunsEveryMoveExactlyOnce) {
  const Program p = MakeProgram(8);
  Write(p);
  sim::EmulatorOptions o = Fast();
  o.silent_after = 4;  // SPEED + 3 moves answered; move 4 runs but its reply is lost
  sim::PtyServer server(o);
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  const test::CliResult cut = Send(dir_.file("puma"), {"--motion-timeout", "1.5"});
  EXPECT_EQ(cut.exit_code, 1);
  EXPECT_NE(cut.err.find("prog.val:11"), std::string::npos) << cut.err;
  EXPECT_NE(cut.err.find("no prompt"), std::string::npos) << cut.err;
  EXPECT_NE(cut.err.find("--resume"), std::string::npos) << cut.err;
  EXPECT_EQ(server.log().size(), 4u);  // move 4 did run

  const test::CliResult resumed = Send(dir_.file("puma"), {"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("it ran"), std::string::npos) << resumed.err;
  ExpectExactlyOnce(server.log(), p);
  ExpectJointsNear(server.joints(), p.targets.back(), "final");

  const test::CliResult nothing = Send(dir_.file("puma"), {"--resume"});
  EXPECT_EQ(nothing.exit_code, 0);
  EXPECT_NE(nothing.out.find("nothing to resume"), std::string::npos) << nothing.out;
  ExpectExactlyOnce(server.log(), p);
}

TEST_F(SendE2E, ArmMovedByHandAfterACutIsLeftToTheOperator) {
  const Program p = MakeProgram(5);
  Write(p);
  sim::EmulatorOptions o = Fast();
  o.silent_after = 3;  // move 3 (prog.val:9) runs, its reply is lost
  sim::PtyServer server(o);
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  EXPECT_EQ(Send(dir_.file("puma"), {"--motion-timeout", "1.5"}).exit_code, 1);
  // Someone jogs joint 1 from a terminal before the operator resumes.
  const int fd = open(dir_.file("puma").c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  const std::string jog = "DO DRIVE 1,7,50\r";
  ASSERT_EQ(write(fd, jog.data(), jog.size()), static_cast<ssize_t>(jog.size()));
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (server.log().size() < 4 && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  close(fd);
  ASSERT_EQ(server.log().size(), 4u);

  const test::CliResult unsure = Send(dir_.file("puma"), {"--resume"});
  EXPECT_EQ(unsure.exit_code, 1);
  EXPECT_NE(unsure.err.find("prog.val:9: cannot tell whether this line ran"), std::string::npos)
      << unsure.err;
  EXPECT_NE(unsure.err.find("--resume-at: "), std::string::npos) << unsure.err;
  EXPECT_NE(unsure.err.find("resume at line 9"), std::string::npos) << unsure.err;
  EXPECT_EQ(server.log().size(), 4u);  // WHERE moved nothing

  // The operator decides move 3 ran and skips it.
  const test::CliResult skip = Send(dir_.file("puma"), {"--resume-at", "11"});
  ASSERT_EQ(skip.exit_code, 0) << skip.err;
  const auto log = server.log();
  ASSERT_EQ(log.size(), 6u);
  ExpectJointsNear(log[4].target_deg, p.targets[3], "move 4");
  ExpectJointsNear(server.joints(), p.targets.back(), "final");
}

TEST_F(SendE2E, PlainSendAfterAnInterruptedOneRefusesUntilTheOperatorChooses) {
  const Program p = MakeProgram(4);
  Write(p);
  sim::EmulatorOptions o = Fast();
  o.fail_after = 2;
  sim::PtyServer server(o);
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  EXPECT_EQ(Send(dir_.file("puma")).exit_code, 1);
  EXPECT_EQ(server.log().size(), 1u);
  // A plain send must not replay the move already made.
  const test::CliResult again = Send(dir_.file("puma"));
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_NE(again.err.find("--resume"), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("--restart"), std::string::npos) << again.err;
  EXPECT_EQ(server.log().size(), 1u);
  // --restart is the explicit choice to start over: the first move is replayed.
  const test::CliResult restart = Send(dir_.file("puma"), {"--restart"});
  ASSERT_EQ(restart.exit_code, 0) << restart.err;
  EXPECT_EQ(server.log().size(), 1u + p.targets.size());
  ExpectJointsNear(server.joints(), p.targets.back(), "final");
}

TEST_F(SendE2E, NoiseOnTheLineDoesNotStopTheStream) {
  const Program p = MakeProgram(5);
  Write(p);
  sim::EmulatorOptions o = Fast();
  o.garble_after = 0;
  sim::PtyServer server(o);
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  const test::CliResult r = Send(dir_.file("puma"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectExactlyOnce(server.log(), p);
  // Counted and reported once, not per line.
  EXPECT_NE(r.err.find("unexpected lines from the controller ignored"), std::string::npos) << r.err;
}

TEST_F(SendE2E, ControllersEndingLinesWithLfOrCrAloneWorkToo) {
  const Program p = MakeProgram(4);
  Write(p);
  for (const char* newline : {"\n", "\r"}) {
    sim::EmulatorOptions o = Fast();
    o.newline = newline;
    sim::PtyServer server(o);
    ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
    const test::CliResult r = Send(dir_.file("puma"), {"--restart"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ExpectExactlyOnce(server.log(), p);
  }
}

TEST_F(SendE2E, ProgramModeUploadsThenExecutes) {
  const std::string text =
      "; armmimic VAL program v1\nSPEED 50\nEDIT MIMIC\nSPEED 100\n"
      "MOVE #PPOINT(5.00,-85.00,-2.00,0.00,0.00,0.00)\n"
      "MOVE #PPOINT(10.00,-80.00,-4.00,0.00,0.00,0.00)\nE\nEXECUTE MIMIC\n";
  test::WriteFile(val_, text);
  sim::PtyServer server(Fast());
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  const test::CliResult r = Send(dir_.file("puma"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(server.log().size(), 2u);
  ExpectJointsNear(server.joints(), {10, -80, -4, 0, 0, 0}, "final");
}

TEST_F(SendE2E, AngleFileIsPlannedAndTheArmEndsAtThePlannedLastTarget) {
  std::ostringstream s;
  s << kAngleFileMagic << "\n# engine=bgsub source=test.avi fps=10\n"
    << kAngleFileUnits << "\n"
    << "frame\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\tupper_cx\tupper_cy\t"
       "fore_cx\tfore_cy\n";
  for (int i = 0; i < 30; ++i) {
    const double upper = -90 + i * 1.0, fore = -90 + i * 2.0;
    s << i << "\t" << FormatNumber(i / 10.0, 4) << "\tok\t" << FormatNumber(upper, 3) << "\t"
      << FormatNumber(fore, 3) << "\tnan\t" << FormatNumber(fore - upper, 3)
      << "\tnan\tnan\tnan\tnan\n";
  }
  const std::string angles = dir_.file("angles.tsv");
  test::WriteFile(angles, s.str());
  const test::CliResult dry = test::RunCli({"send", angles, "--dry-run"});
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  JointArray last{};
  bool found = false;
  std::istringstream lines(dry.out);
  for (std::string line; std::getline(lines, line);) {
    found |= robot::ParsePpointTarget(line.substr(line.rfind('\t') + 1), &last);
  }
  ASSERT_TRUE(found) << dry.out;
  sim::PtyServer server(Fast());
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  const test::CliResult r =
      test::RunCli({"--no-progress", "send", angles, "--port", dir_.file("puma")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GE(server.log().size(), 2u);
  ExpectJointsNear(server.joints(), last, "final");
  EXPECT_TRUE(test::ReadFile(angles + ".journal").size() > 0);
}

TEST_F(SendE2E, VanishedDeviceStopsWithAClearMessage) {
  const Program p = MakeProgram(20);
  Write(p);
  sim::EmulatorOptions o;
  o.time_scale = 2;  // slow enough to pull the plug mid-stream
  auto server = std::make_unique<sim::PtyServer>(o);
  ASSERT_TRUE(server->Start(dir_.file("puma")).ok());
  auto run = std::async(std::launch::async, [&] { return Send(dir_.file("puma")); });
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (server->log().size() < 2 && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  server->Stop();
  const test::CliResult r = run.get();
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("connection was lost"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(dir_.file("puma")), std::string::npos) << r.err;
}

TEST_F(SendE2E, UnsafeLineInAHandEditedProgramNeverReachesThePort) {
  Program p = MakeProgram(3);
  p.text += "; t=3.000\nDO MOVE #PPOINT(0.00,40.00,0.00,0.00,0.00,0.00)\n";  // J2 above 20
  Write(p);
  sim::PtyServer server(Fast());
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  const test::CliResult r = Send(dir_.file("puma"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("prog.val:11"), std::string::npos) << r.err;
  EXPECT_EQ(server.lines_received(), 0);  // refused before the port was opened
  EXPECT_TRUE(server.log().empty());
}

TEST_F(SendE2E, MissingPortIsNamed) {
  Write(MakeProgram(1));
  const test::CliResult r = Send(dir_.file("no-such-tty"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--port: " + dir_.file("no-such-tty")), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no such serial port"), std::string::npos) << r.err;
}

TEST_F(SendE2E, PermissionDeniedIsNamed) {
  // As root every device opens: the CLI then runs as nobody (setpriv).
  // setpriv is part of util-linux, which every Debian system has: a test never skips.
  ASSERT_TRUE(test::CanRunUnprivileged()) << "cannot drop root here (no /usr/bin/setpriv)";
  chmod(dir_.path().c_str(), 0777);
  Write(MakeProgram(1));
  // A real terminal device that only its owner (root) may open.
  sim::PtyServer server(Fast());
  ASSERT_TRUE(server.Start().ok());
  const std::string locked = server.device_path();
  ASSERT_EQ(chmod(locked.c_str(), 0600), 0);
  const test::CliResult r =
      test::RunCliUnprivileged({"--no-progress", "send", val_, "--port", locked});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("permission denied"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(locked), std::string::npos) << r.err;
}

TEST_F(SendE2E, BusyPortIsNamed) {
  Write(MakeProgram(30));
  test::WriteFile(dir_.file("other.val"), MakeProgram(1).text);
  sim::EmulatorOptions o;
  o.time_scale = 3;  // the first send is still running when the second one tries the port
  sim::PtyServer server(o);
  ASSERT_TRUE(server.Start(dir_.file("puma")).ok());
  auto run = std::async(std::launch::async, [&] { return Send(dir_.file("puma")); });
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (server.log().empty() && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const test::CliResult second =
      test::RunCli({"send", dir_.file("other.val"), "--port", dir_.file("puma")});
  server.Stop();
  run.get();
  EXPECT_EQ(second.exit_code, 1);
  EXPECT_NE(second.err.find("busy"), std::string::npos) << second.err;
  EXPECT_NE(second.err.find("--port: " + dir_.file("puma")), std::string::npos) << second.err;
}

}  // namespace
}  // namespace armmimic
