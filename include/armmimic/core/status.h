// Status: the result of an operation that can fail because of the user's input (a bad setting,
// an unreadable file, a malformed line). Broken invariants (programming errors) throw instead.
//
// A Status about one setting carries that setting's key ("bgsub.threshold", "planner.cutoff_hz",
// "analysis.background"): the key of its row in an option table (docs/architecture.md). The
// message is in the library's own words and never names a command-line flag; each shell maps the
// key to its own words: the CLI to the flag, the GUI to the field, which it highlights.
#pragma once

#include <string>
#include <utility>

namespace armmimic {

class Status {
 public:
  Status() = default;  // ok
  static Status Ok() { return Status(); }
  // An error about no one setting (a file, a line, the controller).
  static Status Error(std::string message) { return Status(std::string(), std::move(message)); }
  // An error about the setting `key`.
  static Status Error(std::string key, std::string message) {
    return Status(std::move(key), std::move(message));
  }

  bool ok() const { return !failed_; }
  explicit operator bool() const { return ok(); }
  const std::string& message() const { return message_; }
  // The setting the error is about, or "" when it is about none.
  const std::string& key() const { return key_; }

  // This error, now about `key` (an error about a file that a setting named, say); ok stays ok.
  Status WithKey(std::string key) const {
    Status s = *this;
    if (failed_) s.key_ = std::move(key);
    return s;
  }

 private:
  Status(std::string key, std::string message)
      : failed_(true), key_(std::move(key)), message_(std::move(message)) {}
  bool failed_ = false;
  std::string key_;
  std::string message_;
};

}  // namespace armmimic
