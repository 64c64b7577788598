#include "armmimic/robot/mapping.h"

#include <cmath>
#include <sstream>

#include "armmimic/core/angles.h"

namespace armmimic::robot {
namespace {

std::string Term(const JointMap& m, const std::string& source) {
  std::string s = (m.sign < 0 ? "-" : "+") + source;
  const std::string off = FormatNumber(m.offset_deg, 2);
  s += (m.offset_deg < 0 ? "" : "+") + off;
  return s;
}

}  // namespace

SourceKind DetectSourceKind(const AngleFile& angles) {
  return angles.has_file_column || angles.Meta("engine") == "marker" ? SourceKind::kMarker
                                                                     : SourceKind::kArm;
}

const char* SourceKindName(SourceKind kind) {
  return kind == SourceKind::kMarker ? "marker" : "arm";
}

MappingOptions MappingOptions::Default(SourceKind kind) {
  MappingOptions m;
  m.kind = kind;
  if (kind == SourceKind::kMarker) {
    m.j2 = {-1, -90};
    m.j3 = {1, 0};  // held at its offset: aligned with J2
  }
  return m;
}

Status MappingOptions::Check() const {
  const JointMap* maps[3] = {&j1, &j2, &j3};
  for (int j = 0; j < 3; ++j) {
    if (maps[j]->sign != 1 && maps[j]->sign != -1) {
      return Status::Error("mapping.j" + std::to_string(j + 1),
                           "J" + std::to_string(j + 1) + " mapping sign must be +1 or -1");
    }
    if (!std::isfinite(maps[j]->offset_deg)) {
      return Status::Error("mapping.j" + std::to_string(j + 1),
                           "J" + std::to_string(j + 1) + " mapping offset must be a number");
    }
  }
  for (int j = 3; j < kJoints; ++j) {
    if (!std::isfinite(hold_deg[j])) {
      return Status::Error("mapping.hold_deg",
                           "J" + std::to_string(j + 1) + " hold value must be a number");
    }
  }
  return Status::Ok();
}

std::string MappingOptions::Describe() const {
  std::string s = SourceKindName(kind);
  s += " j1=" + Term(j1, "yaw");
  if (kind == SourceKind::kMarker) {
    s += " j2=" + Term(j2, "bend");
    s += " j3=" + FormatNumber(j3.offset_deg, 2);
  } else {
    s += " j2=" + Term(j2, j2_elevation ? "elevation" : "upper");
    s += " j3=" + Term(j3, j3_flexion ? "flexion" : "bend");
  }
  for (int j = 3; j < kJoints; ++j) {
    s += " j" + std::to_string(j + 1) + "=" + FormatNumber(hold_deg[j], 2);
  }
  s += std::string(" mirror=") + (mirror ? "yes" : "no");
  return s;
}

JointArray MappingOptions::Map(double upper_deg, double bend_deg, double yaw_deg) const {
  JointArray out = hold_deg;
  const double yaw_sign = mirror ? -1 : 1;
  out[0] = j1.sign * yaw_sign * yaw_deg + j1.offset_deg;
  if (kind == SourceKind::kMarker) {
    out[1] = j2.sign * (mirror ? -bend_deg : bend_deg) + j2.offset_deg;
    out[2] = j3.offset_deg;
    return out;
  }
  double j2_source = 0;
  if (j2_elevation) {
    j2_source = std::abs(Wrap180(upper_deg + 90));
  } else {
    j2_source = mirror ? 180 - upper_deg : upper_deg;
  }
  double j3_source = 0;
  if (j3_flexion) {
    j3_source = std::abs(Wrap180(bend_deg));
  } else {
    j3_source = mirror ? -bend_deg : bend_deg;
  }
  out[1] = j2.sign * j2_source + j2.offset_deg;
  out[2] = j3.sign * j3_source + j3.offset_deg;
  return out;
}

bool SourcesFrom3d(const AngleRow& row, int image_side, double* upper, double* bend, double* yaw) {
  if (image_side == 0 || !std::isfinite(row.upper_az_deg) || !std::isfinite(row.upper_el_deg) ||
      !std::isfinite(row.elbow_deg)) {
    return false;
  }
  *upper = row.upper_el_deg;
  *bend = 180 - row.elbow_deg;
  *yaw = std::abs(row.upper_el_deg) > 90 - kAzimuthBlindDeg
             ? kNaN
             : Wrap180(image_side > 0 ? row.upper_az_deg : 180 - row.upper_az_deg);
  return true;
}

int ImageSideOf(const AngleFile& angles) {
  const std::string side = angles.Meta("pose.side");
  if (side == "left") return 1;
  if (side == "right") return -1;
  return 0;
}

int SideFor3d(const MappingOptions& mapping, SourceKind kind, const AngleFile& angles) {
  if (kind != SourceKind::kArm || !mapping.arm_3d || !angles.has_3d_columns) return 0;
  return ImageSideOf(angles);
}

std::string ParseJointMap(const std::string& value, JointMap* out) {
  const auto comma = value.find(',');
  const std::string form = "'" + value + "' is not SIGN,OFFSET (e.g. -1,-90 or +,0)";
  if (comma == std::string::npos) return form;
  const std::string sign = value.substr(0, comma);
  const std::string off = value.substr(comma + 1);
  JointMap m;
  if (sign == "+" || sign == "+1" || sign == "1") {
    m.sign = 1;
  } else if (sign == "-" || sign == "-1") {
    m.sign = -1;
  } else {
    return form;
  }
  std::istringstream ss(off);
  ss.imbue(std::locale::classic());
  double d = 0;
  if (off.empty() || !(ss >> d) || !ss.eof() || !std::isfinite(d)) return form;
  m.offset_deg = d;
  *out = m;
  return "";
}

}  // namespace armmimic::robot
