// Marker-joint scenes with ground truth (thesis chapter 4): the model joint ray cast in 3D as
// two equal, Lambertian-shaded cylinders. The lower one stands upright and turns about its own
// axis (yaw); the upper one bends at the pivot. Two black disc markers lie on the lower part's
// curved surface at +-alpha either side of the front, a distance e below the pivot; one lies on
// the front of the upper part, e above the pivot along its axis. A level pinhole camera (or, for
// the flat model, a parallel projection) looks at it. Truth is the model's own pose, not a
// measurement (docs/synth.md).
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

// The joint's geometry in pixels at the pivot's depth (1 model unit = 1 pixel there).
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
// front towards screen right, i.e. brings the joint's right side (on screen left while it faces
// the camera) towards the camera. Bend tilts the upper part at the pivot, counter-clockwise on
// screen positive (at zero yaw). The contract's yaw_deg is |yaw_deg|.
struct MarkerPose {
  double yaw_deg = 0;
  double bend_deg = 0;
};

// Foreshortening below which a marker counts as hidden (thesis: past about 35 degrees of yaw):
// cos of the angle between a marker's surface normal and the line of sight.
inline constexpr double kMarkerHiddenCos = 0.2588;  // cos(75 deg)

// The camera. Perspective: a level pinhole camera with its principal point at the image centre
// and the given horizontal field of view, placed so that the joint's radius at the pivot's depth
// is model.radius_px (at 60 degrees, 8.7 radii from the axis: a 3 cm joint seen from 26 cm).
// "orthographic" is the flat model: a parallel projection (a camera infinitely far away).
struct MarkerCamera {
  std::string projection = "perspective";  // or "orthographic"
  double fov_deg = 60;
};

struct MarkerSceneOptions {
  uint64_t seed = 1;
  cv::Size size{320, 240};
  int views = 48;                    // images besides the reference
  double max_yaw_deg = 45;           // yaw uniform in [-max, max], up to 180
  double max_bend_deg = 60;          // bend uniform in [-max, max]
  double noise_sigma = 2;            // Gaussian sensor noise, grey levels
  std::string background = "mixed";  // plain, gradient, texture, room; simple (plain or
                                     // gradient, by seed) or mixed (any, by seed)
  std::string lighting = "mixed";    // normal, bright, dim, side, shadow, or mixed (by seed)
  int clutter = 0;  // dark marker-like blobs on the background (some beside markers)
  MarkerCamera camera;
  Status Check() const;  // errors are keyed by the setting ("marker_scene.views")
};

struct MarkerTruth {
  int frame = 0;
  std::string file;    // view_000.png ...; "reference.png" for the reference
  MarkerPose pose;     // signed yaw as rendered
  double yaw_deg = 0;  // |pose.yaw_deg|: the contract's yaw
  double bend_deg = 0;
  // A marker is readable when it faces the camera within 75 degrees and lies inside the image.
  // The view is readable when a lower marker is (it gives the yaw); bend needs the upper one.
  bool readable = false;
  bool left_readable = false, right_readable = false, upper_readable = false;
  // cos(normal, direction to the camera) at each marker's centre, and the smallest of them.
  double left_cos = 0, right_cos = 0, upper_cos = 0;
  double min_marker_cos = 0;
  cv::Point2d upper_px, left_px, right_px;  // projected marker centres (on the surface)
  cv::Point2d pivot_px;
  // A truth-file row: upper/fore nan; extra columns kMarkerTruthExtra.
  TruthRow ToRow() const;
};

// Extra truth columns of marker scenes, after the 12 listed ones.
extern const char* const kMarkerTruthExtra[12];

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
  // Zero yaw and zero bend (the engine's reference).
  cv::Mat Reference(MarkerTruth* truth = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A marker scene folder, for either renderer: OUTDIR/reference.png is `reference`,
// OUTDIR/views/ holds the `views` images `render` draws (each names its file in its truth), and
// OUTDIR/truth.tsv, written last, holds `truth`'s meta and one row a view. An old truth.tsv is
// removed first: it would describe views this run replaces, so until the new one is written the
// folder says it is not a whole scene. Cancelled: no truth.tsv.
Status WriteMarkerSceneFolder(const std::string& outdir, const cv::Mat& reference, int views,
                              const std::function<cv::Mat(int, MarkerTruth*)>& render,
                              TruthFile truth, const std::function<void(int, int)>& progress,
                              const std::atomic<bool>* cancel);

// Writes reference.png, views/view_NNN.png and truth.tsv (with a `file` column) into `outdir`
// (created if missing). Every file appears complete or not at all. An earlier truth.tsv is
// removed first and the new one written last, so a folder with a truth.tsv is a whole scene.
// When `cancel` becomes true no further view is written (the result is an error saying so).
Status WriteMarkerScene(const MarkerSceneOptions& options, const std::string& outdir,
                        const std::function<void(int, int)>& progress,
                        const std::atomic<bool>* cancel = nullptr);

}  // namespace armmimic::synth
