#include "hybrid/agreement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"

namespace armmimic::internal {
namespace {

constexpr double kRadToDeg = 180 / M_PI;

// The length of the segment between two of lk's joints; 0 when either is missing.
double Length(const std::optional<cv::Point2d>& from, const std::optional<cv::Point2d>& to) {
  return from && to ? cv::norm(*to - *from) : 0;
}

}  // namespace

double AllowedDisagreementDeg(double length_px, const HybridOptions& options) {
  if (!(length_px > 0)) return options.max_disagreement_deg;
  return options.max_disagreement_deg + std::atan(2 * options.joint_px / length_px) * kRadToDeg;
}

std::string Disagreement(const ArmMeasurement& lk, const ArmMeasurement& bgsub,
                         const HybridOptions& options, const std::string& opinion) {
  return DisagreementWithRival(lk, bgsub, options, std::numeric_limits<double>::infinity(),
                               opinion);
}

std::string DisagreementWithRival(const ArmMeasurement& lk, const ArmMeasurement& bgsub,
                                  const HybridOptions& options, double rival_apart_deg,
                                  const std::string& opinion) {
  struct Segment {
    const char* name;
    double lk_deg, bgsub_deg, length_px;
  };
  const Segment segments[] = {
      {"upper arm", lk.upper_deg, bgsub.upper_deg, Length(lk.shoulder_px, lk.elbow_px)},
      {"forearm", lk.fore_deg, bgsub.fore_deg, Length(lk.elbow_px, lk.wrist_px)},
  };
  for (const Segment& s : segments) {
    if (!std::isfinite(s.lk_deg) || !std::isfinite(s.bgsub_deg)) {
      return std::string("no ") + s.name + " direction to compare";
    }
    const double apart = std::abs(Wrap180(s.lk_deg - s.bgsub_deg));
    const double allowed =
        std::min(AllowedDisagreementDeg(s.length_px, options), rival_apart_deg / 2);
    if (apart > allowed) {
      return "the tracker and " + opinion + " disagree on the " + s.name + " by " +
             FormatNumber(apart, 1) + " degrees (allowed " + FormatNumber(allowed, 1) + ")";
    }
  }
  return std::string();
}

}  // namespace armmimic::internal
