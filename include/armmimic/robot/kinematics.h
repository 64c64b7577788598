// Kinematics: where the PUMA 760's links are for a set of joint angles, for the 3-D robot view.
// Link lengths are the PUMA 760 model's (docs/robot.md, "The arm in 3-D"); the joint zeros and
// directions are armmimic's own, as the mapping and the compact 2-D views use them: J2 = 0 hangs
// the upper arm straight down, J2 = -90 holds it forward and level, J2 = -180 raises it straight
// up; J3 = 0 is a straight elbow and J3 < 0 flexes it the way J2 < 0 raises the arm.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "armmimic/core/angle_file.h"
#include "armmimic/robot/limits.h"

namespace armmimic::robot {

// Metres. The base frame has z up, x forward (where J1 = 0 points the arm) and y to the left.
struct ArmGeometry {
  double shoulder_height_m = 1.12;  // base plane to the J2 axis
  double upper_arm_m = 0.65;        // J2 axis to J3 axis
  double shoulder_offset_m = 0.19;  // the arm's plane beside the J1 axis, along the J2 axis
  double forearm_m = 0.60;          // J3 axis to the wrist centre (J4/J5/J6 axes meet)
  double flange_m = 0.10;           // wrist centre to the tool flange (drawn, not a model value)
};

struct ArmPose {
  Eigen::Vector3d base;           // on the base plane, under the J1 axis
  Eigen::Vector3d shoulder;       // on the J1 axis, at the J2 axis
  Eigen::Vector3d shoulder_side;  // where the upper arm leaves the J2 axis (offset sideways)
  Eigen::Vector3d elbow;
  Eigen::Vector3d wrist;   // wrist centre
  Eigen::Vector3d flange;  // tool flange centre
  // Orientation of each joint's body in the base frame: [0] the base, [j] the body J(j) moves.
  // Column 2 (local z) of [2..6] points back along the link, from its tip towards its joint.
  std::array<Eigen::Matrix3d, kJoints + 1> rotation;
};

ArmPose ForwardKinematics(const JointArray& joint_deg, const ArmGeometry& geometry = {});

// One solid of the drawn arm: a cylinder from `from` to `to`. `joint` is the joint (0-based)
// whose motion it shows, -1 for the fixed base.
struct ArmPart {
  Eigen::Vector3d from;
  Eigen::Vector3d to;
  double radius_m = 0;
  int joint = -1;
};

// The solids of the arm in `pose`, base first: pedestal, shoulder housing (J1), upper arm (J2),
// forearm (J3), wrist (J4, J5) and flange with an off-centre finger that shows J6's roll.
std::vector<ArmPart> ArmParts(const ArmPose& pose, const ArmGeometry& geometry = {});

// The person's arm of an angle row's 3-D columns (docs/robot.md, "Mapping the 3-D columns"),
// placed beside the robot in its base frame so that the two can be compared: each segment's
// direction turned the way the default mapping turns the robot (the arm's outward direction in
// the image plane is +x, towards the camera +y, up +z), with the robot's link lengths, from a
// shoulder `beside_m` to the robot's right (-y) at the robot's shoulder height.
struct PersonArm {
  Eigen::Vector3d shoulder, elbow, wrist;
};
// image_side: +1 the arm on the image's right, -1 on its left (ImageSideOf). False when the row
// is not ok, lacks a 3-D value, or the side is 0.
bool PersonArmFromRow(const AngleRow& row, int image_side, PersonArm* out, double beside_m = 0.9,
                      const ArmGeometry& geometry = {});

// The joints of `joint_deg` outside `limits`: the view draws their parts red.
std::array<bool, kJoints> JointsOutside(const JointLimits& limits, const JointArray& joint_deg);

}  // namespace armmimic::robot
