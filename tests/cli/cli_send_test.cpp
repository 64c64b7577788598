// armmimic-cli send and puma-sim as separate processes, the way an operator runs them.
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "test_util.h"

extern char** environ;

namespace armmimic {
namespace {

const char* kProgram =
    "; armmimic VAL program v1\n"
    "SPEED 50\n"
    "; t=0.000\n"
    "DO MOVE #PPOINT(0.00,-90.00,0.00,0.00,0.00,0.00)\n"
    "; t=1.000\n"
    "DO MOVE #PPOINT(12.00,-80.00,-6.00,0.00,0.00,0.00)\n"
    "; t=2.000\n"
    "DO MOVE #PPOINT(24.00,-70.00,-12.00,0.00,0.00,0.00)\n";

// `armmimic-cli puma-sim ...` in the background; its first stdout line is the device path.
class SimProcess {
 public:
  explicit SimProcess(std::vector<std::string> args) {
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, out[1], 1);
    posix_spawn_file_actions_addclose(&fa, out[0]);
    posix_spawn_file_actions_addclose(&fa, out[1]);
    args.insert(args.begin(), {ARMMIMIC_CLI_PATH, "-q", "puma-sim"});
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int rc = posix_spawn(&pid_, ARMMIMIC_CLI_PATH, &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(out[1]);
    fd_ = out[0];
    if (rc != 0) throw std::runtime_error(std::string("posix_spawn: ") + std::strerror(rc));
    device_ = ReadLine(5000);
  }
  ~SimProcess() {
    if (pid_ > 0) Stop();
    if (fd_ >= 0) close(fd_);
  }
  const std::string& device() const { return device_; }
  // SIGTERM, then everything it printed after the device path; its exit code in `code`.
  std::string Stop(int* code = nullptr) {
    kill(pid_, SIGTERM);
    std::string rest;
    char buf[512];
    ssize_t n;
    while ((n = read(fd_, buf, sizeof(buf))) > 0) rest.append(buf, static_cast<std::size_t>(n));
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    if (code) *code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return rest;
  }

 private:
  std::string ReadLine(int timeout_ms) {
    std::string line;
    char c;
    while (true) {
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, timeout_ms) <= 0 || read(fd_, &c, 1) != 1 || c == '\n') break;
      line += c;
    }
    return line;
  }
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string device_;
};

TEST(CliSend, HelpNamesEveryFlag) {
  const test::CliResult r = test::RunCli({"send", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* flag : {"--port", "--baud", "--data-bits", "--parity", "--stop-bits", "--flow",
                           "--dry-run", "--resume", "--list-ports", "--profile", "--timeout"}) {
    EXPECT_NE(r.out.find(flag), std::string::npos) << flag;
  }
  const test::CliResult sim = test::RunCli({"puma-sim", "--help"});
  EXPECT_EQ(sim.exit_code, 0);
  EXPECT_NE(sim.out.find("--link"), std::string::npos);
}

TEST(CliSend, UsageErrorsExitTwoNamingTheFlag) {
  test::TempDir dir;
  test::WriteFile(dir.file("p.val"), kProgram);
  test::CliResult r = test::RunCli({"send"});
  EXPECT_EQ(r.exit_code, 2);
  r = test::RunCli({"send", dir.file("p.val")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--port"), std::string::npos) << r.err;
  r = test::RunCli({"send", dir.file("p.val"), "--port", "/dev/null", "--flow", "smoke"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--flow"), std::string::npos) << r.err;
  r = test::RunCli({"send", dir.file("p.val"), "--port", "/dev/null", "--parity", "maybe"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--parity"), std::string::npos) << r.err;
  r = test::RunCli({"send", dir.file("p.val"), "--port", "x", "--resume", "--restart"});
  EXPECT_EQ(r.exit_code, 2);
}

TEST(CliSend, ListPortsExitsZeroAndPumaSimRefusesBadFlags) {
  const test::CliResult r = test::RunCli({"send", "--list-ports"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  test::CliResult sim = test::RunCli({"puma-sim", "--time-scale", "-1"});
  EXPECT_EQ(sim.exit_code, 2);
  EXPECT_NE(sim.err.find("--time-scale"), std::string::npos) << sim.err;
  sim = test::RunCli({"puma-sim", "--limits", "J2=5:-5"});
  EXPECT_EQ(sim.exit_code, 2);
  EXPECT_NE(sim.err.find("--limits"), std::string::npos) << sim.err;
}

TEST(CliSend, DryRunPrintsEveryLineWithItsTimeAndOpensNoPort) {
  test::TempDir dir;
  test::WriteFile(dir.file("p.val"), kProgram);
  const test::CliResult r =
      test::RunCli({"send", dir.file("p.val"), "--port", dir.file("nothing-here"), "--dry-run"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("p.val:2\tSPEED 50"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("t=2.000\t"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("DO MOVE #PPOINT(24.00,-70.00,-12.00,0.00,0.00,0.00)"), std::string::npos);
  // What the robot panel's confirmation shows: duration, start pose, ranges against the limits.
  EXPECT_NE(r.err.find("4 lines (3 motion), about 2.0 s"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Start pose (the first target): J1 0.0 J2 -90.0 J3 0.0"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("J2     -90.0 ..    -70.0   (limits -200 .. 20)"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::ifstream(dir.file("p.val.journal")).good());  // nothing was sent
}

TEST(CliSend, BadInputFilesAreNamed) {
  test::TempDir dir;
  test::CliResult r = test::RunCli({"send", dir.file("missing.val"), "--dry-run"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing.val"), std::string::npos) << r.err;
  test::WriteFile(dir.file("p.val"), std::string(kProgram) + "DO MOVE #PPOINT(0,0,0,0,0,999)\n");
  r = test::RunCli({"send", dir.file("p.val"), "--dry-run"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("p.val:9"), std::string::npos) << r.err;
  test::WriteFile(dir.file("bad.profile"), "no_such_key = 1\n");
  test::WriteFile(dir.file("q.val"), kProgram);
  r = test::RunCli({"send", dir.file("q.val"), "--dry-run", "--profile", dir.file("bad.profile")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.profile:1"), std::string::npos) << r.err;
  r = test::RunCli({"send", dir.file("q.val"), "--resume", "--port", "/dev/null"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("q.val.journal"), std::string::npos) << r.err;
}

TEST(CliSend, SendsToPumaSimWhichEndsAtTheLastTarget) {
  test::TempDir dir;
  test::WriteFile(dir.file("p.val"), kProgram);
  SimProcess sim(
      {"--link", dir.file("puma"), "--log", dir.file("moves.log"), "--time-scale", "0.02"});
  ASSERT_EQ(sim.device().rfind("/dev/", 0), 0u) << sim.device();
  const test::CliResult r =
      test::RunCli({"-q", "send", dir.file("p.val"), "--port", dir.file("puma")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  int code = -1;
  const std::string tail = sim.Stop(&code);
  EXPECT_EQ(code, 0);
  EXPECT_NE(tail.find("final joints:    24.000   -70.000   -12.000     0.000     0.000     0.000"),
            std::string::npos)
      << tail;
  EXPECT_NE(tail.find("moves executed: 3"), std::string::npos) << tail;
  std::istringstream log(test::ReadFile(dir.file("moves.log")));
  std::vector<std::string> lines;
  for (std::string l; std::getline(log, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2],
            "3\t24.000 -70.000 -12.000 0.000 0.000 0.000\t"
            "DO MOVE #PPOINT(24.00,-70.00,-12.00,0.00,0.00,0.00)");
}

TEST(CliSend, PumaSimFaultFlagsReachTheEmulator) {
  test::TempDir dir;
  test::WriteFile(dir.file("p.val"), kProgram);
  SimProcess sim({"--time-scale", "0.02", "--fail-after", "2"});
  const test::CliResult r = test::RunCli({"-q", "send", dir.file("p.val"), "--port", sim.device()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("p.val:6"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("*Servo error*"), std::string::npos) << r.err;
  EXPECT_NE(sim.Stop().find("moves executed: 1"), std::string::npos);
}

// SIGTERM (a service manager or a batch scheduler stopping the send) stops the stream as Ctrl-C
// does, and the message names the signal that came.
TEST(CliSend, SigtermStopsTheStreamAndTheMessageNamesIt) {
  test::TempDir dir;
  std::string program = "; armmimic VAL program v1\nSPEED 50\n";
  for (int i = 0; i < 20; ++i) {
    program += "; t=" + std::to_string(i) + ".000\nDO MOVE #PPOINT(" + (i % 2 ? "30" : "0") +
               ".00,-90.00,0.00,0.00,0.00,0.00)\n";
  }
  test::WriteFile(dir.file("p.val"), program);
  SimProcess sim({"--time-scale", "1"});  // real time: each 30-degree move takes a while
  test::Child send({ARMMIMIC_CLI_PATH, "send", dir.file("p.val"), "--port", sim.device()},
                   dir.file("out.txt"), dir.file("err.txt"));
  ASSERT_TRUE(send.started());
  // Once the first move is acknowledged, the stream is under way.
  for (int i = 0; i < 4000 && !send.Exited(); ++i) {
    if (test::ReadFile(dir.file("p.val.journal")).find("\nack 2 ") != std::string::npos) break;
    usleep(5000);
  }
  ASSERT_FALSE(send.Exited()) << test::ReadFile(dir.file("err.txt"));
  send.Signal(SIGTERM);
  const int status = send.Wait();
  const std::string err = test::ReadFile(dir.file("err.txt"));
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << ": " << err;
  EXPECT_EQ(WEXITSTATUS(status), 1) << err;
  EXPECT_NE(err.find("interrupted (SIGTERM)"), std::string::npos) << err;
  EXPECT_EQ(err.find("Ctrl-C"), std::string::npos) << err;
  EXPECT_EQ(test::ReadFile(dir.file("p.val.journal")).find("\ndone"), std::string::npos);
}

}  // namespace
}  // namespace armmimic
