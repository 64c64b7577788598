// Private: the ray tracer behind MarkerRigRenderer. It shares no code with marker_render.cpp:
// a camera with a pose (height, tilt, roll) and a distorting lens, glossy capped cylinders, a
// wall behind the joint that takes its shadow.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/synth/marker_scene.h"

namespace armmimic::synth::rig {

using V3 = cv::Vec3d;

// A pinhole camera with radial distortion. World frame: the pivot at the origin, y up, z towards
// the camera's side of the joint. Camera frame: x right, y down, z forward.
struct RigCamera {
  V3 centre;               // in the world
  cv::Matx33d from_world;  // camera = from_world * (world - centre)
  double focal_px = 277;
  cv::Point2d principal_px{160, 120};
  double k1 = 0, k2 = 0;
  // Image point of a world point; false when it lies behind the camera.
  bool Project(const V3& world, cv::Point2d* px) const;
  // Unit direction (world) of the ray seen at image point (u, v): undistorts iteratively.
  V3 Ray(double u, double v) const;
};

struct WallRect {
  cv::Rect2d box;  // wall coordinates (world x, y)
  V3 bgr;          // 0..1 albedo
};
struct WallDisc {
  cv::Point2d centre;
  double rx = 0.3, ry = 0.3, angle = 0;
  double albedo = 0.15;
};

struct RigScene {
  RigCamera camera;
  // The joint, in radii.
  double marker_radius = 0.2, marker_angle = 0.7, e = 1.8;
  double lower_length = 3.6, upper_length = 3.1;
  V3 body_bgr{0.85, 0.85, 0.85};
  double marker_albedo = 0.15;
  double specular = 0.2, shininess = 30, marker_gloss = 0.4;
  // Light: a distant source (world direction towards it) and ambient share.
  V3 light{-0.3, 0.5, 0.8};
  double ambient = 0.35, gain = 1.0;
  // The wall: the plane z = -wall_depth; base colour, a linear gradient, ripples, rectangles
  // (posters) and dark discs (clutter).
  double wall_depth = 6;
  V3 wall_bgr{0.7, 0.7, 0.7};
  cv::Vec2d wall_gradient{0, 0};  // albedo change per radius in x and y
  double ripple = 0;              // albedo amplitude of the texture
  cv::Vec3d ripple_freq{0.7, 1.3, 2.1};
  std::vector<WallRect> posters;
  std::vector<WallDisc> discs;
};

// Traces `pose` into `out` (CV_32FC3, grey levels 0..255), 3x3 samples a pixel.
void TraceRig(const RigScene& scene, const MarkerPose& pose, cv::Size size, cv::Mat* out);

// The markers' projections and how squarely they face the camera (kMarkerHiddenCos).
void RigTruth(const RigScene& scene, const MarkerPose& pose, cv::Size size, MarkerTruth* truth);

}  // namespace armmimic::synth::rig
