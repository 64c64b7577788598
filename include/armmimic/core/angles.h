// Angle helpers for the contract's conventions: directions in degrees CCW on screen from +x,
// in (-180, 180], with image y pointing down.
#pragma once

#include <cmath>
#include <limits>

#include <opencv2/core/types.hpp>

namespace armmimic {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline double DegFromRad(double rad) { return rad * 180.0 / kPi; }
inline double RadFromDeg(double deg) { return deg * kPi / 180.0; }

// Wraps any angle to (-180, 180].
double Wrap180(double deg);

// Wraps to (-90, 90]: the axis a direction lies on (the thesis' orientation theta).
double FoldToAxis(double deg);

// Direction of the vector from `from_px` to `to_px` in image pixels (y down):
// atan2(-(y2-y1), x2-x1) in degrees, in (-180, 180].
double DirectionDeg(const cv::Point2d& from_px, const cv::Point2d& to_px);

// Unit vector on screen (y down) for a direction in degrees.
cv::Point2d DirectionVector(double deg);

// Signed smallest difference a - b, wrapped to (-180, 180].
double AngleDiff(double a_deg, double b_deg);

// The smallest difference between two axes (mod 180), in [0, 90].
double AxisDiff(double a_deg, double b_deg);

// Of the two directions on axis `axis_deg` (theta and theta+180), the one that points from
// `from_px` towards `towards_px`. Used to resolve a segment's direction from the shoulder.
double ResolveDirection(double axis_deg, const cv::Point2d& from_px, const cv::Point2d& towards_px);

// A 3-D segment's direction, d = to - from in the camera's frame (x to the image's right, y
// down, z away from the camera), as the angle file's 3-D columns give it: azimuth
// atan2(-d_z, d_x) (0: the image's right, +90: at the camera) and elevation
// atan2(-d_y, hypot(d_x, d_z)) (+90: straight up), degrees.
void AzimuthElevationDeg(const cv::Vec3d& from, const cv::Vec3d& to, double* az_deg,
                         double* el_deg);

// The angle at `joint` between the segments to `a` and to `b`, degrees in [0, 180] (180: a
// straight arm at the elbow).
double JointAngleDeg(const cv::Vec3d& a, const cv::Vec3d& joint, const cv::Vec3d& b);

}  // namespace armmimic
