// Moments, orientation and semi-axes of a binary region (thesis sections 3.2-3.4).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "armmimic/core/geometry.h"

namespace armmimic {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadToDeg = 180.0 / kPi;

// Sign of v, with |v| <= tol counted as zero.
int SignOf(double v, double tol) { return v > tol ? 1 : (v < -tol ? -1 : 0); }

}  // namespace

RegionMoments ComputeMoments(const cv::Mat& mask) {
  return ComputeMoments(mask, cv::Rect(0, 0, mask.cols, mask.rows));
}

RegionMoments ComputeMoments(const cv::Mat& mask, const cv::Rect& roi) {
  if (mask.empty()) return RegionMoments();
  if (mask.type() != CV_8UC1) {
    throw std::invalid_argument("ComputeMoments: mask must be CV_8UC1");
  }
  const cv::Rect r = roi & cv::Rect(0, 0, mask.cols, mask.rows);
  // Raw sums are exact integers: a single pass, row sums first, then weighted by y.
  int64_t n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  const int x_end = r.x + r.width;
  for (int y = r.y; y < r.y + r.height; ++y) {
    const uint8_t* row = mask.ptr<uint8_t>(y);
    int64_t rn = 0, rsx = 0, rsxx = 0;
    int x = r.x;
    while (x < x_end) {
      // Background is skipped eight pixels at a time.
      if (x + 8 <= x_end) {
        uint64_t word;
        std::memcpy(&word, row + x, sizeof(word));
        if (word == 0) {
          x += 8;
          continue;
        }
      }
      const int stop = std::min(x + 8, x_end);
      for (; x < stop; ++x) {
        if (row[x]) {
          ++rn;
          rsx += x;
          rsxx += int64_t(x) * x;
        }
      }
    }
    n += rn;
    sx += rsx;
    sxx += rsxx;
    sy += rn * y;
    sxy += rsx * y;
    syy += rn * y * y;
  }
  RegionMoments m;
  if (n == 0) return m;
  m.m00 = static_cast<double>(n);
  m.m10 = static_cast<double>(sx);
  m.m01 = static_cast<double>(sy);
  m.cx = m.m10 / m.m00;
  m.cy = m.m01 / m.m00;
  // mu_pq * m00 as exact integers (eqs. 3-6..3-8), so symmetric regions give exact zeros.
  using i128 = __int128;
  const i128 n20 = i128(n) * sxx - i128(sx) * sx;
  const i128 n02 = i128(n) * syy - i128(sy) * sy;
  const i128 n11 = i128(n) * sxy - i128(sx) * sy;
  m.mu20 = static_cast<double>(n20) / m.m00;
  m.mu02 = static_cast<double>(n02) / m.m00;
  m.mu11 = static_cast<double>(n11) / m.m00;
  return m;
}

double OrientationDeg(const RegionMoments& m) {
  const double d = m.mu20 - m.mu02;
  const double tol = 1e-12 * (std::abs(m.mu20) + std::abs(m.mu02));
  const int sd = SignOf(d, tol);
  const int s11 = SignOf(m.mu11, tol);
  // theta_img: angle of the axis of least inertia from +x towards +y (image y down), Table 3-1.
  double theta_img = 0;
  if (sd == 0) {
    // Equal second moments: the arctangent's argument is infinite or undefined.
    theta_img = s11 > 0 ? 45.0 : (s11 < 0 ? -45.0 : 0.0);  // 0: no preferred axis (a disc)
  } else if (s11 == 0) {
    theta_img = sd > 0 ? 0.0 : 90.0;
  } else {
    const double half_atan = 0.5 * std::atan(2.0 * m.mu11 / d) * kRadToDeg;  // (-45, 45)
    if (sd > 0) {
      theta_img = half_atan;  // mu11 > 0: (0, 45); mu11 < 0: (-45, 0)
    } else if (s11 > 0) {
      theta_img = half_atan + 90.0;  // (45, 90)
    } else {
      theta_img = half_atan - 90.0;  // (-90, -45)
    }
  }
  // Contract convention: counter-clockwise on screen (y flipped), folded to (-90, 90].
  double deg = -theta_img;
  if (deg <= -90.0) deg += 180.0;
  if (deg > 90.0) deg -= 180.0;
  return deg + 0.0;  // no negative zero
}

SemiAxes ComputeSemiAxes(const RegionMoments& m) {
  SemiAxes s;
  if (m.m00 <= 0) return s;
  const double d = m.mu20 - m.mu02;
  const double root = std::sqrt(d * d + 4.0 * m.mu11 * m.mu11);
  const double sum = m.mu20 + m.mu02;
  s.major = std::sqrt(std::max(0.0, 2.0 * (sum + root) / m.m00));
  s.minor = std::sqrt(std::max(0.0, 2.0 * (sum - root) / m.m00));
  return s;
}

}  // namespace armmimic
