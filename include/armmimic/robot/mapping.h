// Mapping from measured arm angles to PUMA joints (thesis 4.4.1.2): each joint is
// sign * source + offset, with a mirror option.
//
// Arm engines (bgsub, lk):  J1 = yaw, J2 = upper-arm elevation, J3 = elbow flexion.
//   elevation = the upper arm's angle from hanging, in [0,180] on either side of the body:
//               |Wrap180(upper_deg + 90)| (hanging 0, horizontal 90, raised 180).
//   flexion   = |bend_deg| (0 straight, 150 fully flexed; the 2-D bend's sign is not anatomy).
//   Defaults J1 = +yaw, J2 = -elevation, J3 = -flexion: every human pose lands inside the
//   default limits (J2 in [-180,0] of [-200,20], J3 in [-180,0] of [-225,45]).
// Marker engine: J1 = yaw, J2 = bend, J3 held (kept aligned with J2). Default J2 = -bend - 90
//   (bend in [-110,110] fits [-200,20]).
// mirror: the person is seen mirrored (the robot faces them): yaw turns J1 the other way and
//   signed sources (upper, bend) are mirrored (upper -> 180 - upper, bend -> -bend).
// J4..J6 are held at hold_deg.
#pragma once

#include <string>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/robot/limits.h"

namespace armmimic::robot {

enum class SourceKind { kArm, kMarker };

// kMarker when the file has the marker's file column or says engine=marker.
SourceKind DetectSourceKind(const AngleFile& angles);
const char* SourceKindName(SourceKind kind);  // "arm" / "marker"

struct JointMap {
  double sign = 1;  // +1 or -1
  double offset_deg = 0;
};

struct MappingOptions {
  SourceKind kind = SourceKind::kArm;
  JointMap j1{1, 0};
  JointMap j2{-1, 0};
  JointMap j3{-1, 0};
  bool mirror = false;
  // Arm only: J2 from the elevation (default) or from the continuous signed upper_deg; J3 from
  // the flexion (default) or from the signed bend_deg.
  bool j2_elevation = true;
  bool j3_flexion = true;
  JointArray hold_deg{};  // J4..J6 targets (entries 3..5); J1..J3 entries unused
  // Arm only: in rows with the 3-D columns (docs/robot.md, "Mapping the 3-D columns"), J1 from the
  // upper arm's azimuth, J2 from its elevation and J3 from elbow_deg (SourcesFrom3d); false: from
  // the 2-D columns always.
  bool arm_3d = true;
  // The side of the image the arm is on, for the azimuth: +1 right (the person's left arm),
  // -1 left, 0 unknown. Not a setting: taken from the angle file's header (ImageSideOf) or the
  // live engine.
  int image_side = 0;
  // true: the planner checks `kind` against the file (DetectSourceKind); false: `kind` was chosen
  // by the user for a file whose kind cannot be told from its header, and is used as given.
  bool follow_file_kind = true;

  static MappingOptions Default(SourceKind kind);
  // sign is +1 or -1, offsets and holds finite.
  Status Check() const;
  // One line for headers and summaries: "arm j1=+yaw+0 j2=-elevation+0 j3=-flexion+0 ...".
  std::string Describe() const;

  // Maps one sample. `upper_deg` and `bend_deg` may be unwrapped (any multiple of 360 added);
  // `yaw_deg` must be finite (the planner holds the last yaw while it is NaN).
  JointArray Map(double upper_deg, double bend_deg, double yaw_deg) const;
};

// An upper arm within this many degrees of vertical has no azimuth to speak of (its horizontal
// part is under a third of its length, and the azimuth's error grows as 1 / cos(elevation)):
// J1 is held there.
inline constexpr double kAzimuthBlindDeg = 20;

// The 2-D sources that a row's 3-D columns stand for, so that Map() turns them like any arm row
// with J2 from the elevation and J3 from the flexion: `upper` the upper arm's elevation (the
// folded elevation is then el + 90: 0 hanging, 90 level, 180 up), `bend` 180 - elbow_deg (the
// flexion), `yaw` the upper arm's azimuth from the image plane on the arm's side, positive
// towards the camera (image_side +1: az itself; -1: 180 - az), nan while the upper arm is within
// kAzimuthBlindDeg of vertical. False when the row lacks a 3-D value or image_side is 0.
bool SourcesFrom3d(const AngleRow& row, int image_side, double* upper, double* bend, double* yaw);

// The arm's side of the image from an angle file's header: the pose engine's pose.side names the
// person's own arm, seen facing the camera (their left arm on the image's right: +1); 0 when the
// header does not say.
int ImageSideOf(const AngleFile& angles);

// The side SourcesFrom3d reads the rows of `angles` on under `mapping` (`kind` the file's), or 0
// when they are planned from the 2-D columns: a marker file, arm_3d off, or no 3-D columns.
// Also 0 for 3-D columns whose header does not name the side (the plan refuses those).
int SideFor3d(const MappingOptions& mapping, SourceKind kind, const AngleFile& angles);

// "SIGN,OFFSET" with SIGN + or - (or +1/-1), e.g. "-1,-90" or "+,0". Error text or "".
std::string ParseJointMap(const std::string& value, JointMap* out);

}  // namespace armmimic::robot
