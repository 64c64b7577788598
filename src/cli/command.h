// Subcommand registry: each cmd_*.cpp registers one subcommand, so adding a command touches no
// shared file.
#pragma once

#include <string>
#include <vector>

namespace armmimic::cli {

enum class ProgressMode { kAuto, kOn, kOff };

struct GlobalOptions {
  bool quiet = false;
  ProgressMode progress = ProgressMode::kAuto;
  bool ShowProgress() const;  // kAuto: when stderr is a terminal and not quiet
};

// Exit codes of the contract.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // runtime failure: unreadable video, port error, robot error
constexpr int kExitUsage = 2;    // usage error

using CommandFn = int (*)(const std::vector<std::string>& args, const GlobalOptions& global);

struct Command {
  const char* name;
  const char* summary;  // one line for the top-level help
  int order;            // position in the top-level help
  CommandFn run;
};

class CommandRegistry {
 public:
  static void Add(const Command& command);
  static std::vector<Command> All();  // sorted by order
  static const Command* Find(const std::string& name);
};

struct CommandRegistrar {
  explicit CommandRegistrar(const Command& command) { CommandRegistry::Add(command); }
};

}  // namespace armmimic::cli

#define ARMMIMIC_REGISTER_COMMAND(ident, name, summary, order, fn) \
  static const ::armmimic::cli::CommandRegistrar ident##_registrar({name, summary, order, fn})
