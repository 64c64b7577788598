#include "arm_motion.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace armmimic::synth {
namespace {

ArmPose Lerp(const ArmPose& a, const ArmPose& b, double s) {
  return {a.upper_deg + (b.upper_deg - a.upper_deg) * s, a.bend_deg + (b.bend_deg - a.bend_deg) * s,
          a.yaw_deg + (b.yaw_deg - a.yaw_deg) * s};
}

// Minimum-jerk time law: 0 -> 1 with zero velocity and acceleration at both ends.
double MinJerk(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * t * (10.0 + t * (-15.0 + 6.0 * t));
}

// Duration weight of a segment: large moves take longer, and every move takes a moment.
double Effort(const ArmPose& a, const ArmPose& b) {
  const double d =
      std::max({std::fabs(b.upper_deg - a.upper_deg), std::fabs(b.bend_deg - a.bend_deg) * 1.2,
                std::fabs(b.yaw_deg - a.yaw_deg) * 1.5});
  return d + 25.0;
}

bool SegmentValid(const ArmPose& a, const ArmPose& b,
                  const std::function<bool(const ArmPose&)>& valid) {
  for (int k = 0; k <= 16; ++k) {
    if (!valid(Lerp(a, b, k / 16.0))) return false;
  }
  return true;
}

std::vector<ArmPose> Repeat(const std::vector<ArmPose>& cycle, int times) {
  std::vector<ArmPose> out{cycle.front()};
  for (int t = 0; t < times; ++t) out.insert(out.end(), cycle.begin() + 1, cycle.end());
  return out;
}

}  // namespace

ArmMotionPlan::ArmMotionPlan(ArmMotion motion, int frames, uint64_t seed,
                             const std::function<bool(const ArmPose&)>& valid) {
  const ArmPose hang{-90, 0, 0};
  // Longer scenes repeat the cycle rather than slowing it down.
  const int cycles = std::max(1, static_cast<int>(std::lround(frames / 160.0)));
  switch (motion) {
    case ArmMotion::kSwing:
      keys_ = Repeat({hang, {90, 0, 0}, hang}, cycles);
      break;
    case ArmMotion::kBend:
      keys_ = Repeat({hang, {-80, 150, 0}, {-10, 40, 0}, hang}, cycles);
      break;
    case ArmMotion::kYaw:
      keys_ = Repeat({hang, {0, 0, 0}, {0, 0, 70}, {0, 0, 0}, {0, 0, 40}}, cycles);
      break;
    case ArmMotion::kMixed: {
      std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 0x51ED);
      std::uniform_real_distribution<double> upper(-90.0, 90.0), bend(0.0, 150.0);
      keys_.push_back(hang);
      const int count = std::max(2, frames / 60);
      // Short scenes get smaller moves rather than faster ones: a minimum-jerk move of D degrees
      // over T frames peaks at 1.875 D / T, so D <= 2 T keeps it under about 4 degrees a frame.
      const double max_move = 2.0 * frames / count;
      for (int k = 0; k < count; ++k) {
        ArmPose next = hang;
        for (int attempt = 0; attempt < 200; ++attempt) {
          ArmPose cand{upper(rng), bend(rng), 0};
          // Alternate large and small moves so the sequence covers the range.
          if (std::fabs(cand.upper_deg - keys_.back().upper_deg) < 30 &&
              std::fabs(cand.bend_deg - keys_.back().bend_deg) < 30) {
            continue;
          }
          if (std::max(std::fabs(cand.upper_deg - keys_.back().upper_deg),
                       std::fabs(cand.bend_deg - keys_.back().bend_deg)) > max_move) {
            continue;
          }
          if (SegmentValid(keys_.back(), cand, valid)) {
            next = cand;
            break;
          }
        }
        keys_.push_back(next);
      }
      break;
    }
  }
  // Keyframe times proportional to the effort of each move, spread over `frames`.
  std::vector<double> effort{0.0};
  for (std::size_t i = 1; i < keys_.size(); ++i) {
    effort.push_back(effort.back() + Effort(keys_[i - 1], keys_[i]));
  }
  const double total = effort.back();
  for (double e : effort) key_frame_.push_back(total > 0 ? e / total * std::max(1, frames) : 0.0);
}

ArmPose ArmMotionPlan::At(int i) const {
  if (keys_.empty()) return {};
  if (i <= 0) return keys_.front();
  const double t = i;
  for (std::size_t k = 1; k < keys_.size(); ++k) {
    if (t <= key_frame_[k]) {
      const double span = key_frame_[k] - key_frame_[k - 1];
      const double s = span > 0 ? (t - key_frame_[k - 1]) / span : 1.0;
      return Lerp(keys_[k - 1], keys_[k], MinJerk(s));
    }
  }
  return keys_.back();
}

}  // namespace armmimic::synth
