#include "armmimic/robot/link_protocol.h"

#include <gtest/gtest.h>

namespace armmimic::robot {
namespace {

std::vector<LinkLine> Lines(const std::vector<std::string>& texts) {
  std::vector<LinkLine> lines;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    LinkLine l;
    l.text = texts[i];
    l.line_no = static_cast<int>(i) + 5;
    l.index = static_cast<int>(i);
    l.timeout_s = 2;
    lines.push_back(l);
  }
  return lines;
}

// Starts a protocol on `texts` and completes the wake-up with a plain prompt.
struct Fixture {
  explicit Fixture(const std::vector<std::string>& texts, LinkSettings settings = {})
      : link(settings) {
    link.SetAckCallback([this](const LinkLine& l, const std::vector<std::string>& replies) {
      acked.push_back(l.line_no);
      all_replies.insert(all_replies.end(), replies.begin(), replies.end());
    });
    link.Start(Lines(texts), "prog.val", 0.0);
    EXPECT_EQ(link.TakeOutput(), "\r");
    link.OnBytes("\r\n.", 0.01);
  }
  LinkProtocol link;
  std::vector<int> acked;
  std::vector<std::string> all_replies;
};

TEST(LinkProtocol, WakesThenSendsOneLineAtATimeAfterEchoAndPrompt) {
  Fixture f({"SPEED 50", "DO MOVE #PPOINT(1,2,3,4,5,6)"});
  EXPECT_EQ(f.link.TakeOutput(), "SPEED 50\r");
  f.link.OnBytes("SPEED 50\r\n", 0.02);
  EXPECT_EQ(f.link.TakeOutput(), "");  // echo alone is not enough
  EXPECT_EQ(f.link.acknowledged(), 0u);
  ASSERT_NE(f.link.in_flight(), nullptr);
  f.link.OnBytes(".", 0.03);
  EXPECT_EQ(f.link.acknowledged(), 1u);
  EXPECT_EQ(f.link.TakeOutput(), "DO MOVE #PPOINT(1,2,3,4,5,6)\r");
  f.link.OnBytes("DO MOVE #PPOINT(1,2,3,4,5,6)\r\n.", 1.0);
  EXPECT_EQ(f.link.state(), LinkState::kDone);
  EXPECT_EQ(f.acked, (std::vector<int>{5, 6}));
  EXPECT_EQ(f.link.in_flight(), nullptr);
}

TEST(LinkProtocol, EchoSplitAcrossManyReads) {
  Fixture f({"DO MOVE #PPOINT(10.00,-90.00,0.00,0.00,0.00,0.00)"});
  f.link.TakeOutput();
  const std::string reply = "DO MOVE #PPOINT(10.00,-90.00,0.00,0.00,0.00,0.00)\r\n.";
  for (std::size_t i = 0; i < reply.size(); ++i) {
    EXPECT_EQ(f.link.state(), LinkState::kWaitingReply) << "at byte " << i;
    f.link.OnBytes(reply.substr(i, 1), 0.1 + i * 0.001);
  }
  EXPECT_EQ(f.link.state(), LinkState::kDone);
}

TEST(LinkProtocol, AcceptsCrLfCrAndLfLineEndsAndPromptOnItsOwnLine) {
  for (const std::string nl : {"\r\n", "\r", "\n", "\n\r", "\r\r\n"}) {
    Fixture f({"SPEED 50", "SPEED 60", "SPEED 70"});
    f.link.OnBytes("SPEED 50" + nl + "." + nl, 0.1);
    f.link.OnBytes(nl + "SPEED 60" + nl + nl + "." + nl, 0.2);
    f.link.OnBytes("SPEED 70" + nl, 0.3);
    f.link.OnBytes(".", 0.3);
    EXPECT_EQ(f.link.state(), LinkState::kDone) << "line end " << static_cast<int>(nl[0]);
  }
}

TEST(LinkProtocol, PromptGluedToTheEchoOnTheSameLine) {
  Fixture f({"SPEED 50", "SPEED 60"});
  f.link.OnBytes("SPEED 50.", 0.1);
  EXPECT_EQ(f.link.acknowledged(), 1u);
  f.link.OnBytes("SPEED 60 .\r\n", 0.2);
  EXPECT_EQ(f.link.state(), LinkState::kDone);
}

TEST(LinkProtocol, EchoWithTheControllersCaseAndSpacingStillMatches) {
  Fixture f({"do move #ppoint(1,2,3,4,5,6)"});
  f.link.OnBytes(".DO  MOVE #PPOINT(1,2,3,4,5,6)\r\n.", 0.1);
  EXPECT_EQ(f.link.state(), LinkState::kDone);
}

TEST(LinkProtocol, ErrorReplyStopsTheStreamWithTheControllersTextAndTheLine) {
  Fixture f({"SPEED 50", "DO MOVE #PPOINT(0,90,0,0,0,0)", "SPEED 60"});
  f.link.OnBytes("SPEED 50\r\n.", 0.1);
  EXPECT_EQ(f.link.TakeOutput(), "SPEED 50\rDO MOVE #PPOINT(0,90,0,0,0,0)\r");
  f.link.OnBytes("DO MOVE #PPOINT(0,90,0,0,0,0)\r\n*Joint 2 out of range*\r\n.", 0.2);
  EXPECT_EQ(f.link.state(), LinkState::kFailed);
  EXPECT_EQ(f.link.error(), LinkError::kControllerError);
  EXPECT_EQ(f.link.controller_text(), "*Joint 2 out of range*");
  EXPECT_NE(f.link.error_message().find("prog.val:6"), std::string::npos) << f.link.error_message();
  EXPECT_NE(f.link.error_message().find("*Joint 2 out of range*"), std::string::npos);
  EXPECT_EQ(f.link.acknowledged(), 1u);
  EXPECT_EQ(f.link.TakeOutput(), "");  // nothing after the error
}

TEST(LinkProtocol, ErrorInsteadOfTheEchoAlsoStops) {
  Fixture f({"FOO"});
  f.link.OnBytes("*Unknown command*\r\n.", 0.1);
  EXPECT_EQ(f.link.error(), LinkError::kControllerError);
}

TEST(LinkProtocol, SilenceAfterALineTimesOutNamingTheLine) {
  Fixture f({"SPEED 50", "DO MOVE #PPOINT(1,2,3,4,5,6)"});
  f.link.OnBytes("SPEED 50\r\n.", 0.1);
  f.link.OnTick(1.0);
  EXPECT_EQ(f.link.state(), LinkState::kWaitingReply);
  f.link.OnTick(2.2);  // 2 s timeout after the write at 0.1
  EXPECT_EQ(f.link.state(), LinkState::kFailed);
  EXPECT_EQ(f.link.error(), LinkError::kTimeout);
  EXPECT_NE(f.link.error_message().find("prog.val:6"), std::string::npos) << f.link.error_message();
  EXPECT_NE(f.link.error_message().find("echo never came back"), std::string::npos);
  ASSERT_NE(f.link.in_flight(), nullptr);
  EXPECT_EQ(f.link.in_flight()->line_no, 6);
}

TEST(LinkProtocol, WakeRetriesTheCarriageReturnThenGivesUp) {
  LinkSettings s;
  s.wake_attempts = 3;
  s.wake_timeout_s = 1;
  LinkProtocol link(s);
  link.Start(Lines({"SPEED 50"}), "prog.val", 0);
  EXPECT_EQ(link.TakeOutput(), "\r");
  link.OnTick(1.01);
  EXPECT_EQ(link.TakeOutput(), "\r");
  link.OnTick(2.02);
  EXPECT_EQ(link.TakeOutput(), "\r");
  EXPECT_EQ(link.state(), LinkState::kWaking);
  link.OnTick(3.03);
  EXPECT_EQ(link.error(), LinkError::kNotReady);
  EXPECT_NE(link.error_message().find("prog.val"), std::string::npos);
  EXPECT_EQ(link.TakeOutput(), "");
}

TEST(LinkProtocol, WakeSeesARunningProgramAndSaysSo) {
  LinkProtocol link;
  link.Start(Lines({"SPEED 50"}), "prog.val", 0);
  link.OnBytes("\r\n*", 0.01);
  EXPECT_EQ(link.state(), LinkState::kWaking);  // could still be "*Servo error*"
  link.OnTick(0.5);
  EXPECT_EQ(link.error(), LinkError::kNotReady);
  EXPECT_NE(link.error_message().find("running a program"), std::string::npos);
}

TEST(LinkProtocol, GarbageAndStalePromptsBetweenLinesAreSkipped) {
  LinkProtocol link;
  link.Start(Lines({"SPEED 50", "SPEED 60"}), "prog.val", 0);
  link.TakeOutput();
  link.OnTick(1.6);  // a second wake CR
  // Both wake prompts arrive; the second one is stale once line 1 is out.
  link.OnBytes("\r\n.\r\n.", 1.7);
  EXPECT_EQ(link.TakeOutput(), "\rSPEED 50\r");
  link.OnBytes("~#}@!\r\nSPEED 50\r\n\x01\xfe%&\r\n.", 1.8);
  EXPECT_EQ(link.acknowledged(), 1u);
  EXPECT_TRUE(link.last_replies().empty());  // the garbled line is not a reply
  link.OnBytes("SPEED 60\r\n\r\n\r\n.", 1.9);
  EXPECT_EQ(link.state(), LinkState::kDone);
  EXPECT_GT(link.noise_lines(), 0);
}

TEST(LinkProtocol, StarThatStartsAnErrorLineIsNotTakenForThePrompt) {
  Fixture f({"EXECUTE MIMIC"});
  f.link.OnBytes("EXECUTE MIMIC\r\n*", 0.1);
  f.link.OnBytes("Servo error*\r\n.", 0.12);
  EXPECT_EQ(f.link.error(), LinkError::kControllerError);
  EXPECT_EQ(f.link.controller_text(), "*Servo error*");
}

TEST(LinkProtocol, ProgramRunPromptWaitsForTheTopLevelPrompt) {
  Fixture f({"EXECUTE MIMIC", "WHERE"});
  f.link.OnBytes("EXECUTE MIMIC\r\n*", 0.1);
  f.link.OnTick(0.5);
  EXPECT_EQ(f.link.acknowledged(), 0u);
  f.link.OnBytes("\r\n\r\nPROGRAM COMPLETED: MIMIC\r\n.", 1.5);
  EXPECT_EQ(f.link.acknowledged(), 1u);
  EXPECT_EQ(f.link.last_replies(), (std::vector<std::string>{"PROGRAM COMPLETED: MIMIC"}));
  f.link.OnBytes("WHERE\r\n  JT1 JT2 JT3 JT4 JT5 JT6\r\n  1.000 -90.000 2.5 0 0 -1\r\n.", 1.6);
  EXPECT_EQ(f.link.state(), LinkState::kDone);
  JointArray j{};
  ASSERT_TRUE(ParseWhereReply(f.link.last_replies(), &j));
  EXPECT_EQ(j, (JointArray{1, -90, 2.5, 0, 0, -1}));
}

TEST(LinkProtocol, EditorLineNumberPromptsAcknowledgeProgramLines) {
  Fixture f({"EDIT MIMIC", "MOVE #PPOINT(1,2,3,4,5,6)", "E"});
  f.link.OnBytes("EDIT MIMIC\r\n1? ", 0.1);
  f.link.OnBytes("MOVE #PPOINT(1,2,3,4,5,6)\r\n2? ", 0.2);
  f.link.OnBytes("E\r\n.", 0.3);
  EXPECT_EQ(f.link.state(), LinkState::kDone);
}

TEST(LinkProtocol, ProfileWithoutEchoAcknowledgesOnThePrompt) {
  LinkSettings s;
  s.echo = false;
  Fixture f({"SPEED 50"}, s);
  f.link.OnBytes("\r\n.", 0.1);
  EXPECT_EQ(f.link.state(), LinkState::kDone);
}

TEST(LinkProtocol, GateRefusesALineAndNothingIsWritten) {
  LinkProtocol link;
  link.SetGate([](const LinkLine& l) {
    return l.text.find("999") != std::string::npos ? std::string("J2 out of limits") : "";
  });
  link.Start(Lines({"SPEED 50", "DO MOVE #PPOINT(0,999,0,0,0,0)"}), "prog.val", 0);
  link.TakeOutput();
  link.OnBytes("\r\n.", 0.1);
  EXPECT_EQ(link.TakeOutput(), "SPEED 50\r");
  link.OnBytes("SPEED 50\r\n.", 0.2);
  EXPECT_EQ(link.TakeOutput(), "");
  EXPECT_EQ(link.error(), LinkError::kRefused);
  EXPECT_NE(link.error_message().find("prog.val:6"), std::string::npos);
  EXPECT_EQ(link.in_flight(), nullptr);
}

TEST(LinkProtocol, AbortStopsAndKeepsTheLineInFlight) {
  Fixture f({"DO MOVE #PPOINT(1,2,3,4,5,6)"});
  f.link.Abort("/dev/ttyS0: the device vanished");
  EXPECT_EQ(f.link.error(), LinkError::kAborted);
  ASSERT_NE(f.link.in_flight(), nullptr);
}

TEST(LinkProtocol, ACallbackThatAbortsStopsBeforeTheNextWrite) {
  LinkProtocol link;
  link.SetAckCallback([&](const LinkLine& l, const std::vector<std::string>&) {
    if (l.line_no == 5) link.Abort("journal full");
  });
  link.Start(Lines({"SPEED 50", "SPEED 60"}), "prog.val", 0);
  link.TakeOutput();
  link.OnBytes("\r\n.", 0.1);
  EXPECT_EQ(link.TakeOutput(), "SPEED 50\r");
  link.OnBytes("SPEED 50\r\n.", 0.2);
  EXPECT_EQ(link.TakeOutput(), "");
  EXPECT_EQ(link.error(), LinkError::kAborted);

  LinkProtocol refuse;
  refuse.SetSentCallback([&](const LinkLine&) { refuse.Abort("cannot write the journal"); });
  refuse.Start(Lines({"SPEED 50"}), "prog.val", 0);
  refuse.TakeOutput();
  refuse.OnBytes("\r\n.", 0.1);
  EXPECT_EQ(refuse.TakeOutput(), "");
  EXPECT_EQ(refuse.error_message(), "cannot write the journal");
}

TEST(LinkProtocol, EndlessBytesWithoutALineEndAreDroppedAsNoise) {
  Fixture f({"SPEED 50"});
  f.link.TakeOutput();
  const std::string junk(1000, '#');
  for (int i = 0; i < 100; ++i) f.link.OnBytes(junk, 0.1 + i * 0.001);
  EXPECT_EQ(f.link.state(), LinkState::kWaitingReply);
  EXPECT_GT(f.link.noise_lines(), 0);
  f.link.OnBytes("\r\nSPEED 50\r\n.", 0.3);
  EXPECT_EQ(f.link.state(), LinkState::kDone);
}

TEST(LinkHelpers, ParsesTargetsAndKnowsMotionLines) {
  JointArray j{};
  ASSERT_TRUE(ParsePpointTarget("DO MOVE #PPOINT(1.5, -90, 0,0,0, 2)", &j));
  EXPECT_EQ(j, (JointArray{1.5, -90, 0, 0, 0, 2}));
  ASSERT_TRUE(ParsePpointTarget("mo #ppoint(1,2,3,4,5,6)", &j));
  EXPECT_FALSE(ParsePpointTarget("DO MOVE #PPOINT(1,2,3,4,5)", &j));
  EXPECT_FALSE(ParsePpointTarget("SPEED 50", &j));
  EXPECT_TRUE(IsMotionLine("DO MOVE #PPOINT(1,2,3,4,5,6)"));
  EXPECT_TRUE(IsMotionLine("DO DRIVE 2,-10,50"));
  EXPECT_TRUE(IsMotionLine("EXECUTE MIMIC"));
  EXPECT_FALSE(IsMotionLine("SPEED 50"));
  EXPECT_FALSE(IsMotionLine("EDIT MIMIC"));
  EXPECT_FALSE(IsMotionLine("WHERE"));
  EXPECT_FALSE(ParseWhereReply({"JT1 JT2 JT3 JT4 JT5 JT6", "1 2 3"}, &j));
}

}  // namespace
}  // namespace armmimic::robot
