#include "armmimic/engines/pose_options.h"

#include <cmath>

namespace armmimic {

const char* PoseSideName(PoseSide side) {
  switch (side) {
    case PoseSide::kAuto:
      return "auto";
    case PoseSide::kLeft:
      return "left";
    case PoseSide::kRight:
      return "right";
  }
  return "?";
}

bool ParsePoseSide(const std::string& name, PoseSide* out) {
  for (PoseSide s : {PoseSide::kAuto, PoseSide::kLeft, PoseSide::kRight}) {
    if (name == PoseSideName(s)) {
      *out = s;
      return true;
    }
  }
  return false;
}

Status PoseOptions::Check() const {
  auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  if (!in(min_score, 0, 1)) return Status::Error("pose option min_score must be in [0, 1]");
  if (!in(min_length_ratio, 0, 1)) {
    return Status::Error("pose option min_length_ratio must be in [0, 1]");
  }
  if (!in(crop_score, 0, 1)) return Status::Error("pose option crop_score must be in [0, 1]");
  if (!in(arm_crop, 0, 4) || (arm_crop > 0 && arm_crop < 1)) {
    return Status::Error("pose option arm_crop must be 0 (one look) or in [1, 4]");
  }
  if (!in(max_disagreement_deg, 1, 180)) {
    return Status::Error("pose option max_disagreement_deg must be in [1, 180]");
  }
  return Status::Ok();
}

}  // namespace armmimic
