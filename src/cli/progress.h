// ProgressBar: a one-line bar on stderr for long work, redrawn at most 10 times a second.
#pragma once

#include <chrono>
#include <string>

namespace armmimic::cli {

class ProgressBar {
 public:
  // total < 0: unknown (shows a count and rate only). Disabled bars draw nothing.
  ProgressBar(std::string label, long total, bool enabled);
  ~ProgressBar();
  void Update(long done);
  void SetLabel(const std::string& label);
  void SetTotal(long total) { total_ = total; }
  // Clears the bar line.
  void Finish();

 private:
  void Draw(long done);
  std::string label_;
  long total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace armmimic::cli
