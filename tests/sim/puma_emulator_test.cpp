#include "armmimic/sim/puma_emulator.h"

#include <cmath>

#include <gtest/gtest.h>

#include "armmimic/robot/link_protocol.h"

namespace armmimic::sim {
namespace {

using robot::JointArray;

EmulatorOptions Fast() {
  EmulatorOptions o;
  o.time_scale = 0.01;
  return o;
}

// Feeds a line and advances time until the emulator is idle; returns everything it printed.
std::string Say(PumaEmulator& emu, const std::string& line, double* now) {
  std::string out = emu.Feed(line + "\r", *now);
  for (int i = 0; i < 100000 && emu.busy(); ++i) {
    *now += 0.001;
    out += emu.Tick(*now);
  }
  return out;
}

TEST(PumaEmulator, WakesWithThePromptAndEchoesEveryLine) {
  PumaEmulator emu(Fast());
  double now = 0;
  EXPECT_EQ(emu.Feed("\r", now), "\r\n.");
  EXPECT_EQ(Say(emu, "SPEED 50", &now), "SPEED 50\r\n.");
  EXPECT_EQ(Say(emu, "WHERE", &now),
            "WHERE\r\n     JT1       JT2       JT3       JT4       JT5       JT6\r\n"
            "     0.000   -90.000     0.000     0.000     0.000     0.000\r\n.");
}

TEST(PumaEmulator, MoveReachesTheTargetAndPromptsOnlyWhenDone) {
  EmulatorOptions o;
  o.time_scale = 1.0;
  o.settle_s = 0;
  PumaEmulator emu(o);
  double now = 0;
  emu.Feed("SPEED 50\r", now);
  // J1 by 30 deg at 60 deg/s * 50 % = 1 s.
  EXPECT_EQ(emu.Feed("DO MOVE #PPOINT(30,-90,0,0,0,0)\r", now),
            "DO MOVE #PPOINT(30,-90,0,0,0,0)\r\n");
  EXPECT_EQ(emu.Tick(0.5), "");
  EXPECT_NEAR(emu.joints()[0], 15, 1e-9);
  EXPECT_EQ(emu.Tick(1.0), ".");
  EXPECT_EQ(emu.joints(), (JointArray{30, -90, 0, 0, 0, 0}));
  ASSERT_EQ(emu.log().size(), 1u);
  EXPECT_NEAR(emu.log()[0].end_s - emu.log()[0].start_s, 1.0, 1e-9);
}

TEST(PumaEmulator, DriveMovesOneJointRelative) {
  PumaEmulator emu(Fast());
  double now = 0;
  Say(emu, "DO DRIVE 2,-10,50", &now);
  EXPECT_EQ(emu.joints(), (JointArray{0, -100, 0, 0, 0, 0}));
  EXPECT_NE(Say(emu, "DO DRIVE 7,1,50", &now).find("*Invalid joint*"), std::string::npos);
}

TEST(PumaEmulator, CommandsAbbreviateToAnyUniquePrefix) {
  PumaEmulator emu(Fast());
  double now = 0;
  EXPECT_EQ(Say(emu, "SP 20", &now), "SP 20\r\n.");
  EXPECT_EQ(Say(emu, "do mo #ppoint(1,-90,0,0,0,0)", &now), "do mo #ppoint(1,-90,0,0,0,0)\r\n.");
  EXPECT_EQ(emu.joints()[0], 1);
  EXPECT_EQ(Say(emu, "WH", &now).substr(0, 4), "WH\r\n");
  EXPECT_EQ(Say(emu, "E", &now), "E\r\n*Ambiguous command*\r\n.");
}

TEST(PumaEmulator, RefusesUnknownCommandsBadSyntaxAndTargetsOutOfRange) {
  PumaEmulator emu(Fast());
  double now = 0;
  EXPECT_EQ(Say(emu, "FLY AWAY", &now), "FLY AWAY\r\n*Unknown command*\r\n.");
  EXPECT_EQ(Say(emu, "DO MOVE #PPOINT(1,2,3)", &now),
            "DO MOVE #PPOINT(1,2,3)\r\n*Syntax error*\r\n.");
  EXPECT_EQ(Say(emu, "DO MOVE #PPOINT(0,30,0,0,0,0)", &now),
            "DO MOVE #PPOINT(0,30,0,0,0,0)\r\n*Joint 2 out of range*\r\n.");
  EXPECT_EQ(Say(emu, "SPEED 0", &now), "SPEED 0\r\n*Value out of range*\r\n.");
  const std::string long_line = "DO MOVE #PPOINT(" + std::string(80, '1') + ")";
  EXPECT_NE(Say(emu, long_line, &now).find("*Line too long*"), std::string::npos);
  EXPECT_TRUE(emu.log().empty());
  EXPECT_EQ(emu.joints(), (JointArray{0, -90, 0, 0, 0, 0}));
}

TEST(PumaEmulator, EditsAndExecutesAProgram) {
  PumaEmulator emu(Fast());
  double now = 0;
  EXPECT_EQ(Say(emu, "EDIT MIMIC", &now), "EDIT MIMIC\r\n1? ");
  EXPECT_EQ(Say(emu, "SPEED 50", &now), "SPEED 50\r\n2? ");
  EXPECT_EQ(Say(emu, "MOVE #PPOINT(10,-80,5,0,0,0)", &now), "MOVE #PPOINT(10,-80,5,0,0,0)\r\n3? ");
  EXPECT_EQ(Say(emu, "MOVE #PPOINT(20,-70,5,0,0,0)", &now), "MOVE #PPOINT(20,-70,5,0,0,0)\r\n4? ");
  EXPECT_EQ(Say(emu, "E", &now), "E\r\n.");
  EXPECT_TRUE(emu.log().empty());  // nothing moves while editing
  EXPECT_EQ(Say(emu, "EXECUTE MIMIC", &now), "EXECUTE MIMIC\r\n*\r\nPROGRAM COMPLETED: MIMIC\r\n.");
  ASSERT_EQ(emu.log().size(), 2u);
  EXPECT_EQ(emu.joints(), (JointArray{20, -70, 5, 0, 0, 0}));
  EXPECT_EQ(Say(emu, "EXECUTE NOPE", &now), "EXECUTE NOPE\r\n*Undefined program*\r\n.");
}

TEST(PumaEmulator, AbortStopsARunningProgram) {
  EmulatorOptions o;
  o.time_scale = 1;
  PumaEmulator emu(o);
  double now = 0;
  for (const char* l : {"EDIT P", "MOVE #PPOINT(60,-90,0,0,0,0)", "E"}) Say(emu, l, &now);
  emu.Feed("EXECUTE P\r", now);
  now += 0.5;
  const std::string out = emu.Feed("ABORT\r", now);
  EXPECT_NE(out.find("PROGRAM ABORTED: P"), std::string::npos) << out;
  EXPECT_FALSE(emu.busy());
  EXPECT_NEAR(emu.joints()[0], 60 * 0.5 / 1.05, 1e-6);  // 1 s of motion plus 0.05 s settling
}

TEST(PumaEmulator, FaultErrorAfterNLinesIsOneShotAndNotExecuted) {
  EmulatorOptions o = Fast();
  o.fail_after = 1;
  PumaEmulator emu(o);
  double now = 0;
  Say(emu, "SPEED 50", &now);
  EXPECT_EQ(Say(emu, "DO MOVE #PPOINT(5,-90,0,0,0,0)", &now),
            "DO MOVE #PPOINT(5,-90,0,0,0,0)\r\n*Servo error*\r\n.");
  EXPECT_TRUE(emu.log().empty());
  EXPECT_EQ(Say(emu, "DO MOVE #PPOINT(5,-90,0,0,0,0)", &now),
            "DO MOVE #PPOINT(5,-90,0,0,0,0)\r\n.");
  EXPECT_EQ(emu.log().size(), 1u);
}

TEST(PumaEmulator, FaultSilenceExecutesThenSaysNothingUntilReconnect) {
  EmulatorOptions o = Fast();
  o.silent_after = 1;
  PumaEmulator emu(o);
  double now = 0;
  Say(emu, "SPEED 50", &now);
  EXPECT_EQ(Say(emu, "DO MOVE #PPOINT(5,-90,0,0,0,0)", &now), "");
  EXPECT_EQ(emu.log().size(), 1u);  // it ran
  EXPECT_EQ(Say(emu, "WHERE", &now), "");
  emu.OnDisconnect();
  EXPECT_NE(Say(emu, "WHERE", &now).find("5.000"), std::string::npos);
}

TEST(PumaEmulator, FaultGarbleSendsNoiseBeforeEveryPrompt) {
  EmulatorOptions o = Fast();
  o.garble_after = 0;
  PumaEmulator emu(o);
  double now = 0;
  const std::string out = Say(emu, "SPEED 50", &now);
  EXPECT_EQ(out.rfind("SPEED 50\r\n", 0), 0u);
  EXPECT_GT(out.size(), std::string("SPEED 50\r\n.").size());
  EXPECT_EQ(out.back(), '.');
}

TEST(PumaEmulator, PartialLinesWaitForTheirEndAndCrLfCountsOnce) {
  PumaEmulator emu(Fast());
  EXPECT_EQ(emu.Feed("SPE", 0), "");
  EXPECT_EQ(emu.Feed("ED 40\r\n", 0), "SPEED 40\r\n.");  // the LF adds no empty line
  EXPECT_EQ(emu.Feed("\n", 0), "\r\n.");                 // a lone LF is a line
}

// The protocol and the emulator talk in simulated time: the final joint state equals the last
// target and every move ran once, in order.
TEST(PumaEmulator, StreamsAProgramThroughTheLinkProtocol) {
  PumaEmulator emu(Fast());
  std::vector<robot::LinkLine> lines;
  std::vector<JointArray> targets;
  lines.push_back({"SPEED 80", 1, 0, 2});
  for (int i = 0; i < 20; ++i) {
    JointArray t = {std::sin(i * 0.3) * 40, -90 + i * 2.5, -i * 3.0, 0, 0, 0};
    targets.push_back(t);
    char buf[128];
    std::snprintf(buf, sizeof(buf), "DO MOVE #PPOINT(%.2f,%.2f,%.2f,0.00,0.00,0.00)", t[0], t[1],
                  t[2]);
    lines.push_back({buf, i + 2, i + 1, 5});
  }
  robot::LinkProtocol link;
  link.Start(lines, "prog.val", 0);
  double now = 0;
  for (int step = 0; step < 200000 && !link.finished(); ++step) {
    now += 0.001;
    const std::string out = link.TakeOutput();
    std::string back = out.empty() ? emu.Tick(now) : emu.Feed(out, now);
    if (!back.empty()) link.OnBytes(back, now);
    link.OnTick(now);
  }
  ASSERT_EQ(link.state(), robot::LinkState::kDone) << link.error_message();
  ASSERT_EQ(emu.log().size(), targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i) {
    for (int j = 0; j < robot::kJoints; ++j) {
      EXPECT_NEAR(emu.log()[i].target_deg[j], targets[i][j], 0.006) << "move " << i;
    }
  }
  for (int j = 0; j < robot::kJoints; ++j) EXPECT_NEAR(emu.joints()[j], targets.back()[j], 0.006);
}

}  // namespace
}  // namespace armmimic::sim
