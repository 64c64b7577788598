// ArgParser: the flag parser every subcommand uses. "--flag value" and "--flag=value", named
// positionals, --help, and errors that name the flag and end in exit code 2.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <opencv2/core/types.hpp>

namespace armmimic::cli {

class ArgParser {
 public:
  // `command`: "analyze"; `synopsis`: the usage lines; `description`: a paragraph.
  ArgParser(std::string command, std::string synopsis, std::string description);

  // `names` is "-o,--output" or "--threshold". `metavar` shows in the help ("N", "FILE").
  void Flag(const std::string& names, bool* out, const std::string& help);
  // A flag without a value that calls `on` when given.
  void Switch(const std::string& names, const std::string& help, std::function<void()> on);
  void String(const std::string& names, std::string* out, const std::string& metavar,
              const std::string& help);
  void Int(const std::string& names, int* out, const std::string& metavar, const std::string& help,
           int min_value = -2147483647, int max_value = 2147483647);
  void Double(const std::string& names, double* out, const std::string& metavar,
              const std::string& help);
  // A value parsed by `parse`, which returns an error text ("" when fine).
  void Custom(const std::string& names, const std::string& metavar, const std::string& help,
              std::function<std::string(const std::string& value)> parse);
  // Positional arguments, between `min_count` and `max_count` (-1: unbounded).
  void Positionals(std::vector<std::string>* out, const std::string& metavar, int min_count,
                   int max_count);

  // Parses `args`. Returns std::nullopt to go on, or the exit code to return now (0 after
  // --help, 2 after a usage error, with the message printed to stderr).
  std::optional<int> Parse(const std::vector<std::string>& args);
  bool Given(const std::string& long_name) const;  // e.g. Given("--threshold")

  std::string Help() const;
  // Prints "armmimic-cli <command>: <message>" and the --help hint; returns 2.
  int UsageError(const std::string& message) const;

 private:
  struct Option {
    std::vector<std::string> names;
    std::string metavar;  // empty for flags
    std::string help;
    std::function<std::string(const std::string&)> parse;
    std::function<void()> on_switch;  // set for a flag without a value
  };
  const Option* FindOption(const std::string& name) const;

  std::string command_;
  std::string synopsis_;
  std::string description_;
  std::vector<Option> options_;
  std::vector<std::string>* positionals_ = nullptr;
  std::string positional_metavar_;
  int positional_min_ = 0;
  int positional_max_ = 0;
  std::set<std::string> given_;
};

// "X,Y" -> point; "X,Y,W,H" -> rectangle. Return an error text or "".
std::string ParsePointArg(const std::string& value, cv::Point2d* out);
std::string ParseRectArg(const std::string& value, cv::Rect* out);
// "WxH" (or "WXH") with W, H > 0 -> size. Returns an error text or "".
std::string ParseSizeArg(const std::string& value, cv::Size* out);
// A random seed: a non-negative decimal that fits 64 bits. Returns an error text or "".
std::string ParseSeedArg(const std::string& value, std::uint64_t* out);
// Plain number parsing with '.' decimals whatever the locale.
bool ParseDoubleArg(const std::string& value, double* out);
bool ParseIntArg(const std::string& value, int* out);

}  // namespace armmimic::cli
