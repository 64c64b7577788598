// Private: the lower part of the marker joint as a cylinder seen by a level camera
// (docs/marker.md, "The cylinder model"): its silhouette in the image, the mapping between image
// columns and angles on its surface, and the column profile of its shading.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace armmimic::internal {

// A level pinhole camera with square pixels; `focal_px` <= 0 means a parallel projection.
struct MarkerCamera {
  double focal_px = 0;
  cv::Point2d principal_px;
  // A parallel projection is a pinhole camera this far away (in focal lengths of the image).
  static MarkerCamera FromFov(double fov_deg, cv::Size size);
};

// Where the lower part is: its two silhouette edges at one image row give its axis direction and
// its distance from the camera. Lengths are in cylinder radii (R = 1), angles in radians.
// theta is the angle of a surface point about the axis, measured from the direction towards the
// camera, positive towards screen right.
class CylinderView {
 public:
  CylinderView() = default;
  CylinderView(const MarkerCamera& camera, double left_edge_px, double right_edge_px);

  bool valid() const { return distance_ > 1; }
  // theta of the surface point seen at image column x (clamped to the limbs).
  double ThetaFromX(double x) const;
  double XFromTheta(double theta) const;
  // d theta / d x at column x (radians per pixel).
  double ThetaSlope(double x) const;
  // The limbs are at +-limb(): pi/2 - asin(1 / distance).
  double limb() const { return limb_; }
  // Angle between the surface normal at theta and the direction to the camera.
  double Facing(double theta) const;
  // Depth (along the optical axis) of the surface point at theta, in radii.
  double Depth(double theta) const;
  // Horizontal position of the surface point at theta in the camera frame (x right, z depth).
  cv::Point2d Horizontal(double theta) const;
  double distance() const { return distance_; }  // camera centre to axis, in radii
  double axis_angle() const { return phi0_; }    // axis direction from the optical axis
  double axis_x() const { return axis_x_; }      // image column of the axis
  double half_width_px() const { return half_width_px_; }
  const MarkerCamera& camera() const { return camera_; }

 private:
  MarkerCamera camera_;
  double phi0_ = 0, distance_ = 0, limb_ = 0, axis_x_ = 0, half_width_px_ = 0;
};

// Mean grey level of the columns [x0, x0 + width) over `rows` of `gray`.
void ColumnProfile(const cv::Mat& gray, const std::vector<int>& rows, int x0, int width,
                   std::vector<double>* out);

// A silhouette edge in a column profile: the steepest step, with sub-pixel position (parabola
// through the gradient's peak) and its signed strength (grey levels per pixel).
struct ProfileEdge {
  double x = 0;
  double strength = 0;
  bool found = false;
};
// Searches profile columns [from, to] (indices into `profile`, whose first column is image
// column x0). `sign` (+1 rising, -1 falling, 0 either) picks the step's direction.
ProfileEdge FindProfileEdge(const std::vector<double>& profile, int x0, int from, int to, int sign);

// The silhouette edge's position to a fraction of a pixel, for one side of the profile (`inside`
// +1: the cylinder lies to the right of the edge, -1: to the left), searched within `range`
// pixels of `start`. Near a limb the surface's grey level runs like p + q sqrt(d) + r d with the
// distance d from the edge (the surface turns away ever faster), and the background is linear;
// each pixel sees both through its own width and the optics' blur (a Gaussian whose width, up to
// 1.4 px, is fitted with the edge: a model without it had put a blurred limb's edge up to 3 px
// inside it, where the shading's steep start is). The position with the smallest squared misfit
// wins. Finds an edge even where the limb is as bright as the background behind it (the kink
// remains).
double FitProfileEdge(const std::vector<double>& profile, int x0, double start, double range,
                      int inside);

// Centroid factor k of a disc of angular radius `delta` on a unit cylinder: seen from afar, the
// coverage-weighted centre of a disc centred at theta lies k * sin(theta) from the axis.
double DiscCentroidFactor(double delta);

}  // namespace armmimic::internal
