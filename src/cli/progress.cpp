#include "progress.h"

#include <cstdio>

namespace armmimic::cli {

ProgressBar::ProgressBar(std::string label, long total, bool enabled)
    : label_(std::move(label)),
      total_(total),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_ - std::chrono::seconds(1)) {}

ProgressBar::~ProgressBar() { Finish(); }

void ProgressBar::SetLabel(const std::string& label) { label_ = label; }

void ProgressBar::Update(long done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100) && !(total_ > 0 && done >= total_)) return;
  last_draw_ = now;
  Draw(done);
}

void ProgressBar::Draw(long done) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? done / elapsed : 0;
  char line[200];
  if (total_ > 0) {
    const double f = done > total_ ? 1.0 : static_cast<double>(done) / static_cast<double>(total_);
    const int width = 30;
    const int filled = static_cast<int>(f * width);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar += std::string(static_cast<std::size_t>(width - filled), '.');
    const double eta = rate > 0 ? (total_ - done) / rate : 0;
    std::snprintf(line, sizeof(line), "\r%-12.12s [%s] %3d%% %ld/%ld  %.0f/s  eta %.0fs ",
                  label_.c_str(), bar.c_str(), static_cast<int>(f * 100), done, total_, rate, eta);
  } else {
    std::snprintf(line, sizeof(line), "\r%-12.12s %ld  %.0f/s ", label_.c_str(), done, rate);
  }
  std::fputs(line, stderr);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::Finish() {
  if (!drawn_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace armmimic::cli
