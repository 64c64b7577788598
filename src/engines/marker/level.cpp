// A tilted camera levelled (docs/marker.md, "A tilted camera"): the pitch from the reference's
// two limbs, and the resampling of an image as a level camera would take it.
#include "marker/level.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"

namespace armmimic::internal {

double LevelPitch(const LowerCalibration& cal, const MarkerCamera& camera) {
  const double dx = cal.limb_x[1] - cal.limb_x[0];
  if (!(dx > 1) || std::isnan(cal.limb_lean[0]) || std::isnan(cal.limb_lean[1])) return kNaN;
  // A vertical through column x leans by -(x - cx) tan(p) / f columns per row; a roll adds the
  // same lean to both, which the difference cancels.
  return std::atan(-camera.focal_px * (cal.limb_lean[1] - cal.limb_lean[0]) / dx);
}

LevelWarp::LevelWarp(const MarkerCamera& camera, cv::Size size, double pitch) : pitch_(pitch) {
  const double f = camera.focal_px;
  // The level camera turns by -pitch about the image's x axis, which keeps image rows rows: the
  // original rows map to a band of rows, and the level image is that band (its principal point
  // moves with it). Only the corners' columns can fall outside the original.
  const double c = std::cos(pitch), s = std::sin(pitch);
  const cv::Matx33d turn(1, 0, 0, 0, c, s, 0, -s, c);  // rotation about x by -pitch
  auto level_row = [&](double v) {                     // with the principal point at row 0
    const double y = (v - camera.principal_px.y) / f;
    return f * (c * y + s) / (c - s * y);
  };
  const double top = level_row(0), bottom = level_row(size.height - 1);
  level_size_ = cv::Size(size.width, static_cast<int>(std::floor(bottom - top)) + 1);
  camera_ = camera;
  camera_.principal_px.y = -top;
  const cv::Matx33d k(f, 0, camera.principal_px.x, 0, f, camera.principal_px.y, 0, 0, 1);
  const cv::Matx33d k_level(f, 0, camera_.principal_px.x, 0, f, camera_.principal_px.y, 0, 0, 1);
  to_original_ = k * turn.t() * k_level.inv();
  to_level_ = k_level * turn * k.inv();
  cv::Mat map(level_size_, CV_32FC2);
  for (int y = 0; y < level_size_.height; ++y) {
    auto* row = map.ptr<cv::Vec2f>(y);
    for (int x = 0; x < level_size_.width; ++x) {
      const cv::Point2d p = ToOriginal(cv::Point2d(x, y));
      row[x] = cv::Vec2f(static_cast<float>(p.x), static_cast<float>(p.y));
    }
  }
  cv::convertMaps(map, cv::Mat(), map1_, map2_, CV_16SC2);
}

void LevelWarp::Apply(const cv::Mat& image, cv::Mat* level, Resampling resampling) const {
  // Beyond the original image the nearest edge pixel repeats: no dark band a marker could be
  // taken from.
  cv::remap(image, *level, map1_, map2_,
            resampling == Resampling::kSharp ? cv::INTER_CUBIC : cv::INTER_LINEAR,
            cv::BORDER_REPLICATE);
}

namespace {

cv::Point2d Map(const cv::Matx33d& h, cv::Point2d p) {
  const cv::Vec3d q = h * cv::Vec3d(p.x, p.y, 1);
  return {q[0] / q[2], q[1] / q[2]};
}

cv::Rect Map(const cv::Matx33d& h, const cv::Rect& r) {
  const std::array<cv::Point2d, 4> corners = {
      Map(h, cv::Point2d(r.x, r.y)), Map(h, cv::Point2d(r.x + r.width, r.y)),
      Map(h, cv::Point2d(r.x, r.y + r.height)), Map(h, cv::Point2d(r.x + r.width, r.y + r.height))};
  double x0 = corners[0].x, x1 = x0, y0 = corners[0].y, y1 = y0;
  for (const cv::Point2d& c : corners) {
    x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
  }
  return cv::Rect(cv::Point(static_cast<int>(std::floor(x0)), static_cast<int>(std::floor(y0))),
                  cv::Point(static_cast<int>(std::ceil(x1)), static_cast<int>(std::ceil(y1))));
}

}  // namespace

cv::Point2d LevelWarp::ToOriginal(cv::Point2d p) const { return Map(to_original_, p); }
cv::Rect LevelWarp::ToOriginal(const cv::Rect& r) const { return Map(to_original_, r); }
cv::Point2d LevelWarp::ToLevel(cv::Point2d p) const { return Map(to_level_, p); }
cv::Rect LevelWarp::ToLevel(const cv::Rect& r) const { return Map(to_level_, r); }

}  // namespace armmimic::internal
