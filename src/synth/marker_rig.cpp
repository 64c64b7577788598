// The rig renderer's scenes (docs/synth.md, "The rig renderer"): one seed draws the joint, the
// camera, the lens, the light and the wall within the ranges of its set; views, truth and the
// folder writer. The tracing is in marker_rig_trace.cpp.
// Length: DrawRig draws every value of the rig from one seeded generator in a fixed order.
#include "armmimic/synth/marker_rig.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "marker_rig_trace.h"

namespace armmimic::synth {

Status MarkerRigOptions::Check() const {
  if (size.width < 160 || size.height < 120 || size.width > 4096 || size.height > 4096 ||
      size.width * 3 < size.height * 4) {
    return Status::Error("marker_scene.size", "the image size " + std::to_string(size.width) + "x" +
                                                  std::to_string(size.height) +
                                                  " is out of range (160x120 .. 4096x4096, 4:3 "
                                                  "or wider)");
  }
  if (views < 1 || views > 100000) {
    return Status::Error("marker_scene.views", "the number of views must be in [1, 100000]");
  }
  if (!(max_yaw_deg >= 0 && max_yaw_deg <= 180)) {
    return Status::Error("marker_scene.max_yaw_deg", "the largest yaw must be in [0, 180] degrees");
  }
  if (!(max_bend_deg >= 0 && max_bend_deg <= 80)) {
    return Status::Error("marker_scene.max_bend_deg",
                         "the largest bend must be in [0, 80] degrees");
  }
  if (set != "easy" && set != "medium" && set != "hard") {
    return Status::Error("marker_scene.set",
                         "the set '" + set + "' is not one of easy, medium, hard");
  }
  return Status::Ok();
}

AngleMeta MarkerRig::Describe() const {
  return {{"radius_px", FormatNumber(radius_px, 2)},
          {"marker_radius", FormatNumber(marker_radius, 3)},
          {"marker_angle_deg", FormatNumber(marker_angle_deg, 2)},
          {"pivot_distance", FormatNumber(pivot_distance, 3)},
          {"fov_deg", FormatNumber(fov_deg, 2)},
          {"k1", FormatNumber(k1, 4)},
          {"k2", FormatNumber(k2, 4)},
          {"principal", FormatNumber(principal_px.x, 1) + "," + FormatNumber(principal_px.y, 1)},
          {"pitch_deg", FormatNumber(pitch_deg, 2)},
          {"roll_deg", FormatNumber(roll_deg, 2)},
          {"elevation_deg", FormatNumber(elevation_deg, 2)},
          {"pivot", FormatNumber(pivot_px.x, 1) + "," + FormatNumber(pivot_px.y, 1)},
          {"blur_px", FormatNumber(blur_px, 2)},
          {"noise", FormatNumber(noise, 2)},
          {"specular", FormatNumber(specular, 3)},
          {"shininess", FormatNumber(shininess, 1)},
          {"clutter", std::to_string(clutter)}};
}

namespace {

using rig::V3;

double U(cv::RNG& rng, double lo, double hi) { return rng.uniform(lo, hi); }

V3 Tinted(cv::RNG& rng, double lo, double hi, double tint) {
  const double g = U(rng, lo, hi);
  return V3(g + U(rng, -tint, tint), g + U(rng, -tint, tint), g + U(rng, -tint, tint));
}

// Where the ray from the camera through world point p meets the wall.
cv::Point2d OnWall(const rig::RigScene& sc, const V3& p) {
  const V3 c = sc.camera.centre, d = p - c;
  const double t = (-sc.wall_depth - c[2]) / d[2];
  return {c[0] + t * d[0], c[1] + t * d[1]};
}

void DrawRig(const MarkerRigOptions& o, MarkerRig* rig, rig::RigScene* sc) {
  cv::RNG rng(o.seed * 0xD1B54A32D192ED03ULL + 977);
  const bool easy = o.set == "easy", hard = o.set == "hard";
  const double w = o.size.width, h = o.size.height, k = h / 240.0;
  MarkerRig& r = *rig;
  r.radius_px = (easy ? U(rng, 26, 38) : U(rng, 20, 44)) * k;
  r.marker_radius = easy ? U(rng, 0.17, 0.25) : U(rng, 0.13, 0.30);
  r.marker_angle_deg = easy ? U(rng, 34, 46) : U(rng, 28, 55);
  r.pivot_distance = easy ? U(rng, 1.6, 2.0) : U(rng, 1.45, 2.2);
  r.lower_length = r.pivot_distance + U(rng, 1.3, 2.0);
  r.upper_length = r.pivot_distance + U(rng, 1.0, 1.5);
  r.fov_deg = easy ? U(rng, 55, 65) : U(rng, 48, 72);
  r.k1 = easy ? U(rng, -0.03, 0.03) : hard ? U(rng, -0.09, 0.06) : U(rng, -0.07, 0.05);
  r.k2 = easy ? 0 : U(rng, -0.02, 0.02);
  const double pp = easy ? 0 : 2 * k;
  r.principal_px = {w / 2 + U(rng, -pp, pp), h / 2 + U(rng, -pp, pp)};
  r.pitch_deg = easy ? U(rng, -3, 3) : U(rng, -7, 7);
  r.roll_deg = easy ? 0 : hard ? U(rng, -0.8, 0.8) : U(rng, -0.5, 0.5);
  const double reach = (r.pivot_distance + r.marker_radius) * r.radius_px;
  const std::array<double, 2> across = {1.15 * r.radius_px + 3, w - 1.15 * r.radius_px - 3};
  const std::array<double, 2> down = {reach + 3, h - reach - 1.5};
  r.blur_px = (easy ? U(rng, 0.3, 0.5) : hard ? U(rng, 0.5, 0.9) : U(rng, 0.4, 0.7)) * k;
  r.noise = easy ? 1.5 : hard ? 3 : 2;
  r.specular = easy ? U(rng, 0.05, 0.15) : hard ? U(rng, 0.15, 0.4) : U(rng, 0.1, 0.3);
  r.shininess = U(rng, 15, 60);
  r.clutter = hard ? 8 : 0;

  rig::RigCamera& cam = sc->camera;
  cam.focal_px = (w / 2) / std::tan(RadFromDeg(r.fov_deg) / 2);
  cam.principal_px = r.principal_px;
  cam.k1 = r.k1;
  cam.k2 = r.k2;
  const double p = RadFromDeg(r.pitch_deg), q = RadFromDeg(r.roll_deg);
  const cv::Matx33d base(1, 0, 0, 0, -1, 0, 0, 0, -1);
  const cv::Matx33d pitch(1, 0, 0, 0, std::cos(p), -std::sin(p), 0, std::sin(p), std::cos(p));
  const cv::Matx33d roll(std::cos(q), -std::sin(q), 0, std::sin(q), std::cos(q), 0, 0, 0, 1);
  cam.from_world = roll * pitch * base;
  // Place the camera so that the pivot (the world origin) is seen at pivot_px, one radius being
  // radius_px there: anywhere the reference shows the three markers whole, near a side or the
  // bottom edge too.
  const double distance = cam.focal_px / r.radius_px;
  const double a = RadFromDeg(r.marker_angle_deg), e = r.pivot_distance, mr = r.marker_radius;
  for (int attempt = 0; attempt < 100; ++attempt) {
    r.pivot_px = {U(rng, across[0], across[1]), U(rng, down[0], down[1])};
    cam.centre = V3(0, 0, 0);
    const V3 towards_pivot = cam.Ray(r.pivot_px.x, r.pivot_px.y);  // world, from the camera
    cam.centre = -distance * towards_pivot;
    bool whole = true;
    for (const V3& c :
         {V3(-std::sin(a), -e, std::cos(a)), V3(std::sin(a), -e, std::cos(a)), V3(0, e, 1)}) {
      for (const V3& d : {V3(mr, 0, 0), V3(-mr, 0, 0), V3(0, mr, 0), V3(0, -mr, 0)}) {
        cv::Point2d px;
        whole &= cam.Project(c + d, &px) && px.x >= 1.5 && px.y >= 1.5 && px.x <= w - 2.5 &&
                 px.y <= h - 2.5;
      }
    }
    if (whole) break;
  }
  r.elevation_deg = DegFromRad(std::asin(cam.centre[1] / cv::norm(cam.centre)));

  sc->marker_radius = r.marker_radius;
  sc->marker_angle = RadFromDeg(r.marker_angle_deg);
  sc->e = r.pivot_distance;
  sc->lower_length = r.lower_length;
  sc->upper_length = r.upper_length;
  sc->body_bgr = Tinted(rng, 0.7, 0.9, 0.05);
  sc->marker_albedo = U(rng, 0.06, 0.2);
  sc->specular = r.specular;
  sc->shininess = r.shininess;
  // Easy: the light beside the camera, so the joint's shadow falls mostly behind it.
  sc->light = easy ? cv::normalize(V3(U(rng, -0.15, 0.15), U(rng, 0.1, 0.35), 0.9))
                   : cv::normalize(V3(U(rng, -0.9, 0.9), U(rng, 0.1, 0.6), U(rng, 0.4, 0.9)));
  sc->ambient = U(rng, 0.25, 0.45);
  sc->gain = easy ? U(rng, 0.9, 1.1) : U(rng, 0.75, 1.2);
  sc->wall_depth = U(rng, 3, 10);
  sc->wall_bgr = Tinted(rng, 0.4, 0.85, 0.05);
  sc->wall_gradient = {U(rng, -0.03, 0.03), U(rng, -0.03, 0.03)};
  if (!easy) {
    sc->ripple = U(rng, 0, 0.12);
    sc->ripple_freq = {U(rng, 0.3, 1.5), U(rng, 0.3, 1.5), U(rng, 0.5, 2.5)};
    const int posters = rng.uniform(0, 4);
    const double span = (distance + sc->wall_depth) * std::tan(RadFromDeg(r.fov_deg) / 2);
    for (int i = 0; i < posters; ++i) {
      const double pw = U(rng, 0.1, 0.4) * span, ph = U(rng, 0.1, 0.4) * span;
      sc->posters.push_back({cv::Rect2d(U(rng, -span, span - pw), U(rng, -span, span - ph), pw, ph),
                             Tinted(rng, 0.3, 0.9, 0.1)});
    }
  }
  // Dark blobs: every third beside the lower markers, every third within the upper marker's
  // reach, the rest anywhere in view.
  const double grow = (distance + sc->wall_depth) / distance;
  for (int i = 0; i < r.clutter; ++i) {
    V3 near;
    if (i % 3 == 0) {
      const double side = U(rng, 0, 1) < 0.5 ? -1 : 1;
      near = V3(side * (1 + U(rng, 0.25, 1.2)), -r.pivot_distance + U(rng, -0.2, 0.2), 0);
    } else if (i % 3 == 1) {
      const double a = RadFromDeg(U(rng, -90, 90)), d = r.pivot_distance * U(rng, 0.8, 1.25);
      near = V3(-d * std::sin(a), d * std::cos(a), 0);
    } else {
      near = V3(U(rng, -4, 4), U(rng, -4, 3), 0);
    }
    rig::WallDisc disc;
    disc.centre = OnWall(*sc, near);
    disc.rx = U(rng, 0.12, 0.3) * grow;
    disc.ry = U(rng, 0.12, 0.3) * grow;
    disc.angle = U(rng, 0, kPi);
    disc.albedo = U(rng, 0.08, 0.25);
    sc->discs.push_back(disc);
  }
}

}  // namespace

struct MarkerRigRenderer::Impl {
  MarkerRigOptions options;
  MarkerRig rig;
  rig::RigScene scene;
  std::vector<MarkerPose> poses;
};

MarkerRigRenderer::MarkerRigRenderer(const MarkerRigOptions& options)
    : impl_(std::make_unique<Impl>()) {
  const Status st = options.Check();
  if (!st) throw std::invalid_argument("MarkerRigRenderer: " + st.message());
  Impl& m = *impl_;
  m.options = options;
  DrawRig(options, &m.rig, &m.scene);
  cv::RNG rng(options.seed * 0xA24BAED4963EE407ULL + 31);
  m.poses.resize(options.views);
  for (MarkerPose& p : m.poses) {
    p.yaw_deg = rng.uniform(-options.max_yaw_deg, options.max_yaw_deg);
    p.bend_deg = rng.uniform(-options.max_bend_deg, options.max_bend_deg);
  }
}

MarkerRigRenderer::~MarkerRigRenderer() = default;

const MarkerRig& MarkerRigRenderer::rig() const { return impl_->rig; }

MarkerPose MarkerRigRenderer::Pose(int index) const {
  if (index < 0 || index >= static_cast<int>(impl_->poses.size())) {
    throw std::out_of_range("MarkerRigRenderer: no view " + std::to_string(index));
  }
  return impl_->poses[index];
}

cv::Mat MarkerRigRenderer::RenderPose(const MarkerPose& pose, uint64_t noise_seed,
                                      MarkerTruth* truth) const {
  const Impl& m = *impl_;
  cv::Mat canvas;
  rig::TraceRig(m.scene, pose, m.options.size, &canvas);
  cv::GaussianBlur(canvas, canvas, cv::Size(0, 0), m.rig.blur_px);
  cv::Mat noise(canvas.size(), CV_32FC3);
  cv::RNG rng(noise_seed * 0x9E3779B97F4A7C15ULL + m.options.seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, m.rig.noise);
  canvas += noise;
  cv::Mat out;
  canvas.convertTo(out, CV_8UC3);
  if (truth) rig::RigTruth(m.scene, pose, m.options.size, truth);
  return out;
}

cv::Mat MarkerRigRenderer::Render(int index, MarkerTruth* truth) const {
  cv::Mat image = RenderPose(Pose(index), static_cast<uint64_t>(index) + 1, truth);
  if (truth) {
    truth->frame = index;
    char name[32];
    std::snprintf(name, sizeof(name), "view_%03d.png", index);
    truth->file = name;
  }
  return image;
}

cv::Mat MarkerRigRenderer::Reference(MarkerTruth* truth) const {
  cv::Mat image = RenderPose(MarkerPose{}, 1000003, truth);
  if (truth) {
    truth->frame = 0;
    truth->file = "reference.png";
  }
  return image;
}

Status WriteMarkerRigScene(const MarkerRigOptions& options, const std::string& outdir,
                           const std::function<void(int, int)>& progress,
                           const std::atomic<bool>* cancel) {
  const Status st = options.Check();
  if (!st) return st;
  const MarkerRigRenderer scene(options);
  TruthFile truth;
  truth.meta = {{"scene", "marker"},
                {"renderer", "rig"},
                {"set", options.set},
                {"seed", std::to_string(options.seed)},
                {"width", std::to_string(options.size.width)},
                {"height", std::to_string(options.size.height)}};
  for (const auto& kv : scene.rig().Describe()) truth.meta.push_back(kv);
  truth.meta.emplace_back("reference", "reference.png");
  truth.meta.emplace_back("views", "views");
  return WriteMarkerSceneFolder(
      outdir, scene.Reference(), options.views,
      [&scene](int i, MarkerTruth* t) { return scene.Render(i, t); }, std::move(truth), progress,
      cancel);
}

}  // namespace armmimic::synth
