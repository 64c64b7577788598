#include "armmimic/robot/limits.h"
#include "armmimic/core/text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

#include "armmimic/core/angle_file.h"

namespace armmimic::robot {
namespace {

std::vector<std::string> Split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.push_back("");
  return parts;
}

}  // namespace

Status JointLimits::Check() const {
  for (int j = 0; j < kJoints; ++j) {
    const std::string name = "J" + std::to_string(j + 1);
    if (!std::isfinite(min_deg[j]) || !std::isfinite(max_deg[j]) || !(min_deg[j] < max_deg[j])) {
      return Status::Error(!(min_deg[j] < max_deg[j]) || !std::isfinite(min_deg[j])
                               ? "limits.min_deg"
                               : "limits.max_deg",
                           name + " limits [" + FormatNumber(min_deg[j], 2) + "," +
                               FormatNumber(max_deg[j], 2) + "] need min < max");
    }
    if (!std::isfinite(max_speed_deg_s[j]) || !(max_speed_deg_s[j] > 0)) {
      return Status::Error("limits.max_speed_deg_s", name + " speed limit must be > 0 deg/s");
    }
  }
  return Status::Ok();
}

JointLimits JointLimits::Intersect(const JointLimits& a, const JointLimits& b) {
  JointLimits r;
  for (int j = 0; j < kJoints; ++j) {
    r.min_deg[j] = std::max(a.min_deg[j], b.min_deg[j]);
    r.max_deg[j] = std::min(a.max_deg[j], b.max_deg[j]);
    r.max_speed_deg_s[j] = std::min(a.max_speed_deg_s[j], b.max_speed_deg_s[j]);
  }
  return r;
}

std::string ParseLimitsOverride(const std::string& value, JointLimits* limits) {
  const std::string form = " (expected J<n>=MIN:MAX[,J<n>=MIN:MAX...], e.g. J2=-200:20)";
  if (value.empty()) return "empty limits" + form;
  JointLimits result = *limits;
  for (const std::string& item : Split(value, ',')) {
    const auto eq = item.find('=');
    const auto colon = item.find(':');
    if (item.size() < 4 || (item[0] != 'J' && item[0] != 'j') || eq != 2 ||
        colon == std::string::npos || colon < eq) {
      return "'" + item + "' is not a joint limit" + form;
    }
    const int joint = item[1] - '1';
    if (joint < 0 || joint >= kJoints) return "'" + item + "': joints are J1..J6";
    double lo = 0, hi = 0;
    if (!ParseFiniteDouble(item.substr(eq + 1, colon - eq - 1), &lo) ||
        !ParseFiniteDouble(item.substr(colon + 1), &hi)) {
      return "'" + item + "' has a bad number" + form;
    }
    if (!(lo < hi)) return "'" + item + "' needs MIN < MAX";
    result.min_deg[joint] = lo;
    result.max_deg[joint] = hi;
  }
  *limits = result;
  return "";
}

std::string ParseSpeedLimits(const std::string& value, JointLimits* limits) {
  const std::vector<std::string> parts = Split(value, ',');
  if (parts.size() != 1 && parts.size() != kJoints) {
    return "'" + value + "' is not one speed or six comma-separated speeds in deg/s";
  }
  JointArray speeds{};
  for (std::size_t i = 0; i < parts.size(); ++i) {
    double v = 0;
    if (!ParseFiniteDouble(parts[i], &v) || !(v > 0)) {
      return "'" + parts[i] + "' is not a speed > 0 (deg/s)";
    }
    speeds[i] = v;
  }
  for (int j = 0; j < kJoints; ++j) {
    limits->max_speed_deg_s[j] = parts.size() == 1 ? speeds[0] : speeds[j];
  }
  return "";
}

std::string DescribeLimit(const JointLimits& limits, int joint) {
  return "J" + std::to_string(joint + 1) + " [" + FormatNumber(limits.min_deg[joint], 2) + "," +
         FormatNumber(limits.max_deg[joint], 2) + "]";
}

}  // namespace armmimic::robot
