// A second marker-joint renderer, written independently of MarkerSceneRenderer so that the
// marker engine can be scored on views it was not tuned on (docs/marker.md, "Accuracy"). Each
// seed draws its own rig: the joint's radius, marker size and placement, a camera at another
// height, tilted a little and aimed anywhere (the joint may sit near the image's edges), a lens
// with radial distortion, glossy surfaces with specular highlights, a wall behind the joint that
// takes its shadow, slight blur and sensor noise. Poses, truth rows and the folder layout are
// those of `synth marker` (MarkerPose, MarkerTruth, truth.tsv), so the same tools read both.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/synth/marker_scene.h"

namespace armmimic::synth {

struct MarkerRigOptions {
  uint64_t seed = 1;
  cv::Size size{320, 240};
  int views = 28;              // images besides the reference
  double max_yaw_deg = 60;     // yaw uniform in [-max, max]
  double max_bend_deg = 60;    // bend uniform in [-max, max]
  std::string set = "medium";  // easy, medium, hard: how far the rig strays (docs/synth.md)
  Status Check() const;        // errors keyed "marker_scene.<member>"
};

// What one seed drew. Lengths in the joint's radius (R = 1) unless named otherwise.
struct MarkerRig {
  double radius_px = 32;  // the joint's radius at the pivot's depth, pixels
  double marker_radius = 0.2;
  double marker_angle_deg = 40;
  double pivot_distance = 1.8;  // e
  double lower_length = 3.6, upper_length = 3.1;
  double fov_deg = 60;       // horizontal
  double k1 = 0, k2 = 0;     // radial distortion of normalised image coordinates
  cv::Point2d principal_px;  // the lens' centre
  double pitch_deg = 0;      // camera tilt, positive looking down
  double roll_deg = 0;
  double elevation_deg = 0;  // the camera seen from the pivot, above the horizontal
  cv::Point2d pivot_px;      // where the pivot projects
  double blur_px = 0.5;      // Gaussian sigma
  double noise = 2;          // grey levels
  double specular = 0.2, shininess = 30;
  int clutter = 0;
  AngleMeta Describe() const;  // for truth.tsv's meta line
};

class MarkerRigRenderer {
 public:
  // Throws std::invalid_argument when options.Check() fails.
  explicit MarkerRigRenderer(const MarkerRigOptions& options);
  ~MarkerRigRenderer();
  MarkerRigRenderer(const MarkerRigRenderer&) = delete;
  MarkerRigRenderer& operator=(const MarkerRigRenderer&) = delete;

  const MarkerRig& rig() const;
  MarkerPose Pose(int index) const;
  // View `index` (CV_8UC3 BGR) and its truth (file view_NNN.png).
  cv::Mat Render(int index, MarkerTruth* truth = nullptr) const;
  cv::Mat RenderPose(const MarkerPose& pose, uint64_t noise_seed,
                     MarkerTruth* truth = nullptr) const;
  cv::Mat Reference(MarkerTruth* truth = nullptr) const;  // zero yaw, zero bend

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Writes reference.png, views/view_NNN.png and truth.tsv into `outdir` like WriteMarkerScene;
// the meta line adds `renderer=rig`, the set and every drawn rig value (fov_deg among them).
Status WriteMarkerRigScene(const MarkerRigOptions& options, const std::string& outdir,
                           const std::function<void(int, int)>& progress,
                           const std::atomic<bool>* cancel = nullptr);

}  // namespace armmimic::synth
