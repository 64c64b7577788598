#include "armmimic/sim/pty_server.h"

#include <algorithm>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include "armmimic/core/output_file.h"
#include "armmimic/core/text.h"

namespace armmimic::sim {

PtyServer::PtyServer(EmulatorOptions options)
    : line_baud_(options.line_baud), emulator_(std::move(options)) {}

PtyServer::~PtyServer() { Stop(); }

double PtyServer::Now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string PtyServer::FormatLogLine(const LoggedMove& move) {
  // FormatJoints pads to columns; the log keeps single spaces between the six values.
  std::string joints;
  for (char c : PumaEmulator::FormatJoints(move.target_deg)) {
    if (c == ' ' && (joints.empty() || joints.back() == ' ')) continue;
    joints += c;
  }
  return std::to_string(move.seq) + "\t" + joints + "\t" + move.source;
}

Status PtyServer::Start(const std::string& link_path, const std::string& log_path) {
  if (master_fd_ >= 0) return Status::Error("puma-sim: already started");
  if (!log_path.empty()) {
    if (Status st = OpenLogFile(log_path, false, &log_file_); !st) {
      return Status::Error("cannot write the move log: " + st.message());
    }
    emulator_.SetMoveCallback([this](const LoggedMove& move) {
      std::fprintf(log_file_, "%s\n", FormatLogLine(move).c_str());
      std::fflush(log_file_);
    });
  }
  int master = -1, slave = -1;
  char name[256] = {0};
  if (openpty(&master, &slave, name, nullptr, nullptr) != 0) {
    return Status::Error(std::string("cannot open a pseudo-terminal: ") + ErrnoText(errno));
  }
  termios tio{};
  if (tcgetattr(slave, &tio) == 0) {
    cfmakeraw(&tio);
    cfsetispeed(&tio, B9600);
    cfsetospeed(&tio, B9600);
    tcsetattr(slave, TCSANOW, &tio);
  }
  close(slave);
  fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
  fcntl(master, F_SETFD, FD_CLOEXEC);
  master_fd_ = master;
  device_path_ = name;
  if (!link_path.empty()) {
    struct stat st {};
    if (lstat(link_path.c_str(), &st) == 0) {
      if (!S_ISLNK(st.st_mode)) {
        Stop();
        return Status::Error("sim.link", link_path + ": exists and is not a symlink; not replaced");
      }
      unlink(link_path.c_str());
    }
    if (symlink(device_path_.c_str(), link_path.c_str()) != 0) {
      const std::string err = ErrnoText(errno);
      Stop();
      return Status::Error("sim.link", link_path + ": cannot create the symlink: " + err);
    }
    link_path_ = link_path;
  }
  start_ = std::chrono::steady_clock::now();
  stop_ = false;
  thread_ = std::thread([this] { Run(); });
  return Status::Ok();
}

void PtyServer::Stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  if (master_fd_ >= 0) close(master_fd_);
  master_fd_ = -1;
  if (!link_path_.empty()) unlink(link_path_.c_str());
  link_path_.clear();
  if (log_file_) std::fclose(log_file_);
  log_file_ = nullptr;
}

robot::JointArray PtyServer::joints() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return emulator_.joints();
}

std::vector<LoggedMove> PtyServer::log() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return emulator_.log();
}

int PtyServer::lines_received() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return emulator_.lines_received();
}

bool PtyServer::busy() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return emulator_.busy();
}

double PtyServer::idle_s() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return Now() - last_activity_s_;
}

void PtyServer::Paced::Push(const std::string& data, double now_s, double byte_s) {
  for (char c : data) {
    clock_s = std::max(clock_s, now_s) + byte_s;
    bytes += c;
    due_s.push_back(clock_s);
  }
}

std::string PtyServer::Paced::Take(double now_s) {
  std::size_t n = 0;
  while (n < due_s.size() && due_s[n] <= now_s) ++n;
  std::string out = bytes.substr(0, n);
  bytes.erase(0, n);
  due_s.erase(due_s.begin(), due_s.begin() + static_cast<long>(n));
  return out;
}

void PtyServer::Run() {
  bool connected = false;
  char buf[1024];
  byte_s_ = line_baud_ > 0 ? 10.0 / line_baud_ : 0;
  Paced paced_in, paced_out;
  while (!stop_) {
    if (held_) {
      // A controller busy elsewhere: nothing is read or answered, motions stand still.
      usleep(2000);
      continue;
    }
    pollfd p{master_fd_, POLLIN, 0};
    const bool pacing = !paced_in.bytes.empty() || !paced_out.bytes.empty();
    const int r = poll(&p, 1, pacing ? 1 : 5);
    std::string out;
    std::string in;
    bool hangup = false;
    if (r > 0 && (p.revents & POLLIN)) {
      const ssize_t n = read(master_fd_, buf, sizeof(buf));
      if (n > 0) {
        connected = true;
        in.assign(buf, static_cast<std::size_t>(n));
      } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
        hangup = true;
      }
    } else if (r > 0 && (p.revents & (POLLHUP | POLLERR))) {
      hangup = true;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const double now = Now();
      if (byte_s_ > 0) {  // the line delivers one byte per character time
        paced_in.Push(in, now, byte_s_);
        in = paced_in.Take(now);
      }
      if (!in.empty()) {
        last_activity_s_ = now;
        out = emulator_.Feed(in, now);
      }
      if (hangup && connected) emulator_.OnDisconnect();
      out += emulator_.Tick(now);
      if (emulator_.busy() || !out.empty()) last_activity_s_ = now;
      if (byte_s_ > 0) {
        paced_out.Push(out, now, byte_s_);
        out = paced_out.Take(now);
        if (!paced_in.bytes.empty() || !paced_out.bytes.empty()) last_activity_s_ = now;
      }
    }
    if (hangup) {
      connected = false;
      usleep(10000);  // no client: HUP is reported continuously
    }
    std::size_t off = 0;
    int stalls = 0;
    while (off < out.size() && !stop_) {
      const ssize_t w = write(master_fd_, out.data() + off, out.size() - off);
      if (w > 0) {
        off += static_cast<std::size_t>(w);
      } else if (w < 0 && (errno == EAGAIN || errno == EINTR) && ++stalls < 200) {
        pollfd q{master_fd_, POLLOUT, 0};
        poll(&q, 1, 5);
      } else {
        break;  // the client is gone: the bytes are lost, as on a cut cable
      }
    }
  }
}

}  // namespace armmimic::sim
