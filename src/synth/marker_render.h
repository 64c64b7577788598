// Private: the ray caster behind MarkerSceneRenderer (orthographic view of the model joint).
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

// Composites the joint in `pose` over `canvas` (CV_32FC3, grey levels 0..255), with edges and
// markers antialiased by supersampling.
void RenderMarkerJoint(const MarkerJointModel& model, const MarkerPose& pose,
                       const MarkerLight& light, const MarkerMaterial& material, cv::Mat* canvas);

// Exact projections of the marker centres and their foreshortening for `pose`.
void ProjectMarkerJoint(const MarkerJointModel& model, const MarkerPose& pose, cv::Size size,
                        MarkerTruth* truth);

}  // namespace armmimic::synth::internal
