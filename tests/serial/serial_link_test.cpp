// SerialLink in-process, the way the GUI uses it: a Qt event loop, signals, the emulator's pty.
#include "armmimic/serial/serial_link.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QStringList>
#include <QTimer>
#include <filesystem>

#include <unistd.h>

#include <gtest/gtest.h>

#include "armmimic/sim/pty_server.h"
#include "test_util.h"

namespace armmimic::serial {
namespace {

QCoreApplication* App() {
  static int argc = 1;
  static char name[] = "serial_tests";
  static char* argv[] = {name, nullptr};
  static QCoreApplication* app = QCoreApplication::instance() ? QCoreApplication::instance()
                                                              : new QCoreApplication(argc, argv);
  return app;
}

// Runs the event loop until `link` finishes or 20 s pass. Returns finished()'s value.
bool RunUntilFinished(SerialLink& link, std::vector<int>* progress) {
  QEventLoop loop;
  bool ok = false;
  QObject::connect(&link, &SerialLink::finished, &loop, [&](bool result) {
    ok = result;
    loop.quit();
  });
  QObject::connect(&link, &SerialLink::progress, &loop,
                   [&](int done, int) { progress->push_back(done); });
  QTimer::singleShot(20000, &loop, [&] { loop.quit(); });
  loop.exec();
  return ok;
}

std::vector<robot::LinkLine> Moves(int count) {
  std::vector<robot::LinkLine> lines = {{"SPEED 60", 1, 0, 5}};
  for (int i = 1; i <= count; ++i) {
    lines.push_back(
        {"DO MOVE #PPOINT(" + std::to_string(i) + ",-90,0,0,0," + std::to_string(-i) + ")", i + 1,
         i, 5});
  }
  return lines;
}

// The emulator on a pseudo-terminal at `time_scale` (1: real controller timing) and a link
// opened on it with 8N1 at 9600 unless `port` says otherwise.
struct EmulatorLink {
  explicit EmulatorLink(double time_scale, PortSettings port = {})
      : server([time_scale] {
          sim::EmulatorOptions o;
          o.time_scale = time_scale;
          return o;
        }()),
        link(robot::LinkSettings{}) {
    App();
    const Status started = server.Start();
    EXPECT_TRUE(started.ok()) << started.message();
    port.port = server.device_path();
    const Status s = link.Open(port);
    EXPECT_TRUE(s.ok()) << s.message();
    opened = started.ok() && s.ok();
  }
  sim::PtyServer server;
  SerialLink link;
  bool opened = false;
};

TEST(SerialLink, StreamsToTheEmulatorAndReportsProgress) {
  PortSettings port;
  port.baud = 19200;
  port.stop_bits = 2;
  port.flow = FlowControl::kXonXoff;
  EmulatorLink e(0.02, port);
  ASSERT_TRUE(e.opened);
  SerialLink& link = e.link;
  sim::PtyServer& server = e.server;
  std::vector<int> acked_lines;
  link.protocol().SetAckCallback([&](const robot::LinkLine& l, const std::vector<std::string>&) {
    acked_lines.push_back(l.line_no);
  });
  std::vector<int> progress;
  link.Start(Moves(5), "moves.val");
  EXPECT_TRUE(RunUntilFinished(link, &progress)) << link.protocol().error_message();
  EXPECT_EQ(progress, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(acked_lines, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(server.joints(), (robot::JointArray{5, -90, 0, 0, 0, -5}));
  EXPECT_EQ(server.log().size(), 5u);
}

TEST(SerialLink, ASettingThePortRefusesIsNamed) {
  App();
  sim::PtyServer server;
  ASSERT_TRUE(server.Start().ok());
  SerialLink link(robot::LinkSettings{});
  PortSettings port;
  port.port = server.device_path();
  port.parity = 'E';  // a pseudo-terminal has no parity bit
  const Status s = link.Open(port);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.key(), "port.parity") << s.message();
  EXPECT_NE(s.message().find("parity"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find(server.device_path()), std::string::npos) << s.message();
  EXPECT_FALSE(link.is_open());
}

TEST(SerialLink, CancelStopsTheStreamAndNothingMoreIsWritten) {
  EmulatorLink e(1);
  ASSERT_TRUE(e.opened);
  SerialLink& link = e.link;
  sim::PtyServer& server = e.server;
  link.protocol().SetAckCallback([&](const robot::LinkLine& l, const std::vector<std::string>&) {
    if (l.line_no == 2) link.Cancel("stopped by the operator");
  });
  std::vector<int> progress;
  link.Start(Moves(10), "moves.val");
  EXPECT_FALSE(RunUntilFinished(link, &progress));
  EXPECT_EQ(link.protocol().error(), robot::LinkError::kAborted);
  EXPECT_EQ(link.protocol().error_message(), "stopped by the operator");
  link.Close();
  EXPECT_EQ(server.log().size(), 1u);
}

TEST(SerialLink, PauseHoldsTheNextLineAndEveryReplyLineIsReported) {
  EmulatorLink e(0.02);
  ASSERT_TRUE(e.opened);
  SerialLink& link = e.link;
  sim::PtyServer& server = e.server;
  QStringList replies;
  QObject::connect(&link, &SerialLink::lineReceived, [&](const QString& line) { replies << line; });
  bool finished = false, ok = false;
  QObject::connect(&link, &SerialLink::finished, [&](bool result) {
    finished = true;
    ok = result;
  });
  int acked = 0;
  QObject::connect(&link, &SerialLink::progress, [&](int done, int) {
    acked = done;
    if (done == 2) link.SetPaused(true);
  });
  link.Start(Moves(5), "moves.val");
  QEventLoop loop;
  auto pump = [&](int ms) {
    QTimer::singleShot(ms, &loop, [&] { loop.quit(); });
    loop.exec();
  };
  for (int i = 0; i < 200 && !link.paused() && !finished; ++i) pump(10);
  ASSERT_TRUE(link.paused());
  // Whatever the controller answers meanwhile is held: no acknowledgement, no further line.
  pump(400);
  const int received = server.lines_received();
  const std::size_t moves = server.log().size();
  pump(400);
  EXPECT_EQ(acked, 2);
  EXPECT_FALSE(finished);
  EXPECT_EQ(server.lines_received(), received);
  EXPECT_EQ(server.log().size(), moves);
  link.SetPaused(false);
  for (int i = 0; i < 2000 && !finished; ++i) pump(10);
  EXPECT_TRUE(ok) << link.protocol().error_message();
  EXPECT_EQ(acked, 6);
  EXPECT_EQ(server.joints(), (robot::JointArray{5, -90, 0, 0, 0, -5}));
  // Lines as received: the prompt the controller printed, then its echo of our line.
  EXPECT_TRUE(replies.contains(".SPEED 60")) << replies.join(" | ").toStdString();
  EXPECT_GE(replies.size(), 6);
}

TEST(SerialLink, SettingsNameTheSettingAndFlagParsersWork) {
  PortSettings p;
  EXPECT_EQ(p.Check().key(), "port.port");
  p.port = "/dev/ttyS0";
  p.data_bits = 9;
  EXPECT_EQ(p.Check().key(), "port.data_bits");
  EXPECT_NE(p.Check().message().find("data bits 9"), std::string::npos);
  FlowControl f;
  EXPECT_EQ(ParseFlowControl("RTSCTS", &f), "");
  EXPECT_EQ(f, FlowControl::kRtsCts);
  EXPECT_EQ(ParseFlowControl("xonxoff", &f), "");
  EXPECT_EQ(f, FlowControl::kXonXoff);
  EXPECT_NE(ParseFlowControl("maybe", &f), "");
  char parity = 'N';
  EXPECT_EQ(ParseParity("odd", &parity), "");
  EXPECT_EQ(parity, 'O');
  EXPECT_NE(ParseParity("mark", &parity), "");
}

// A path that is no serial device gets "not a serial port", not an ioctl error; a bare name is
// tried as given (a file in the current folder) and under /dev, and the message names both.
TEST(SerialLink, PathsThatAreNoSerialPortAreNamedPlainly) {
  App();
  test::TempDir dir;
  test::WriteFile(dir.file("reg"), "not a port");
  SerialLink link(robot::LinkSettings{});
  PortSettings port;
  port.port = "/dev/null";  // a character device, but no terminal
  Status s = link.Open(port);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.key(), "port.port");
  EXPECT_NE(s.message().find("/dev/null: /dev/null is not a serial port"), std::string::npos)
      << s.message();
  EXPECT_EQ(s.message().find("Inappropriate ioctl"), std::string::npos) << s.message();
  port.port = dir.file("reg");
  s = link.Open(port);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find(dir.file("reg") + " is not a serial port (it is a regular file)"),
            std::string::npos)
      << s.message();
  port.port = dir.path();
  s = link.Open(port);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("is not a serial port (it is a folder)"), std::string::npos)
      << s.message();

  const std::string cwd = std::filesystem::current_path().string();
  ASSERT_EQ(chdir(dir.path().c_str()), 0);
  port.port = "reg";  // a bare name: here, not /dev/reg
  const Status bare = link.Open(port);
  port.port = "no-such-port-here";
  const Status missing = link.Open(port);
  ASSERT_EQ(chdir(cwd.c_str()), 0);
  ASSERT_FALSE(bare.ok());
  EXPECT_NE(bare.message().find("reg: ./reg is not a serial port (it is a regular file)"),
            std::string::npos)
      << bare.message();
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("tried ./no-such-port-here and /dev/no-such-port-here"),
            std::string::npos)
      << missing.message();
  EXPECT_FALSE(link.is_open());
}

}  // namespace
}  // namespace armmimic::serial
