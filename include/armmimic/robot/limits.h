// JointLimits: the position and speed bounds every planned or sent joint target must respect.
// The defaults are the contract's PUMA 760 ranges (thesis Table 4-1); the speed limits are our
// conservative choice. The CLI (plan, send) and the GUI fill the same struct.
#pragma once

#include <array>
#include <string>

#include "armmimic/core/status.h"

namespace armmimic::robot {

constexpr int kJoints = 6;
using JointArray = std::array<double, kJoints>;

struct JointLimits {
  JointArray min_deg = {-160, -200, -225, -266, -100, -266};
  JointArray max_deg = {160, 20, 45, 266, 100, 266};
  // Fastest a joint may be asked to move, in degrees per second.
  JointArray max_speed_deg_s = {45, 45, 45, 90, 90, 90};

  // min < max, finite, speeds > 0. The message names the joint ("J2").
  Status Check() const;
  bool Inside(int joint, double deg) const {
    return deg >= min_deg[joint] && deg <= max_deg[joint];
  }
  // The tighter of two sets of limits (used by send: the configured ones and a file's header).
  static JointLimits Intersect(const JointLimits& a, const JointLimits& b);
};

// "J2=-200:20" style overrides, comma-separated: "J1=-90:90,J3=-200:0". Returns an error text or
// "".
std::string ParseLimitsOverride(const std::string& value, JointLimits* limits);
// "45" (every joint) or six comma-separated values "45,45,45,90,90,90". Error text or "".
std::string ParseSpeedLimits(const std::string& value, JointLimits* limits);
// "J1 [-160,160]" style summary of one joint.
std::string DescribeLimit(const JointLimits& limits, int joint);

}  // namespace armmimic::robot
