// The lk arm-side names and LkOptions::Check(): the ranges of the lk table (option_table.cpp)
// and the one rule a range cannot say (an odd window).
#include <string>

#include "armmimic/core/text.h"
#include "armmimic/engines/lk_options.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic {

const char* LkArmSideName(LkArmSide side) {
  switch (side) {
    case LkArmSide::kAuto:
      return "auto";
    case LkArmSide::kLeft:
      return "left";
    case LkArmSide::kRight:
      return "right";
  }
  return "?";
}

bool ParseLkArmSide(const std::string& name, LkArmSide* out) {
  return ParseByName(name, {LkArmSide::kAuto, LkArmSide::kLeft, LkArmSide::kRight}, LkArmSideName,
                     out);
}

Status LkOptions::Check() const {
  if (Status st = CheckOptionFields(LkOptionFields(), "lk", *this); !st) return st;
  if (window_px % 2 == 0) {  // cv::calcOpticalFlowPyrLK's window has a centre pixel
    return Status::Error("lk.window_px",
                         "LK window is " + std::to_string(window_px) + "; it must be odd");
  }
  return Status::Ok();
}

}  // namespace armmimic
