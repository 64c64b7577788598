// The pose side names and PoseOptions::Check(): the ranges of the pose table (option_table.cpp)
// and the one rule a range cannot say (no arm look between 0 and 1).
#include "armmimic/engines/pose_options.h"

#include "armmimic/core/text.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic {

const char* PoseSideName(PoseSide side) {
  switch (side) {
    case PoseSide::kAuto:
      return "auto";
    case PoseSide::kLeft:
      return "left";
    case PoseSide::kRight:
      return "right";
    case PoseSide::kBoth:
      return "both";
  }
  return "?";
}

bool ParsePoseSide(const std::string& name, PoseSide* out) {
  return ParseByName(name, {PoseSide::kAuto, PoseSide::kLeft, PoseSide::kRight, PoseSide::kBoth},
                     PoseSideName, out);
}

Status PoseOptions::Check() const {
  if (Status st = CheckOptionFields(PoseOptionFields(), "pose", *this); !st) return st;
  if (arm_crop > 0 && arm_crop < 1) {  // a look smaller than the upper body's extent
    return Status::Error("pose.arm_crop", "arm look size is " + OptionRefusedNumberText(arm_crop) +
                                              "; it must be 0 (one look) or in [1, 4]");
  }
  return Status::Ok();
}

}  // namespace armmimic
