// The 1-euro filter (Casiez, Roussel and Vogel, CHI 2012) as MediaPipe runs it on BlazePose's
// world landmarks: a low-pass filter whose cut-off rises with the signal's own speed, so a
// still joint is steadied and a moving one is followed without lag.
#pragma once

namespace armmimic::internal {

class OneEuroFilter {
 public:
  // min_cutoff_hz: the cut-off of a still signal; beta: how fast the cut-off rises with speed
  // (per unit of the signal per second); derivative_cutoff_hz: the cut-off of the speed itself.
  OneEuroFilter(double min_cutoff_hz, double beta, double derivative_cutoff_hz)
      : min_cutoff_(min_cutoff_hz), beta_(beta), derivative_cutoff_(derivative_cutoff_hz) {}
  // The filtered value of `x` seen at `time_s`. The first value, and a value not later than the
  // one before, pass unfiltered. `value_scale` scales the speed that raises the cut-off (MediaPipe
  // gives image landmarks one over the object's size, so that speed is in sizes per second).
  double Apply(double time_s, double x, double value_scale = 1);
  void Reset() { seen_ = false; }

 private:
  double min_cutoff_;
  double beta_;
  double derivative_cutoff_;
  bool seen_ = false;
  double last_time_s_ = 0;
  double last_x_ = 0;
  double last_dx_ = 0;
};

}  // namespace armmimic::internal
