#include "armmimic/core/angles.h"

namespace armmimic {

double Wrap180(double deg) {
  if (!std::isfinite(deg)) return deg;
  double r = std::fmod(deg, 360.0);
  if (r <= -180.0) r += 360.0;
  if (r > 180.0) r -= 360.0;
  return r;
}

double FoldToAxis(double deg) {
  if (!std::isfinite(deg)) return deg;
  double r = std::fmod(deg, 180.0);
  if (r <= -90.0) r += 180.0;
  if (r > 90.0) r -= 180.0;
  return r;
}

double DirectionDeg(const cv::Point2d& from_px, const cv::Point2d& to_px) {
  return Wrap180(DegFromRad(std::atan2(-(to_px.y - from_px.y), to_px.x - from_px.x)));
}

cv::Point2d DirectionVector(double deg) {
  const double r = RadFromDeg(deg);
  return {std::cos(r), -std::sin(r)};
}

double AngleDiff(double a_deg, double b_deg) { return Wrap180(a_deg - b_deg); }

double AxisDiff(double a_deg, double b_deg) { return std::fabs(FoldToAxis(a_deg - b_deg)); }

double ResolveDirection(double axis_deg, const cv::Point2d& from_px,
                        const cv::Point2d& towards_px) {
  const cv::Point2d v = DirectionVector(axis_deg);
  const cv::Point2d d = towards_px - from_px;
  const double dot = v.x * d.x + v.y * d.y;
  return dot >= 0 ? Wrap180(axis_deg) : Wrap180(axis_deg + 180.0);
}

void AzimuthElevationDeg(const cv::Vec3d& from, const cv::Vec3d& to, double* az_deg,
                         double* el_deg) {
  const cv::Vec3d d = to - from;
  *az_deg = Wrap180(DegFromRad(std::atan2(-d[2], d[0])));  // -0 would give -180
  *el_deg = DegFromRad(std::atan2(-d[1], std::hypot(d[0], d[2])));
}

double JointAngleDeg(const cv::Vec3d& a, const cv::Vec3d& joint, const cv::Vec3d& b) {
  const cv::Vec3d u = a - joint, v = b - joint;
  // atan2 of the cross and dot products: exact near 0 and 180 where acos is not.
  return DegFromRad(std::atan2(cv::norm(u.cross(v)), u.dot(v)));
}

}  // namespace armmimic
