// Marker-joint scenes: scene conditions (background, lighting, clutter) drawn from the seed, views
// with known poses, truth rows and the folder writer. The joint itself is ray cast in
// marker_render.cpp.
// Length: the renderer's constructor draws the scene's conditions from one seeded generator in a
// fixed order.
#include "armmimic/synth/marker_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "armmimic/core/image_io.h"
#include "marker_render.h"

namespace armmimic::synth {

const char* const kMarkerTruthExtra[12] = {
    "file",   "readable", "yaw_signed_deg", "upper_x",        "upper_y",       "left_x",
    "left_y", "right_x",  "right_y",        "upper_readable", "left_readable", "right_readable"};

namespace {

const char* const kBackgrounds[] = {"plain", "gradient", "texture", "room"};
const char* const kLightings[] = {"normal", "bright", "dim", "side", "shadow"};

template <std::size_t N>
bool OneOf(const std::string& v, const char* const (&list)[N]) {
  return std::find_if(std::begin(list), std::end(list), [&](const char* s) { return v == s; }) !=
         std::end(list);
}

cv::Scalar RandomColour(cv::RNG& rng, double lo, double hi) {
  const double base = rng.uniform(lo, hi);
  return cv::Scalar(base + rng.uniform(-12.0, 12.0), base + rng.uniform(-12.0, 12.0),
                    base + rng.uniform(-12.0, 12.0));
}

cv::Mat MakeBackground(const std::string& kind, cv::Size size, cv::RNG& rng) {
  cv::Mat bg(size, CV_32FC3);
  if (kind == "plain") {
    bg.setTo(RandomColour(rng, 120, 215));
  } else if (kind == "gradient") {
    const cv::Scalar a = RandomColour(rng, 100, 225);
    const cv::Scalar b = RandomColour(rng, 100, 225);
    const double angle = rng.uniform(0.0, 2 * kPi);
    const double dx = std::cos(angle), dy = std::sin(angle);
    const double span = std::abs(dx) * size.width + std::abs(dy) * size.height;
    for (int y = 0; y < size.height; ++y) {
      for (int x = 0; x < size.width; ++x) {
        const double t = std::clamp(
            0.5 + ((x - size.width / 2.0) * dx + (y - size.height / 2.0) * dy) / span, 0.0, 1.0);
        const cv::Scalar c = a * (1 - t) + b * t;
        bg.at<cv::Vec3f>(y, x) = cv::Vec3f(c[0], c[1], c[2]);
      }
    }
  } else if (kind == "texture") {
    cv::Mat small(6, 8, CV_32FC3);
    for (int y = 0; y < small.rows; ++y) {
      for (int x = 0; x < small.cols; ++x) {
        const cv::Scalar c = RandomColour(rng, 95, 230);
        small.at<cv::Vec3f>(y, x) = cv::Vec3f(c[0], c[1], c[2]);
      }
    }
    cv::resize(small, bg, size, 0, 0, cv::INTER_CUBIC);
    cv::Mat fine(size.height / 8 + 1, size.width / 8 + 1, CV_32FC3);
    rng.fill(fine, cv::RNG::NORMAL, 0, 10);
    cv::resize(fine, fine, size, 0, 0, cv::INTER_LINEAR);
    bg += fine;
  } else {  // room: a wall, a table and a few posters and boxes
    const int table_y = static_cast<int>(size.height * rng.uniform(0.72, 0.85));
    bg.setTo(RandomColour(rng, 150, 220));
    bg.rowRange(table_y, size.height).setTo(RandomColour(rng, 95, 160));
    const int posters = rng.uniform(3, 6);
    for (int i = 0; i < posters; ++i) {
      const int w = rng.uniform(size.width / 12, size.width / 4);
      const int h = rng.uniform(size.height / 10, size.height / 3);
      const cv::Rect r(rng.uniform(0, size.width - w), rng.uniform(0, table_y), w, h);
      cv::rectangle(bg, r, RandomColour(rng, 90, 235), cv::FILLED);
    }
  }
  return bg;
}

}  // namespace

MarkerJointModel MarkerJointModel::ForSize(cv::Size size) {
  MarkerJointModel m;
  const double k = size.height / 240.0;
  m.radius_px *= k;
  m.lower_length_px *= k;
  m.upper_length_px *= k;
  m.marker_radius_px *= k;
  m.pivot_distance_px *= k;
  m.pivot_px = cv::Point2d(size.width / 2.0, m.pivot_px.y * k);
  return m;
}

Status MarkerSceneOptions::Check() const {
  if (size.width < 160 || size.height < 120 || size.width > 4096 || size.height > 4096) {
    return Status::Error("marker_scene.size", "the image size " + std::to_string(size.width) + "x" +
                                                  std::to_string(size.height) +
                                                  " is out of range (160x120 .. 4096x4096)");
  }
  if (size.width * 3 < size.height * 4) {
    return Status::Error("marker_scene.size",
                         "the image must be at least 4:3 wide so the bent joint fits");
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
  if (!(noise_sigma >= 0 && noise_sigma <= 50)) {
    return Status::Error("marker_scene.noise_sigma", "the noise must be in [0, 50]");
  }
  if (background != "mixed" && background != "simple" && !OneOf(background, kBackgrounds)) {
    return Status::Error("marker_scene.background",
                         "the background '" + background +
                             "' is not one of plain, gradient, texture, room, simple, mixed");
  }
  if (lighting != "mixed" && !OneOf(lighting, kLightings)) {
    return Status::Error(
        "marker_scene.lighting",
        "the lighting '" + lighting + "' is not one of normal, bright, dim, side, shadow, mixed");
  }
  if (clutter < 0 || clutter > 100) {
    return Status::Error("marker_scene.clutter", "the clutter must be in [0, 100]");
  }
  if (camera.projection != "perspective" && camera.projection != "orthographic") {
    return Status::Error("marker_scene.camera", "the camera '" + camera.projection +
                                                    "' is not one of perspective, orthographic");
  }
  if (!(camera.fov_deg >= 10 && camera.fov_deg <= 120)) {
    return Status::Error("marker_scene.fov_deg", "the field of view must be in [10, 120] degrees");
  }

  return Status::Ok();
}

TruthRow MarkerTruth::ToRow() const {
  TruthRow row;
  row.frame = frame;
  row.time_s = 0;
  row.yaw_deg = yaw_deg;
  row.bend_deg = bend_deg;
  row.extra = {file,
               readable ? "1" : "0",
               FormatNumber(pose.yaw_deg, 4),
               FormatNumber(upper_px.x, 3),
               FormatNumber(upper_px.y, 3),
               FormatNumber(left_px.x, 3),
               FormatNumber(left_px.y, 3),
               FormatNumber(right_px.x, 3),
               FormatNumber(right_px.y, 3),
               upper_readable ? "1" : "0",
               left_readable ? "1" : "0",
               right_readable ? "1" : "0"};
  return row;
}

struct MarkerSceneRenderer::Impl {
  MarkerSceneOptions options;
  MarkerJointModel model;
  internal::MarkerView view;
  std::string background_kind;
  std::string lighting_kind;
  internal::MarkerLight light;
  internal::MarkerMaterial material;
  cv::Mat background;  // CV_32FC3, lit, with clutter
  std::vector<MarkerPose> poses;
};

MarkerSceneRenderer::MarkerSceneRenderer(const MarkerSceneOptions& options)
    : impl_(std::make_unique<Impl>()) {
  const Status st = options.Check();
  if (!st) throw std::invalid_argument("MarkerSceneRenderer: " + st.message());
  Impl& m = *impl_;
  m.options = options;
  cv::RNG rng(options.seed * 2654435761ULL + 12345);
  const cv::Size size = options.size;
  const double k = size.height / 240.0;
  m.model = MarkerJointModel::ForSize(size);
  m.model.pivot_px.x += rng.uniform(-22.0, 22.0) * k;
  m.model.pivot_px.y += rng.uniform(-6.0, 6.0) * k;

  m.view = internal::MarkerView::Make(m.model, options.camera, size);
  if (options.background == "mixed") {
    m.background_kind = kBackgrounds[rng.uniform(0, 4)];
  } else if (options.background == "simple") {
    m.background_kind = kBackgrounds[rng.uniform(0, 2)];
  } else {
    m.background_kind = options.background;
  }
  if (options.lighting != "mixed") {
    m.lighting_kind = options.lighting;
  } else {
    const int pick = rng.uniform(0, 8);  // normal light most of the time
    m.lighting_kind = pick < 4 ? "normal" : kLightings[pick - 3];
  }
  const double gray = rng.uniform(0.78, 0.92);
  m.material.cylinder_bgr =
      cv::Vec3d(gray + rng.uniform(-0.05, 0.0), gray, gray + rng.uniform(-0.05, 0.0));
  m.material.marker_albedo = rng.uniform(0.18, 0.23);
  m.light.dir = cv::Vec3d(rng.uniform(-0.5, 0.5), rng.uniform(0.2, 0.6), 0.85);
  double bg_gain = 1.0;
  if (m.lighting_kind == "bright") {
    m.light.gain = 1.3;
    bg_gain = 1.15;
  } else if (m.lighting_kind == "dim") {
    m.light.gain = 0.65;
    bg_gain = 0.5;
  } else if (m.lighting_kind == "side") {
    m.light.dir = cv::Vec3d(rng.uniform(0.0, 1.0) < 0.5 ? -0.9 : 0.9, 0.25, 0.45);
    m.light.ambient = 0.3;
    m.light.gain = 1.1;
  }

  m.background = MakeBackground(m.background_kind, size, rng) * bg_gain;
  if (m.lighting_kind == "shadow") {  // a soft shadow over part of the wall (thesis Fig. 4-10)
    cv::Mat shade(size, CV_32F, cv::Scalar(1.0));
    const cv::Point c(static_cast<int>(rng.uniform(0.0, 1.0) * size.width),
                      static_cast<int>(rng.uniform(0.0, 1.0) * size.height));
    const cv::Size axes(static_cast<int>(rng.uniform(0.25, 0.5) * size.width),
                        static_cast<int>(rng.uniform(0.25, 0.5) * size.height));
    cv::ellipse(shade, c, axes, rng.uniform(0.0, 180.0), 0, 360, cv::Scalar(0.3), cv::FILLED);
    cv::GaussianBlur(shade, shade, cv::Size(0, 0), 6 * k);
    std::vector<cv::Mat> ch;
    cv::split(m.background, ch);
    for (cv::Mat& c3 : ch) c3 = c3.mul(shade);
    cv::merge(ch, m.background);
  }
  // Dark clutter: every third blob sits beside the lower markers and every third within the
  // upper marker's reach, where they compete best.
  const double lower_y = m.model.pivot_px.y + m.model.pivot_distance_px;
  for (int i = 0; i < options.clutter; ++i) {
    cv::Point2d c;
    if (i % 3 == 0) {
      const double side = rng.uniform(0.0, 1.0) < 0.5 ? -1 : 1;
      c = cv::Point2d(m.model.pivot_px.x + side * (m.model.radius_px + rng.uniform(6.0, 30.0) * k),
                      lower_y + rng.uniform(-5.0, 5.0) * k);
    } else if (i % 3 == 1) {
      const double a = RadFromDeg(rng.uniform(-90.0, 90.0));
      const double dist = m.model.pivot_distance_px * rng.uniform(0.8, 1.25);
      c = cv::Point2d(m.model.pivot_px.x + dist * std::sin(a),
                      m.model.pivot_px.y - dist * std::cos(a));
    } else {
      c = cv::Point2d(rng.uniform(0.0, 1.0) * size.width, rng.uniform(0.0, 1.0) * size.height);
    }
    const cv::Size axes(std::max(2, static_cast<int>(rng.uniform(3.5, 9.0) * k)),
                        std::max(2, static_cast<int>(rng.uniform(3.5, 9.0) * k)));
    const double v = rng.uniform(25.0, 60.0);
    cv::ellipse(m.background, cv::Point(cvRound(c.x), cvRound(c.y)), axes, rng.uniform(0.0, 180.0),
                0, 360, cv::Scalar(v, v, v), cv::FILLED);
  }

  cv::RNG pose_rng(options.seed * 0x9E3779B97F4A7C15ULL + 7);
  m.poses.resize(options.views);
  for (MarkerPose& p : m.poses) {
    p.yaw_deg = pose_rng.uniform(-options.max_yaw_deg, options.max_yaw_deg);
    p.bend_deg = pose_rng.uniform(-options.max_bend_deg, options.max_bend_deg);
  }
}

MarkerSceneRenderer::~MarkerSceneRenderer() = default;

const MarkerSceneOptions& MarkerSceneRenderer::options() const { return impl_->options; }
const MarkerJointModel& MarkerSceneRenderer::model() const { return impl_->model; }
const std::string& MarkerSceneRenderer::background_kind() const { return impl_->background_kind; }
const std::string& MarkerSceneRenderer::lighting_kind() const { return impl_->lighting_kind; }

MarkerPose MarkerSceneRenderer::Pose(int index) const {
  if (index < 0 || index >= static_cast<int>(impl_->poses.size())) {
    throw std::out_of_range("MarkerSceneRenderer: no view " + std::to_string(index));
  }
  return impl_->poses[index];
}

MarkerTruth MarkerSceneRenderer::Truth(int index) const {
  MarkerTruth t;
  internal::ProjectMarkerJoint(impl_->model, impl_->view, Pose(index), impl_->options.size, &t);
  t.frame = index;
  char name[32];
  std::snprintf(name, sizeof(name), "view_%03d.png", index);
  t.file = name;
  return t;
}

cv::Mat MarkerSceneRenderer::RenderPose(const MarkerPose& pose, uint64_t noise_seed,
                                        MarkerTruth* truth) const {
  const Impl& m = *impl_;
  cv::Mat canvas = m.background.clone();
  internal::RenderMarkerJoint(m.model, m.view, pose, m.light, m.material, &canvas);
  if (m.options.noise_sigma > 0) {
    cv::Mat noise(canvas.size(), CV_32FC3);
    cv::RNG rng(noise_seed * 6364136223846793005ULL + m.options.seed + 1);
    rng.fill(noise, cv::RNG::NORMAL, 0, m.options.noise_sigma);
    canvas += noise;
  }
  cv::Mat out;
  canvas.convertTo(out, CV_8UC3);  // rounds and saturates
  if (truth) internal::ProjectMarkerJoint(m.model, m.view, pose, m.options.size, truth);
  return out;
}

cv::Mat MarkerSceneRenderer::Render(int index, MarkerTruth* truth) const {
  cv::Mat image = RenderPose(Pose(index), static_cast<uint64_t>(index), nullptr);
  if (truth) *truth = Truth(index);
  return image;
}

cv::Mat MarkerSceneRenderer::Reference(MarkerTruth* truth) const {
  cv::Mat image = RenderPose(MarkerPose{}, 1000003, truth);
  if (truth) {
    truth->frame = 0;
    truth->file = "reference.png";
  }
  return image;
}

Status WriteMarkerSceneFolder(const std::string& outdir, const cv::Mat& reference, int views,
                              const std::function<cv::Mat(int, MarkerTruth*)>& render,
                              TruthFile truth, const std::function<void(int, int)>& progress,
                              const std::atomic<bool>* cancel) {
  std::error_code ec;
  const std::filesystem::path root(outdir);
  std::filesystem::create_directories(root / "views", ec);
  if (ec) return Status::Error(outdir + ": cannot create the folder: " + ec.message());
  std::filesystem::remove(root / "truth.tsv", ec);
  if (ec) return Status::Error(outdir + "/truth.tsv: cannot replace: " + ec.message());
  Status ws = WriteImageAtomically((root / "reference.png").string(), reference);
  if (!ws) return ws;
  truth.extra_columns.assign(std::begin(kMarkerTruthExtra), std::end(kMarkerTruthExtra));
  for (int i = 0; i < views; ++i) {
    if (cancel && cancel->load()) {
      return Status::Error(outdir + ": cancelled after " + std::to_string(i) +
                           " views; no truth.tsv written");
    }
    MarkerTruth t;
    const cv::Mat image = render(i, &t);
    ws = WriteImageAtomically((root / "views" / t.file).string(), image);
    if (!ws) return ws;
    truth.rows.push_back(t.ToRow());
    if (progress) progress(i + 1, views);
  }
  return WriteTruthFile((root / "truth.tsv").string(), truth);
}

Status WriteMarkerScene(const MarkerSceneOptions& options, const std::string& outdir,
                        const std::function<void(int, int)>& progress,
                        const std::atomic<bool>* cancel) {
  const Status st = options.Check();
  if (!st) return st;
  const MarkerSceneRenderer scene(options);
  TruthFile truth;
  const MarkerJointModel& model = scene.model();
  truth.meta = {{"scene", "marker"},
                {"seed", std::to_string(options.seed)},
                {"width", std::to_string(options.size.width)},
                {"height", std::to_string(options.size.height)},
                {"background", scene.background_kind()},
                {"lighting", scene.lighting_kind()},
                {"clutter", std::to_string(options.clutter)},
                {"camera", options.camera.projection},
                {"fov_deg", FormatNumber(options.camera.fov_deg, 2)},
                {"noise", FormatNumber(options.noise_sigma, 2)},
                {"radius_px", FormatNumber(model.radius_px, 3)},
                {"marker_radius_px", FormatNumber(model.marker_radius_px, 3)},
                {"marker_angle_deg", FormatNumber(model.marker_angle_deg, 3)},
                {"pivot_distance_px", FormatNumber(model.pivot_distance_px, 3)},
                {"reference", "reference.png"},
                {"views", "views"}};
  return WriteMarkerSceneFolder(
      outdir, scene.Reference(), options.views,
      [&scene](int i, MarkerTruth* t) { return scene.Render(i, t); }, std::move(truth), progress,
      cancel);
}

}  // namespace armmimic::synth
