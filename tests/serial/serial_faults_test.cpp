// Serial faults over real pseudo-terminals: the device vanishes mid-stream, the port is taken,
// noise arrives between prompts, the controller echoes nothing. Each fault ends with a clear
// message naming the line or port, the journal stays intact, and --resume completes the rest
// with every move executed exactly once (the emulator's log is the proof).
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <future>
#include <mutex>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/sim/pty_server.h"
#include "test_program.h"
#include "test_util.h"

extern char** environ;

namespace armmimic {
namespace {

namespace fs = std::filesystem;
using robot::JointArray;
using Clock = std::chrono::steady_clock;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

using test::Fast;
using test::Program;

// SPEED 50 and `moves` timed moves, each target distinct. Move i is on line 5 + 2 i.
Program MakeProgram(int moves) {
  return test::MakeTimedProgram(moves, "faults", [](int i) -> JointArray {
    return {std::round(std::cos(i * 0.9) * 1500) / 100, -90 + i * 2.0, -i * 1.5, 0, 0, 0};
  });
}

// Every planned target executed exactly once, in order, across all the controllers' logs.
void ExpectExactlyOnce(const std::vector<sim::LoggedMove>& log, const Program& p) {
  ASSERT_EQ(log.size(), p.targets.size());
  for (std::size_t i = 0; i < log.size(); ++i) {
    for (int j = 0; j < robot::kJoints; ++j) {
      EXPECT_NEAR(log[i].target_deg[j], p.targets[i][j], 0.006)
          << "move " << i + 1 << " J" << j + 1;
    }
  }
}

template <typename F>
bool WaitFor(F ready, double seconds = 10) {
  const auto until = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < until) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return ready();
}

class SerialFaults : public ::testing::Test {
 protected:
  void Write(const Program& p) { test::WriteFile(val_, p.text); }
  test::CliResult Send(std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"--no-progress", "send", val_, "--port", port_};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::RunCli(args);
  }
  std::string Journal() const { return test::ReadFile(val_ + ".journal"); }

  test::TempDir dir_;
  std::string val_ = dir_.file("prog.val");
  std::string port_ = dir_.file("puma");
};

// The cable is pulled mid-stream (the controller's side of the pseudo-terminal closes); it is
// plugged in again with the arm where it stopped, and --resume finishes the program.
TEST_F(SerialFaults, DeviceVanishesMidStreamThenResumeFinishesWithEveryMoveOnce) {
  const Program p = MakeProgram(10);
  Write(p);
  sim::EmulatorOptions slow;
  slow.time_scale = 0.5;  // slow enough to pull the plug between moves 3 and 10
  auto first = std::make_unique<sim::PtyServer>(slow);
  ASSERT_TRUE(first->Start(port_).ok());
  auto run = std::async(std::launch::async, [&] { return Send(); });
  ASSERT_TRUE(WaitFor([&] { return first->log().size() >= 3; }, 20));
  first->Stop();
  const test::CliResult cut = run.get();
  EXPECT_EQ(cut.exit_code, 1) << cut.err;
  EXPECT_TRUE(Contains(cut.err, "connection was lost")) << cut.err;
  EXPECT_TRUE(Contains(cut.err, port_)) << cut.err;
  EXPECT_TRUE(Contains(cut.err, "--resume")) << cut.err;
  const std::vector<sim::LoggedMove> before = first->log();
  ASSERT_LT(before.size(), p.targets.size());
  // The journal is intact: it is readable and says the run is unfinished.
  const std::string journal = Journal();
  EXPECT_FALSE(journal.empty());
  EXPECT_FALSE(Contains(journal, "\ndone\n")) << journal;

  // The arm finishes the motion it had started when the line went dead.
  sim::EmulatorOptions again = Fast();
  again.start_deg = before.back().target_deg;
  sim::PtyServer second(again);
  ASSERT_TRUE(second.Start(port_).ok());
  const test::CliResult resumed = Send({"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  std::vector<sim::LoggedMove> all = before;
  for (const auto& m : second.log()) all.push_back(m);
  ExpectExactlyOnce(all, p);
  EXPECT_TRUE(Contains(Journal(), "\ndone\n"));
}

// A second sender on the same program and port is refused without disturbing the first run's
// journal or its moves.
TEST_F(SerialFaults, PortInUseByTheSameProgramLeavesTheRunningJournalAlone) {
  const Program p = MakeProgram(12);
  Write(p);
  sim::EmulatorOptions o;
  o.time_scale = 0.3;
  sim::PtyServer server(o);
  ASSERT_TRUE(server.Start(port_).ok());
  auto run = std::async(std::launch::async, [&] { return Send({"--timeout", "120"}); });
  ASSERT_TRUE(WaitFor([&] { return !server.log().empty(); }, 20));
  // The first send waits on its line in flight however long the checks below take.
  server.Hold(true);
  // A plain send sees the running send's unfinished journal and refuses to replay moves.
  const test::CliResult plain = Send();
  EXPECT_EQ(plain.exit_code, 1) << plain.err;
  EXPECT_TRUE(Contains(plain.err, val_ + ".journal")) << plain.err;
  EXPECT_TRUE(Contains(plain.err, "has not finished")) << plain.err;  // not "stopped": it runs
  // A --resume (the journal check passes) or --restart reaches the port and finds it taken,
  // before it writes anything to the journal.
  for (const char* flag : {"--resume", "--restart"}) {
    const test::CliResult second = Send({flag});
    EXPECT_EQ(second.exit_code, 1) << flag << ": " << second.err;
    EXPECT_TRUE(Contains(second.err, "--port: " + port_)) << flag << ": " << second.err;
    EXPECT_TRUE(Contains(second.err, "busy")) << flag << ": " << second.err;
  }
  server.Hold(false);
  const test::CliResult first = run.get();
  ASSERT_EQ(first.exit_code, 0) << first.err;
  ExpectExactlyOnce(server.log(), p);
  EXPECT_TRUE(Contains(Journal(), "\ndone\n")) << Journal();
}

// Noise before every prompt, then the reply wire is cut: the stream stops naming the line, and
// --resume (noise still on the line) finishes with every move once.
TEST_F(SerialFaults, GarbageBetweenPromptsThenACutReplyThenResume) {
  const Program p = MakeProgram(6);
  Write(p);
  sim::EmulatorOptions o = Fast();
  o.garble_after = 0;
  o.silent_after = 3;  // SPEED + 2 moves answered; move 3 (prog.val:9) runs, its reply is lost
  sim::PtyServer server(o);
  ASSERT_TRUE(server.Start(port_).ok());
  const test::CliResult cut = Send({"--motion-timeout", "1.5"});
  EXPECT_EQ(cut.exit_code, 1) << cut.err;
  EXPECT_TRUE(Contains(cut.err, "prog.val:9")) << cut.err;
  EXPECT_TRUE(Contains(cut.err, "--resume")) << cut.err;
  EXPECT_EQ(server.log().size(), 3u);
  const test::CliResult resumed = Send({"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  ExpectExactlyOnce(server.log(), p);
  EXPECT_TRUE(Contains(resumed.err, "unexpected lines from the controller ignored")) << resumed.err;
}

// A controller that prints the prompt but never echoes: with the default profile (echo = yes)
// the first line stops the stream with a message naming it; with a profile saying echo = no
// the whole program goes through, every line once.
class NoEchoController {
 public:
  explicit NoEchoController(const std::string& link) : link_(link) {
    master_ = posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0 || grantpt(master_) || unlockpt(master_)) return;
    termios t{};
    tcgetattr(master_, &t);
    cfmakeraw(&t);
    tcsetattr(master_, TCSANOW, &t);
    const char* name = ptsname(master_);
    if (!name) return;
    slave_ = open(name, O_RDWR | O_NOCTTY);  // keeps the pair alive between clients
    fs::remove(link_);
    fs::create_symlink(name, link_);
    thread_ = std::thread([this] { Run(); });
  }
  ~NoEchoController() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    if (slave_ >= 0) close(slave_);
    if (master_ >= 0) close(master_);
    std::error_code ec;
    fs::remove(link_, ec);
  }
  bool ok() const { return thread_.joinable(); }
  std::vector<std::string> lines() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return lines_;
  }

 private:
  void Run() {
    std::string partial;
    ssize_t ignored = write(master_, "\r\n.", 3);
    (void)ignored;
    while (!stop_) {
      pollfd fd{master_, POLLIN, 0};
      if (poll(&fd, 1, 10) <= 0 || !(fd.revents & POLLIN)) continue;
      char buf[256];
      const ssize_t n = read(master_, buf, sizeof(buf));
      if (n <= 0) continue;
      partial.append(buf, static_cast<std::size_t>(n));
      for (std::size_t cr; (cr = partial.find('\r')) != std::string::npos;) {
        const std::string line = partial.substr(0, cr);
        partial.erase(0, cr + 1);
        if (line.empty()) {
          ignored = write(master_, "\r\n.", 3);
          continue;
        }
        {
          std::lock_guard<std::mutex> lock(mutex_);
          lines_.push_back(line);
        }
        ignored = write(master_, "\r\n.", 3);  // prompt only, no echo
      }
    }
  }

  std::string link_;
  int master_ = -1;
  int slave_ = -1;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::vector<std::string> lines_;
};

TEST_F(SerialFaults, ControllerThatEchoesNothing) {
  const Program p = MakeProgram(3);
  Write(p);
  {
    NoEchoController controller(port_);
    ASSERT_TRUE(controller.ok());
    const test::CliResult r = Send({"--timeout", "1", "--motion-timeout", "1"});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_TRUE(Contains(r.err, "prog.val:3")) << r.err;  // the first line sent
    EXPECT_TRUE(Contains(r.err, "echo")) << r.err;
    // Nothing after the unconfirmed line went out.
    EXPECT_LE(controller.lines().size(), 1u);
  }
  // The same controller described by a profile that expects no echo.
  std::string profile = test::ReadFile(test::SourcePath("docs/profiles/default.profile"));
  const std::size_t at = profile.find("echo = yes");
  ASSERT_NE(at, std::string::npos);
  profile.replace(at, 10, "echo = no");
  const std::string noecho = dir_.file("noecho.profile");
  test::WriteFile(noecho, profile);
  NoEchoController controller(port_);
  ASSERT_TRUE(controller.ok());
  const test::CliResult r = Send({"--profile", noecho, "--restart"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> got = controller.lines();
  ASSERT_EQ(got.size(), 1 + p.targets.size());
  EXPECT_EQ(got[0], "SPEED 50");
  for (std::size_t i = 0; i < p.targets.size(); ++i) {
    JointArray t{};
    ASSERT_TRUE(robot::ParsePpointTarget(got[i + 1], &t)) << got[i + 1];
    for (int j = 0; j < robot::kJoints; ++j) EXPECT_NEAR(t[j], p.targets[i][j], 0.006);
  }
}

// The same story through the puma-sim command itself (its fault flags and --log file).
TEST_F(SerialFaults, PumaSimCommandRefusesALineThenResumeCompletes) {
  const Program p = MakeProgram(5);
  Write(p);
  const std::string log = dir_.file("moves.log");
  std::vector<std::string> argv_s = {ARMMIMIC_CLI_PATH,
                                     "-q",
                                     "puma-sim",
                                     "--link",
                                     port_,
                                     "--log",
                                     log,
                                     "--time-scale",
                                     "0.02",
                                     "--fail-after",
                                     "3",
                                     "--exit-after-idle",
                                     "20"};
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, dir_.file("sim.err").c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, ARMMIMIC_CLI_PATH, &fa, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);
  struct Reap {
    pid_t pid;
    ~Reap() {
      kill(pid, SIGINT);
      int status = 0;
      waitpid(pid, &status, 0);
    }
  } reap{pid};
  ASSERT_TRUE(WaitFor([&] { return fs::exists(port_); })) << test::ReadFile(dir_.file("sim.err"));

  const test::CliResult refused = Send();
  EXPECT_EQ(refused.exit_code, 1) << refused.err;
  EXPECT_TRUE(Contains(refused.err, "prog.val:9")) << refused.err;  // the third move
  EXPECT_TRUE(Contains(refused.err, "*Servo error*")) << refused.err;
  const test::CliResult resumed = Send({"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;

  // One log line per executed move: "seq<TAB>j1 .. j6<TAB>source".
  std::vector<sim::LoggedMove> moves;
  ASSERT_TRUE(WaitFor([&] {
    std::istringstream in(test::ReadFile(log));
    int n = 0;
    for (std::string line; std::getline(in, line);) n += !line.empty();
    return n >= static_cast<int>(p.targets.size());
  }));
  std::istringstream in(test::ReadFile(log));
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    std::istringstream fields(line);
    sim::LoggedMove m;
    fields >> m.seq;
    for (int j = 0; j < robot::kJoints; ++j) fields >> m.target_deg[j];
    moves.push_back(m);
  }
  ExpectExactlyOnce(moves, p);
}

}  // namespace
}  // namespace armmimic
