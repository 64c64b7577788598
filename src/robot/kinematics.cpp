#include "armmimic/robot/kinematics.h"

#include <cmath>

#include <Eigen/Geometry>

namespace armmimic::robot {
namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

Eigen::Matrix3d About(const Eigen::Vector3d& axis, double deg) {
  return Eigen::AngleAxisd(deg * kRadPerDeg, axis).toRotationMatrix();
}

}  // namespace

ArmPose ForwardKinematics(const JointArray& q, const ArmGeometry& g) {
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  ArmPose p;
  p.rotation[0] = Eigen::Matrix3d::Identity();
  // J1 turns about the vertical; J2 and J3 about the horizontal J2 axis (local y), so that a
  // link hanging along local -z swings forward to +x as the angle goes negative.
  p.rotation[1] = About(z, q[0]);
  p.rotation[2] = p.rotation[1] * About(y, q[1]);
  p.rotation[3] = p.rotation[2] * About(y, q[2]);
  // The wrist: J4 rolls about the forearm, J5 bends across it, J6 rolls the flange.
  p.rotation[4] = p.rotation[3] * About(z, q[3]);
  p.rotation[5] = p.rotation[4] * About(y, q[4]);
  p.rotation[6] = p.rotation[5] * About(z, q[5]);
  p.base = Eigen::Vector3d::Zero();
  p.shoulder = g.shoulder_height_m * z;
  p.shoulder_side = p.shoulder + p.rotation[1] * (g.shoulder_offset_m * y);
  p.elbow = p.shoulder_side + p.rotation[2] * (-g.upper_arm_m * z);
  p.wrist = p.elbow + p.rotation[3] * (-g.forearm_m * z);
  p.flange = p.wrist + p.rotation[5] * (-g.flange_m * z);
  return p;
}

std::vector<ArmPart> ArmParts(const ArmPose& p, const ArmGeometry& g) {
  const double r = g.upper_arm_m * 0.12;  // link thickness, in proportion to the arm
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d side = p.rotation[1] * Eigen::Vector3d::UnitY();
  std::vector<ArmPart> parts;
  // Pedestal and the column J1 turns, up to just under the shoulder housing.
  parts.push_back({p.base, p.shoulder - 1.6 * r * z, 1.3 * r, -1});
  parts.push_back({p.shoulder - 1.6 * r * z, p.shoulder, 1.2 * r, 0});
  // Shoulder housing along the J2 axis, from the column out to the upper arm's side.
  parts.push_back({p.shoulder - 0.6 * r * side, p.shoulder_side + 0.6 * r * side, 1.1 * r, 0});
  parts.push_back({p.shoulder_side, p.elbow, r, 1});
  // Elbow knuckle along the J3 axis, then the forearm.
  parts.push_back({p.elbow - 0.9 * r * side, p.elbow + 0.9 * r * side, 0.9 * r, 2});
  parts.push_back({p.elbow, p.wrist, 0.75 * r, 2});
  // The wrist body (J4 rolls it), the flange (J5 bends it) and a finger off the flange's axis,
  // so that J6's roll is seen.
  const Eigen::Vector3d wrist_axis = p.rotation[5] * Eigen::Vector3d::UnitY();
  parts.push_back({p.wrist - 0.7 * r * wrist_axis, p.wrist + 0.7 * r * wrist_axis, 0.6 * r, 3});
  parts.push_back({p.wrist, p.flange, 0.45 * r, 4});
  const Eigen::Vector3d finger_base =
      p.flange + p.rotation[6] * (0.35 * r * Eigen::Vector3d::UnitX());
  parts.push_back(
      {finger_base, finger_base + p.rotation[6] * (-0.5 * g.flange_m * z), 0.15 * r, 5});
  return parts;
}

std::array<bool, kJoints> JointsOutside(const JointLimits& limits, const JointArray& q) {
  std::array<bool, kJoints> out{};
  for (int j = 0; j < kJoints; ++j) out[j] = !limits.Inside(j, q[j]);
  return out;
}

namespace {

// A segment's direction from its azimuth and elevation in the camera's frame, in the robot's
// base frame (outward on the arm's side +x, towards the camera +y, up +z).
Eigen::Vector3d DirectionInBase(double az_deg, double el_deg, int image_side) {
  const double az = az_deg * M_PI / 180, el = el_deg * M_PI / 180;
  return {image_side * std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

}  // namespace

bool PersonArmFromRow(const AngleRow& row, int image_side, PersonArm* out, double beside_m,
                      const ArmGeometry& geometry) {
  if (!row.ok() || image_side == 0) return false;
  for (double v : {row.upper_az_deg, row.upper_el_deg, row.fore_az_deg, row.fore_el_deg}) {
    if (!std::isfinite(v)) return false;
  }
  out->shoulder = Eigen::Vector3d(0, -beside_m, geometry.shoulder_height_m);
  out->elbow = out->shoulder + geometry.upper_arm_m *
                                   DirectionInBase(row.upper_az_deg, row.upper_el_deg, image_side);
  out->wrist = out->elbow +
               geometry.forearm_m * DirectionInBase(row.fore_az_deg, row.fore_el_deg, image_side);
  return true;
}

}  // namespace armmimic::robot
