#include "armmimic/engines/bgsub_options.h"

#include <sstream>

namespace armmimic {
namespace {

template <typename T>
std::string Str(T v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

Status BgsubOptions::Check() const {
  if (threshold < 1 || threshold > 254) {
    return Status::Error("bgsub.threshold",
                         "the threshold must be between 1 and 254 (got " + Str(threshold) + ")");
  }
  if (background_frames < 1) {
    return Status::Error(
        "bgsub.background_frames",
        "the number of background frames must be at least 1 (got " + Str(background_frames) + ")");
  }
  if (standstill_frames < 1) {
    return Status::Error(
        "bgsub.standstill_frames",
        "the standstill must be at least 1 frame long (got " + Str(standstill_frames) + ")");
  }
  if (!(straight_ratio > 0 && straight_ratio < 1)) {
    return Status::Error("bgsub straight_ratio must be in (0, 1) (got " + Str(straight_ratio) +
                         ")");
  }
  if (closing_size < 0 || closing_size > 51) {
    return Status::Error("bgsub closing_size must be in [0, 51] (got " + Str(closing_size) + ")");
  }
  if (min_arm_area_px < 1) {
    return Status::Error("bgsub min_arm_area_px must be at least 1 (got " + Str(min_arm_area_px) +
                         ")");
  }
  if (!(shoulder_height >= 0 && shoulder_height <= 1) ||
      !(shoulder_side >= 0 && shoulder_side <= 0.5)) {
    return Status::Error("bgsub shoulder_height must be in [0, 1] and shoulder_side in [0, 0.5]");
  }
  if (!(near_shoulder > 0)) {
    return Status::Error("bgsub near_shoulder must be positive (got " + Str(near_shoulder) + ")");
  }
  if (!(bend_hysteresis >= 0 && bend_hysteresis < straight_ratio)) {
    return Status::Error("bgsub bend_hysteresis must be in [0, straight_ratio) (got " +
                         Str(bend_hysteresis) + ")");
  }
  if (!(upper_arm_fraction > 0.1 && upper_arm_fraction < 0.9)) {
    return Status::Error("bgsub upper_arm_fraction must be in (0.1, 0.9) (got " +
                         Str(upper_arm_fraction) + ")");
  }
  if (!(max_speed_deg_s >= 10 && max_speed_deg_s <= 100000)) {
    return Status::Error("bgsub max_speed_deg_s must be in [10, 100000] (got " +
                         Str(max_speed_deg_s) + ")");
  }
  if (!(min_support >= 0 && min_support <= 1)) {
    return Status::Error("bgsub min_support must be in [0, 1] (got " + Str(min_support) + ")");
  }
  if (confirm_frames < 1 || confirm_frames > 1000) {
    return Status::Error("bgsub confirm_frames must be in [1, 1000] (got " + Str(confirm_frames) +
                         ")");
  }
  return Status::Ok();
}

}  // namespace armmimic
