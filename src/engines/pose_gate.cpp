#include "pose_gate.h"

#include <algorithm>

namespace armmimic::internal {

double PoseLengthGate::P90(std::vector<double> v) {
  const auto k = static_cast<std::ptrdiff_t>((v.size() - 1) * 9 / 10);
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<std::size_t>(k)];
}

bool PoseLengthGate::Accept(double length_px, double torso_px, double min_ratio) {
  auto push = [](std::vector<double>& v, double x) {
    if (v.size() >= kWindow) v.erase(v.begin());
    v.push_back(x);
  };
  if (torso_px > 0) {
    push(relative_, length_px / torso_px);
    const double usual = std::max(P90(relative_), floor_ratio_);
    usual_px_ = usual * torso_px;
  } else {
    push(pixels_, length_px);
    usual_px_ = P90(pixels_);
  }
  return length_px >= min_ratio * usual_px_;
}

}  // namespace armmimic::internal
