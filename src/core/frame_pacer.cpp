#include "armmimic/core/frame_pacer.h"

#include <algorithm>
#include <thread>

namespace armmimic {

FramePacer::Clock::time_point FramePacer::Wait(const Frame& frame,
                                               const std::atomic<bool>* cancel) {
  const Clock::time_point now = Clock::now();
  if (!(fps_ > 0)) return now;
  if (!started_) {
    started_ = true;
    first_index_ = frame.index;
    epoch_ = now;
    return now;
  }
  const auto due = epoch_ + std::chrono::duration_cast<Clock::duration>(
                                std::chrono::duration<double>((frame.index - first_index_) / fps_));
  if (now >= due) {
    if (now - due > std::chrono::milliseconds(5)) ++late_;
    return due;
  }
  constexpr auto kStep = std::chrono::milliseconds(20);
  while (Clock::now() < due) {
    if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) break;
    std::this_thread::sleep_for(std::min<Clock::duration>(kStep, due - Clock::now()));
  }
  return due;
}

}  // namespace armmimic
