// Helpers shared by the test suites: temporary folders and running armmimic-cli.
#pragma once

#include <string>
#include <vector>

namespace armmimic::test {

// A fresh folder under $TMPDIR, removed with its contents when the object goes.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs armmimic-cli with `args` (no shell), capturing stdout and stderr. `stdin_text` is fed to
// its standard input.
CliResult RunCli(const std::vector<std::string>& args, const std::string& stdin_text = "");

// Runs armmimic-cli as an unprivileged user (nobody, through setpriv) when the tests run as root,
// so that permission errors can be provoked; as it is otherwise. CanRunUnprivileged() says
// whether that is possible here.
bool CanRunUnprivileged();
CliResult RunCliUnprivileged(const std::vector<std::string>& args);

// armmimic-cli running in the background: stdout and stderr go to files; the child gets the
// default SIGINT/SIGTERM actions whatever this process inherited. Killed if still running when
// the object goes.
class BackgroundCli {
 public:
  BackgroundCli(const std::vector<std::string>& args, const std::string& out_path,
                const std::string& err_path);
  ~BackgroundCli();
  BackgroundCli(const BackgroundCli&) = delete;
  BackgroundCli& operator=(const BackgroundCli&) = delete;
  bool started() const { return pid_ > 0; }
  bool Exited();  // reaps it once it has ended
  // The exit code (-1: killed by a signal or not started), waiting up to `timeout_s` seconds
  // (then it is killed).
  int Wait(double timeout_s);
  void Signal(int sig);

 private:
  int pid_ = -1;
  bool done_ = false;
  int status_ = 0;
};

std::string ReadFile(const std::string& path);
void WriteFile(const std::string& path, const std::string& bytes);
std::string SourcePath(const std::string& relative);  // path inside the source tree

}  // namespace armmimic::test
