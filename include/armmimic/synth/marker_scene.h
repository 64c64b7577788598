// Marker-joint scenes with ground truth (thesis chapter 4): the model joint rendered in 3D as
// two equal cylinders. The lower one stands upright and turns about its own axis (yaw); the
// upper one bends at the pivot. Two black disc markers sit on the lower part's surface at
// +-alpha either side of the front, a distance e below the pivot; one black disc sits on the
// front of the upper part, e above the pivot along its axis. Orthographic camera looking along
// the horizontal. Truth is the model's own pose, not a measurement (docs/marker.md).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"
#include "armmimic/synth/truth_file.h"

namespace armmimic::synth {

// The joint's geometry in pixels (orthographic: 1 model unit = 1 pixel).
struct MarkerJointModel {
  double radius_px = 32;           // R, both cylinders
  double lower_length_px = 112;    // pivot down to the lower part's bottom
  double upper_length_px = 100;    // pivot up to the upper part's top
  double marker_radius_px = 6.5;   // r: disc radius, measured on the surface
  double marker_angle_deg = 40;    // alpha: lower markers at +-alpha from the front
  double pivot_distance_px = 58;   // e: pivot to every marker centre, along the part's axis
  cv::Point2d pivot_px{160, 118};  // where the pivot projects
  // The default model for a 320x240 image, scaled to `size` (by its height) and centred.
  static MarkerJointModel ForSize(cv::Size size);
};

// A pose: yaw turns the whole joint about the lower part's vertical axis; positive turns the
// front towards screen right. Bend tilts the upper part at the pivot, counter-clockwise on screen
// positive (at zero yaw). The contract's yaw_deg is |yaw_deg| (acos cannot tell the sign).
struct MarkerPose {
  double yaw_deg = 0;
  double bend_deg = 0;
};

// Foreshortening below which a marker counts as hidden (thesis: past about 35 degrees of yaw):
// cos of the angle between a marker's surface normal and the line of sight.
inline constexpr double kMarkerHiddenCos = 0.2588;  // cos(75 deg)

struct MarkerSceneOptions {
  uint64_t seed = 1;
  cv::Size size{320, 240};
  int views = 48;                    // images besides the reference
  double max_yaw_deg = 45;           // yaw uniform in [-max, max]: past ~35 a lower marker hides
  double max_bend_deg = 60;          // bend uniform in [-max, max]
  double noise_sigma = 2;            // Gaussian sensor noise, grey levels
  std::string background = "mixed";  // plain, gradient, texture, room, or mixed (by seed)
  std::string lighting = "mixed";    // normal, bright, dim, side, shadow, or mixed (by seed)
  int clutter = 0;       // dark marker-like blobs on the background (some beside markers)
  Status Check() const;  // messages name the option
};

struct MarkerTruth {
  int frame = 0;
  std::string file;    // view_000.png ...; "reference.png" for the reference
  MarkerPose pose;     // signed yaw as rendered
  double yaw_deg = 0;  // |pose.yaw_deg|: the contract's yaw
  double bend_deg = 0;
  bool readable = false;      // every marker faces the camera within 75 deg and is in view
  double min_marker_cos = 0;  // the most foreshortened marker's cos(normal, line of sight)
  cv::Point2d upper_px, left_px, right_px;  // projected marker centres (on the surface)
  cv::Point2d pivot_px;
  // A truth-file row: upper/fore nan; extra columns kMarkerTruthExtra.
  TruthRow ToRow() const;
};

// Extra truth columns of marker scenes, after the 12 listed ones.
extern const char* const kMarkerTruthExtra[9];

class MarkerSceneRenderer {
 public:
  // Throws std::invalid_argument when options.Check() fails.
  explicit MarkerSceneRenderer(const MarkerSceneOptions& options);
  ~MarkerSceneRenderer();
  MarkerSceneRenderer(const MarkerSceneRenderer&) = delete;
  MarkerSceneRenderer& operator=(const MarkerSceneRenderer&) = delete;

  const MarkerSceneOptions& options() const;
  const MarkerJointModel& model() const;
  const std::string& background_kind() const;  // after resolving "mixed"
  const std::string& lighting_kind() const;
  // The pose of view `index` (0 <= index < views) without rendering it.
  MarkerPose Pose(int index) const;
  MarkerTruth Truth(int index) const;
  // View `index`, CV_8UC3 BGR; the same for a given seed and index whatever the call order.
  cv::Mat Render(int index, MarkerTruth* truth = nullptr) const;
  // Any pose in the same scene; `noise_seed` picks the noise.
  cv::Mat RenderPose(const MarkerPose& pose, uint64_t noise_seed,
                     MarkerTruth* truth = nullptr) const;
  // Zero yaw and zero bend (gives the engine N and e).
  cv::Mat Reference(MarkerTruth* truth = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Writes reference.png, views/view_NNN.png and truth.tsv (with a `file` column) into `outdir`
// (created if missing). Every file appears complete or not at all. An earlier truth.tsv is
// removed first and the new one written last, so a folder with a truth.tsv is a whole scene.
// When `cancel` becomes true no further view is written (the result is an error saying so).
Status WriteMarkerScene(const MarkerSceneOptions& options, const std::string& outdir,
                        const std::function<void(int, int)>& progress,
                        const std::atomic<bool>* cancel = nullptr);

}  // namespace armmimic::synth
