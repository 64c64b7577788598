#include "test_util.h"

#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace armmimic::test {

TempDir::TempDir() {
  const char* base = std::getenv("TMPDIR");
  std::string templ = std::string(base && *base ? base : "/tmp") + "/armmimic-test-XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (!mkdtemp(buf.data())) throw std::runtime_error("mkdtemp failed");
  path_ = buf.data();
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

namespace {

std::map<std::string, std::unique_ptr<TempDir>>& SharedDirs() {
  static std::map<std::string, std::unique_ptr<TempDir>> dirs;
  return dirs;
}

}  // namespace

const TempDir& SharedTempDir(const std::string& name, bool* created) {
  std::unique_ptr<TempDir>& dir = SharedDirs()[name];
  if (created) *created = !dir;
  if (!dir) dir = std::make_unique<TempDir>();
  return *dir;
}

void RemoveSharedTempDirs() { SharedDirs().clear(); }

namespace {

// Runs argv_s[0] with argv_s (no shell), capturing stdout and stderr. `envp` is the child's
// environment (this process's when null).
CliResult RunProgram(std::vector<std::string> argv_s, const std::string& stdin_text,
                     char* const* envp = nullptr) {
  int out_pipe[2], err_pipe[2], in_pipe[2];
  if (pipe(out_pipe) || pipe(err_pipe) || pipe(in_pipe)) throw std::runtime_error("pipe failed");
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, in_pipe[0], 0);
  posix_spawn_file_actions_adddup2(&fa, out_pipe[1], 1);
  posix_spawn_file_actions_adddup2(&fa, err_pipe[1], 2);
  for (int fd : {in_pipe[0], in_pipe[1], out_pipe[0], out_pipe[1], err_pipe[0], err_pipe[1]}) {
    posix_spawn_file_actions_addclose(&fa, fd);
  }
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc =
      posix_spawn(&pid, argv_s[0].c_str(), &fa, nullptr, argv.data(), envp ? envp : environ);
  posix_spawn_file_actions_destroy(&fa);
  close(in_pipe[0]);
  close(out_pipe[1]);
  close(err_pipe[1]);
  if (rc != 0) throw std::runtime_error(std::string("posix_spawn failed: ") + std::strerror(rc));
  if (!stdin_text.empty()) {
    ssize_t ignored = write(in_pipe[1], stdin_text.data(), stdin_text.size());
    (void)ignored;
  }
  close(in_pipe[1]);
  CliResult result;
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  int open_fds = 2;
  char buf[4096];
  while (open_fds > 0) {
    if (poll(fds, 2, -1) < 0) break;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = read(fds[i].fd, buf, sizeof(buf));
      if (n <= 0) {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      } else {
        (i == 0 ? result.out : result.err).append(buf, static_cast<std::size_t>(n));
      }
    }
  }
  int status = 0;
  waitpid(pid, &status, 0);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

// Decimal comma and full-stop grouping, as in de_DE.
struct CommaDecimals : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

// A locale definition with only LC_NUMERIC, and a charmap of the 128 ASCII characters: all
// localedef needs, so no locale sources have to be installed.
constexpr const char* kCommaLocaleSource =
    "LC_NUMERIC\ndecimal_point \"<U002C>\"\nthousands_sep \"<U002E>\"\ngrouping 3;3\n"
    "END LC_NUMERIC\n";

std::string AsciiCharmap() {
  std::string map =
      "<code_set_name> ARMMIMIC-TEST-ASCII\n<comment_char> %\n<escape_char> /\n"
      "<mb_cur_min> 1\n<mb_cur_max> 1\nCHARMAP\n";
  char line[32];
  for (int c = 0; c < 128; ++c) {
    std::snprintf(line, sizeof(line), "<U%04X> /x%02x\n", c, c);
    map += line;
  }
  return map + "END CHARMAP\n";
}

}  // namespace

CliResult RunProgram(const std::vector<std::string>& argv, const std::vector<std::string>& env) {
  std::vector<std::string> env_s = env;
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);
  return RunProgram(argv, "", envp.data());
}

std::vector<std::string> EnvironmentWithout(const std::vector<std::string>& drop) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    bool dropped = false;
    for (const std::string& d : drop) dropped = dropped || d == name;
    if (!dropped) env.push_back(entry);
  }
  return env;
}

void LinkOrCopy(const std::string& from, const std::string& to) {
  std::filesystem::create_directories(std::filesystem::path(to).parent_path());
  std::error_code ec;
  std::filesystem::create_hard_link(from, to, ec);
  if (ec) std::filesystem::copy_file(from, to);
}

CommaDecimalLocale::CommaDecimalLocale() : dir_(std::make_unique<TempDir>()) {
  const char* c = std::setlocale(LC_NUMERIC, nullptr);
  saved_c_ = c ? c : "C";
  saved_cpp_ = std::locale::global(std::locale(std::locale::classic(), new CommaDecimals));
  if (const char* lp = std::getenv("LOCPATH")) {
    had_locpath_ = true;
    saved_locpath_ = lp;
  }
  WriteFile(dir_->file("comma.def"), kCommaLocaleSource);
  WriteFile(dir_->file("ascii.map"), AsciiCharmap());
  // -c: the other categories are missing on purpose (they stay the C locale's).
  const CliResult r = RunProgram({"/usr/bin/localedef", "-c", "-i", dir_->file("comma.def"), "-f",
                                  dir_->file("ascii.map"), dir_->file("comma")},
                                 EnvironmentWithout({}));
  setenv("LOCPATH", dir_->path().c_str(), 1);
  if (!std::setlocale(LC_NUMERIC, "comma")) {
    c_error_ = "localedef could not make a comma locale (exit " + std::to_string(r.exit_code) +
               "): " + r.err;
    return;
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", 2.5);
  if (std::string(text) != "2,5") c_error_ = std::string("printf gives '") + text + "', not 2,5";
}

CommaDecimalLocale::~CommaDecimalLocale() {
  std::locale::global(saved_cpp_);
  std::setlocale(LC_NUMERIC, saved_c_.c_str());
  if (had_locpath_) {
    setenv("LOCPATH", saved_locpath_.c_str(), 1);
  } else {
    unsetenv("LOCPATH");
  }
}

Child::Child(const std::vector<std::string>& argv_s, const std::string& out_path,
             const std::string& err_path) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = argv_s;
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults, none;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigaddset(&defaults, SIGHUP);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0].c_str(), &fa, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&fa);
  pid_ = rc == 0 ? pid : -1;
}

namespace {
std::vector<std::string> CliArgv(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {ARMMIMIC_CLI_PATH};
  argv.insert(argv.end(), args.begin(), args.end());
  return argv;
}
}  // namespace

BackgroundCli::BackgroundCli(const std::vector<std::string>& args, const std::string& out_path,
                             const std::string& err_path)
    : child_(CliArgv(args), out_path, err_path) {}

int BackgroundCli::Wait(double timeout_s) {
  if (!child_.started()) return -1;
  for (int waited_ms = 0; !child_.Exited(); waited_ms += 5) {
    if (waited_ms > timeout_s * 1000) {
      child_.Signal(SIGKILL);
      break;
    }
    usleep(5000);
  }
  const int status = child_.Wait();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

Child::~Child() {
  if (pid_ > 0 && !done_) {
    kill(pid_, SIGKILL);
    Wait();
  }
}

bool Child::Exited() {
  if (done_) return true;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) {
    done_ = true;
    status_ = status;
  }
  return done_;
}

int Child::Wait() {
  if (!done_) {
    int status = 0;
    waitpid(pid_, &status, 0);
    status_ = status;
    done_ = true;
  }
  return status_;
}

void Child::Signal(int sig) { kill(pid_, sig); }

CliResult RunCli(const std::vector<std::string>& args, const std::string& stdin_text) {
  std::vector<std::string> argv = {ARMMIMIC_CLI_PATH};
  argv.insert(argv.end(), args.begin(), args.end());
  return RunProgram(argv, stdin_text);
}

bool CanRunUnprivileged() { return geteuid() != 0 || access("/usr/bin/setpriv", X_OK) == 0; }

CliResult RunCliUnprivileged(const std::vector<std::string>& args) {
  if (geteuid() != 0) return RunCli(args);
  std::vector<std::string> argv = {"/usr/bin/setpriv", "--reuid=65534",   "--regid=65534",
                                   "--clear-groups",   "--inh-caps=-all", "--",
                                   ARMMIMIC_CLI_PATH};
  argv.insert(argv.end(), args.begin(), args.end());
  return RunProgram(argv, "");
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string DataRows(const std::string& path) {
  std::istringstream in(ReadFile(path));
  std::string rows;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') rows += line + "\n";
  }
  return rows;
}

void WriteFile(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

std::string SourcePath(const std::string& relative) {
  return std::string(ARMMIMIC_SOURCE_DIR) + "/" + relative;
}

std::string ReadAll(int fd) {
  std::string out;
  char buf[4096];
  ssize_t n;
  while ((n = ::read(fd, buf, sizeof buf)) > 0) out.append(buf, static_cast<std::size_t>(n));
  return out;
}

std::future<std::string> ReadFifoInBackground(const std::string& path) {
  return std::async(std::launch::async, [path] {
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) return "open failed: " + path;
    std::string got = ReadAll(fd);
    ::close(fd);
    return got;
  });
}

}  // namespace armmimic::test
