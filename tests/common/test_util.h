// Helpers shared by the test suites: temporary folders and running armmimic-cli.
#pragma once

#include <future>
#include <locale>
#include <memory>
#include <string>
#include <vector>

namespace armmimic::test {

// A fresh folder under $TMPDIR, removed with its contents when the object goes. Every test
// process runs with its own TMPDIR (test_main.cpp), and anything left there when the tests end
// fails the run: a test removes what it makes, even when it fails.
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

// A folder shared by the tests of one process (a scene rendered once for several tests), made on
// first use: `*created` says whether this call made it. Removed with its contents once the last
// test has run, pass or fail (test_main.cpp), never by a static destructor.
const TempDir& SharedTempDir(const std::string& name, bool* created = nullptr);
// Removes every SharedTempDir; test_main.cpp calls it after the last test.
void RemoveSharedTempDirs();

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs armmimic-cli with `args` (no shell), capturing stdout and stderr. `stdin_text` is fed to
// its standard input.
CliResult RunCli(const std::vector<std::string>& args, const std::string& stdin_text = "");

// A program running in the background (argv[0] a path, no shell): stdin from /dev/null, stdout
// and stderr into files, SIGINT, SIGTERM and SIGHUP at their default action and no signal
// blocked, whatever this process inherited (a shell starts background jobs with SIGINT ignored).
// Killed and reaped when the object goes, if still running.
class Child {
 public:
  Child(const std::vector<std::string>& argv, const std::string& out_path,
        const std::string& err_path);
  ~Child();
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  bool started() const { return pid_ > 0; }
  bool Exited();  // true once the process has ended (reaps it)
  int Wait();     // the wait status
  void Signal(int sig);
  int pid() const { return pid_; }

 private:
  int pid_ = -1;
  bool done_ = false;
  int status_ = 0;
};

// armmimic-cli running in the background (a Child): stdout and stderr go to files. Killed if
// still running when the object goes.
class BackgroundCli {
 public:
  BackgroundCli(const std::vector<std::string>& args, const std::string& out_path,
                const std::string& err_path);
  bool started() const { return child_.started(); }
  bool Exited() { return child_.Exited(); }  // reaps it once it has ended
  // The exit code (-1: killed by a signal or not started), waiting up to `timeout_s` seconds
  // (then it is killed).
  int Wait(double timeout_s);
  void Signal(int sig) { child_.Signal(sig); }

 private:
  Child child_;
};

// Runs armmimic-cli as an unprivileged user (nobody, through setpriv) when the tests run as root,
// so that permission errors can be provoked; as it is otherwise. CanRunUnprivileged() says
// whether that is possible here.
bool CanRunUnprivileged();
CliResult RunCliUnprivileged(const std::vector<std::string>& args);

// Runs argv[0] (a path, no shell) with `argv` and the environment `env` ("NAME=value" strings;
// the whole environment, nothing is inherited), capturing stdout and stderr.
CliResult RunProgram(const std::vector<std::string>& argv, const std::vector<std::string>& env);
// This process's environment without the variables named in `drop`.
std::vector<std::string> EnvironmentWithout(const std::vector<std::string>& drop);

// Puts the file `from` at `to`, making `to`'s folder: a hard link where the file system allows it
// (a program is large), a copy otherwise; not a symbolic link, which a program resolves back to
// the folder it came from.
void LinkOrCopy(const std::string& from, const std::string& to);

// Puts the process under comma-decimal number formatting for its lifetime, as a German or French
// desktop does, with no locale installed on the machine: a C locale whose LC_NUMERIC has ','
// decimals ("12,5") is compiled into a temporary folder with localedef (glibc's, always there)
// and selected with setlocale(LC_NUMERIC), and the global C++ locale gets a comma numpunct
// facet. The destructor restores both. active() says whether the C locale took; c_error() why not.
class CommaDecimalLocale {
 public:
  CommaDecimalLocale();
  ~CommaDecimalLocale();
  CommaDecimalLocale(const CommaDecimalLocale&) = delete;
  CommaDecimalLocale& operator=(const CommaDecimalLocale&) = delete;
  bool active() const { return c_error_.empty(); }
  const std::string& c_error() const { return c_error_; }

 private:
  std::unique_ptr<TempDir> dir_;
  std::string saved_c_;
  std::locale saved_cpp_;
  std::string saved_locpath_;
  bool had_locpath_ = false;
  std::string c_error_;
};

std::string ReadFile(const std::string& path);
// The lines of an angle file (or any text file) that are not '#' comments, each ending in "\n":
// its rows, to compare two runs whose headers may differ.
std::string DataRows(const std::string& path);
void WriteFile(const std::string& path, const std::string& bytes);
std::string SourcePath(const std::string& relative);  // path inside the source tree

// Everything `fd` yields until end of file.
std::string ReadAll(int fd);
// A reader of the FIFO `path` on its own thread: it opens the FIFO (which lets a writer's open
// go through), reads to the end and returns the bytes ("open failed: PATH" if it cannot open).
std::future<std::string> ReadFifoInBackground(const std::string& path);

}  // namespace armmimic::test
