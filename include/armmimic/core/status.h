// Status: the result of an operation that can fail because of the user's input (a bad flag, an
// unreadable file, a malformed line). The message names the file, line or flag it is about.
// Broken invariants (programming errors) throw instead.
#pragma once

#include <string>
#include <utility>

namespace armmimic {

class Status {
 public:
  Status() = default;  // ok
  static Status Ok() { return Status(); }
  static Status Error(std::string message) { return Status(std::move(message)); }

  bool ok() const { return !failed_; }
  explicit operator bool() const { return ok(); }
  const std::string& message() const { return message_; }

 private:
  explicit Status(std::string message) : failed_(true), message_(std::move(message)) {}
  bool failed_ = false;
  std::string message_;
};

}  // namespace armmimic
