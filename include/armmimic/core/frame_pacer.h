// FramePacer: releases the frames of a video file at the file's own frame rate, as a camera
// would deliver them (`mimic VIDEO --realtime`). Frame i is due i/fps after the first frame
// read; Wait() sleeps until then and returns the due time, which is the frame's capture time
// even when the reader falls behind (the wait then is zero and the frame counts as late).
#pragma once

#include <atomic>
#include <chrono>

#include "armmimic/core/frame.h"

namespace armmimic {

class FramePacer {
 public:
  using Clock = std::chrono::steady_clock;
  // fps <= 0: no pacing (Wait returns at once, with the time it was called).
  explicit FramePacer(double fps) : fps_(fps) {}
  // Sleeps until `frame` is due (in short steps, returning early once `cancel` is set).
  Clock::time_point Wait(const Frame& frame, const std::atomic<bool>* cancel = nullptr);
  int late_frames() const { return late_; }  // frames read after they were due

 private:
  double fps_;
  bool started_ = false;
  int first_index_ = 0;
  Clock::time_point epoch_;
  int late_ = 0;
};

}  // namespace armmimic
