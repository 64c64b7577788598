#include "pose/one_euro.h"

#include <cmath>

namespace armmimic::internal {
namespace {

// The smoothing factor of a first-order low-pass filter of cut-off `cutoff_hz` sampled every
// `dt_s` seconds.
double Alpha(double cutoff_hz, double dt_s) {
  const double tau = 1 / (2 * M_PI * cutoff_hz);
  return 1 / (1 + tau / dt_s);
}

}  // namespace

double OneEuroFilter::Apply(double time_s, double x, double value_scale) {
  if (!seen_ || !(time_s > last_time_s_)) {
    seen_ = true;
    last_time_s_ = time_s;
    last_x_ = x;
    last_dx_ = 0;
    return x;
  }
  const double dt = time_s - last_time_s_;
  const double dx = (x - last_x_) * value_scale / dt;
  const double a_d = Alpha(derivative_cutoff_, dt);
  last_dx_ = a_d * dx + (1 - a_d) * last_dx_;
  const double a = Alpha(min_cutoff_ + beta_ * std::abs(last_dx_), dt);
  last_x_ = a * x + (1 - a) * last_x_;
  last_time_s_ = time_s;
  return last_x_;
}

}  // namespace armmimic::internal
