// Zero-phase low-pass filter for joint series (the thesis' smoothing of the measured angles):
// a 2nd-order Butterworth run forwards and backwards, so it adds no delay.
#pragma once

#include <vector>

namespace armmimic::robot {

// Filters `x`, sampled at `sample_rate_hz`, with a cutoff of `cutoff_hz` (0: returns x as is).
// The ends are padded by odd reflection so a constant or a ramp passes unchanged. Throws
// std::invalid_argument when cutoff_hz is not below half the sample rate.
std::vector<double> ZeroPhaseLowPass(const std::vector<double>& x, double sample_rate_hz,
                                     double cutoff_hz);

// Makes a series of angles continuous: each value is moved by a multiple of 360 to be closest to
// the previous one. NaN entries are kept and skipped.
std::vector<double> UnwrapDeg(const std::vector<double>& deg);

}  // namespace armmimic::robot
