// armmimic-cli: the command-line twin of the armmimic application.
#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

#include "armmimic/version.h"
#include "command.h"

namespace armmimic::cli {

bool GlobalOptions::ShowProgress() const {
  if (quiet || progress == ProgressMode::kOff) return false;
  if (progress == ProgressMode::kOn) return true;
  return isatty(STDERR_FILENO) == 1;
}

namespace {

std::vector<Command>& Registry() {
  static std::vector<Command> commands;
  return commands;
}

void PrintTopHelp(std::ostream& out) {
  out << "armmimic-cli " << ARMMIMIC_VERSION
      << ": make a robot arm mimic a human arm seen on video.\n\n"
         "Usage: armmimic-cli [-q] [--progress|--no-progress] COMMAND [ARGS...]\n"
         "       armmimic-cli COMMAND --help\n\nCommands:\n";
  for (const Command& c : CommandRegistry::All()) {
    std::string name = c.name;
    out << "  " << name << std::string(name.size() < 12 ? 12 - name.size() : 1, ' ') << c.summary
        << "\n";
  }
  out << "\nGlobal options:\n"
         "  -q                quiet: only errors\n"
         "  --progress        always draw a progress bar on stderr\n"
         "  --no-progress     never draw one (default: a bar when stderr is a terminal)\n"
         "  --version         print the version\n"
         "\nExit codes: 0 ok, 1 runtime failure, 2 usage error.\n";
}

}  // namespace

void CommandRegistry::Add(const Command& command) { Registry().push_back(command); }

std::vector<Command> CommandRegistry::All() {
  std::vector<Command> all = Registry();
  std::sort(all.begin(), all.end(),
            [](const Command& a, const Command& b) { return a.order < b.order; });
  return all;
}

const Command* CommandRegistry::Find(const std::string& name) {
  for (const Command& c : Registry()) {
    if (name == c.name) return &c;
  }
  return nullptr;
}

}  // namespace armmimic::cli

int main(int argc, char** argv) {
  using namespace armmimic::cli;
  GlobalOptions global;
  std::vector<std::string> rest;
  bool after_dashdash = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--") after_dashdash = true;
    if (!after_dashdash) {
      if (a == "-q" || a == "--quiet") {
        global.quiet = true;
        continue;
      }
      if (a == "--progress") {
        global.progress = ProgressMode::kOn;
        continue;
      }
      if (a == "--no-progress") {
        global.progress = ProgressMode::kOff;
        continue;
      }
      if (a == "--version" && rest.empty()) {
        std::cout << "armmimic-cli " << ARMMIMIC_VERSION << "\n";
        return kExitOk;
      }
    }
    rest.push_back(a);
  }
  if (rest.empty()) {
    PrintTopHelp(std::cerr);
    return kExitUsage;
  }
  if (rest[0] == "-h" || rest[0] == "--help" || rest[0] == "help") {
    if (rest.size() > 1 && CommandRegistry::Find(rest[1])) {
      return CommandRegistry::Find(rest[1])->run({"--help"}, global);
    }
    PrintTopHelp(std::cout);
    return kExitOk;
  }
  const Command* command = CommandRegistry::Find(rest[0]);
  if (!command) {
    std::cerr << "armmimic-cli: unknown command '" << rest[0] << "'\n"
              << "Try 'armmimic-cli --help'.\n";
    return kExitUsage;
  }
  try {
    return command->run(std::vector<std::string>(rest.begin() + 1, rest.end()), global);
  } catch (const std::exception& e) {
    std::cerr << "armmimic-cli " << rest[0] << ": internal error: " << e.what() << "\n";
    return kExitFailure;
  }
}
