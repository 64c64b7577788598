// Private: the ray caster behind MarkerSceneRenderer (the model joint seen by a pinhole camera,
// or by a parallel projection for the flat model).
#pragma once

#include <opencv2/core.hpp>

#include "armmimic/synth/marker_scene.h"

namespace armmimic::synth::internal {

struct MarkerLight {
  cv::Vec3d dir{-0.35, 0.45, 0.82};  // towards the light, world frame (x right, y up, z to camera)
  double ambient = 0.4;              // share of light that does not depend on the normal
  double gain = 1.0;                 // overall illumination
};

struct MarkerMaterial {
  cv::Vec3d cylinder_bgr{0.86, 0.86, 0.84};  // albedo per channel
  double marker_albedo = 0.2;                // black paper
};

// Where the camera is. World frame: x right, y up, z towards the camera; the camera centre is the
// origin and looks along -z with its rows horizontal. Model lengths are pixels at the pivot's
// depth, so the pivot sits at depth `focal_px` (perspective) and projects to model.pivot_px.
struct MarkerView {
  bool perspective = true;
  double focal_px = 277;  // horizontal and vertical focal length
  cv::Point2d principal_px{160, 120};
  // The pivot in the world frame (perspective), or in the image (parallel projection).
  cv::Vec3d pivot_world;
  static MarkerView Make(const MarkerJointModel& model, const MarkerCamera& camera, cv::Size size);
};

// Composites the joint in `pose` over `canvas` (CV_32FC3, grey levels 0..255), with edges and
// markers antialiased by supersampling.
void RenderMarkerJoint(const MarkerJointModel& model, const MarkerView& view,
                       const MarkerPose& pose, const MarkerLight& light,
                       const MarkerMaterial& material, cv::Mat* canvas);

// Exact projections of the marker centres and how squarely each faces the camera for `pose`.
void ProjectMarkerJoint(const MarkerJointModel& model, const MarkerView& view,
                        const MarkerPose& pose, cv::Size size, MarkerTruth* truth);

}  // namespace armmimic::synth::internal
