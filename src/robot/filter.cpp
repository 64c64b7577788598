#include "armmimic/robot/filter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace armmimic::robot {
namespace {

struct Biquad {
  double b0, b1, b2, a1, a2;
};

// 2nd-order Butterworth low-pass by the bilinear transform.
Biquad Butterworth(double sample_rate_hz, double cutoff_hz) {
  const double k = std::tan(3.14159265358979323846 * cutoff_hz / sample_rate_hz);
  const double s2 = std::sqrt(2.0);
  const double norm = 1.0 / (1.0 + s2 * k + k * k);
  Biquad f;
  f.b0 = k * k * norm;
  f.b1 = 2 * f.b0;
  f.b2 = f.b0;
  f.a1 = 2 * (k * k - 1) * norm;
  f.a2 = (1 - s2 * k + k * k) * norm;
  return f;
}

// One pass (transposed direct form II), starting in the steady state of x[0].
void Run(const Biquad& f, std::vector<double>* x) {
  if (x->empty()) return;
  const double x0 = (*x)[0];
  double z2 = (f.b2 - f.a2) * x0;
  double z1 = (1 - f.b0) * x0;
  for (double& v : *x) {
    const double in = v;
    const double y = f.b0 * in + z1;
    z1 = f.b1 * in - f.a1 * y + z2;
    z2 = f.b2 * in - f.a2 * y;
    v = y;
  }
}

}  // namespace

std::vector<double> ZeroPhaseLowPass(const std::vector<double>& x, double sample_rate_hz,
                                     double cutoff_hz) {
  if (cutoff_hz == 0 || x.size() < 2) return x;
  if (!(sample_rate_hz > 0) || !(cutoff_hz > 0) || !(cutoff_hz < 0.5 * sample_rate_hz)) {
    throw std::invalid_argument("ZeroPhaseLowPass: cutoff must be in (0, sample_rate/2)");
  }
  const int n = static_cast<int>(x.size());
  // Odd reflection about each end, about three time constants long.
  const int pad = std::min(n - 1, std::max(6, static_cast<int>(3 * sample_rate_hz / cutoff_hz)));
  std::vector<double> y;
  y.reserve(n + 2 * pad);
  for (int i = pad; i >= 1; --i) y.push_back(2 * x[0] - x[i]);
  y.insert(y.end(), x.begin(), x.end());
  for (int i = 1; i <= pad; ++i) y.push_back(2 * x[n - 1] - x[n - 1 - i]);
  const Biquad f = Butterworth(sample_rate_hz, cutoff_hz);
  Run(f, &y);
  std::reverse(y.begin(), y.end());
  Run(f, &y);
  std::reverse(y.begin(), y.end());
  return std::vector<double>(y.begin() + pad, y.begin() + pad + n);
}

std::vector<double> UnwrapDeg(const std::vector<double>& deg) {
  std::vector<double> out(deg);
  double prev = std::nan("");
  for (double& v : out) {
    if (std::isnan(v)) continue;
    if (!std::isnan(prev)) v -= 360.0 * std::round((v - prev) / 360.0);
    prev = v;
  }
  return out;
}

}  // namespace armmimic::robot
