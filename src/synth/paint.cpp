#include "paint.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace armmimic::synth {
namespace {

// Light direction (towards the light) in image axes (x right, y down, z towards the viewer).
constexpr double kLx = -0.45, kLy = -0.55, kLz = 0.70;

inline void Blend(Layer* layer, int x, int y, float a, const cv::Vec3f& c) {
  cv::Vec3f& p = layer->color.at<cv::Vec3f>(y, x);
  p = p * (1.0f - a) + c * a;
  if (!layer->alpha.empty()) {
    float& al = layer->alpha.at<float>(y, x);
    al = al * (1.0f - a) + a;
  }
}

inline float Shade(const Shading& s, double nx, double ny, double nz) {
  const double n = std::sqrt(nx * nx + ny * ny + nz * nz);
  const double l = std::sqrt(kLx * kLx + kLy * kLy + kLz * kLz);
  const double dot = n > 0 ? (nx * kLx + ny * kLy + nz * kLz) / (n * l) : 0.0;
  return s.ambient + s.diffuse * static_cast<float>(std::max(0.0, dot));
}

cv::Rect Clip(double x0, double y0, double x1, double y1, const cv::Size& size) {
  const int ix0 = std::max(0, static_cast<int>(std::floor(x0)));
  const int iy0 = std::max(0, static_cast<int>(std::floor(y0)));
  const int ix1 = std::min(size.width - 1, static_cast<int>(std::ceil(x1)));
  const int iy1 = std::min(size.height - 1, static_cast<int>(std::ceil(y1)));
  if (ix1 < ix0 || iy1 < iy0) return {};
  return {ix0, iy0, ix1 - ix0 + 1, iy1 - iy0 + 1};
}

}  // namespace

float Texture::Sample(double u, double v) const {
  if (noise.empty() || amplitude == 0) return 1.0f;
  const int n = noise.rows;
  const int iu = static_cast<int>(std::floor(u)) & (n - 1);
  const int iv = static_cast<int>(std::floor(v)) & (n - 1);
  return 1.0f + amplitude * noise.at<float>(iv, iu);
}

void PaintCapsule(Layer* layer, cv::Point2d a, cv::Point2d b, double ra, double rb,
                  const cv::Vec3f& color, const Texture* texture, const Shading& shading) {
  const double rmax = std::max(ra, rb) + 1.0;
  const cv::Rect box =
      Clip(std::min(a.x, b.x) - rmax, std::min(a.y, b.y) - rmax, std::max(a.x, b.x) + rmax,
           std::max(a.y, b.y) + rmax, layer->color.size());
  if (box.empty()) return;
  const cv::Point2d ab = b - a;
  const double len2 = ab.dot(ab);
  const double len = std::sqrt(len2);
  const cv::Point2d along = len > 1e-9 ? ab * (1.0 / len) : cv::Point2d(1, 0);
  const cv::Point2d perp(-along.y, along.x);
  for (int y = box.y; y < box.y + box.height; ++y) {
    for (int x = box.x; x < box.x + box.width; ++x) {
      const cv::Point2d p(x - a.x, y - a.y);
      const double t = len2 > 1e-12 ? std::clamp(p.dot(ab) / len2, 0.0, 1.0) : 0.0;
      const cv::Point2d q = p - ab * t;
      const double d = std::sqrt(q.dot(q));
      const double r = ra + (rb - ra) * t;
      const float alpha = static_cast<float>(std::clamp(r - d + 0.5, 0.0, 1.0));
      if (alpha <= 0) continue;
      const double side = p.dot(perp);
      const double f = std::clamp(side / std::max(r, 0.5), -1.0, 1.0);
      const double nz = std::sqrt(std::max(0.0, 1.0 - f * f));
      float k = Shade(shading, perp.x * f, perp.y * f, nz);
      if (texture) k *= texture->Sample(p.dot(along), side + 64.0);
      Blend(layer, x, y, alpha, color * k);
    }
  }
}

void PaintEllipse(Layer* layer, cv::Point2d center, double rx, double ry, double angle_deg,
                  const cv::Vec3f& color, const Texture* texture, const Shading& shading,
                  double clip_y) {
  const double rmax = std::max(rx, ry) + 1.0;
  const cv::Rect box =
      Clip(center.x - rmax, center.y - rmax, center.x + rmax, center.y + rmax, layer->color.size());
  if (box.empty()) return;
  const double th = angle_deg * CV_PI / 180.0;
  const double c = std::cos(th), s = std::sin(th);
  const double rmin = std::min(rx, ry);
  for (int y = box.y; y < box.y + box.height; ++y) {
    for (int x = box.x; x < box.x + box.width; ++x) {
      const double dx = x - center.x, dy = y - center.y;
      const double u = (dx * c + dy * s) / rx;
      const double v = (-dx * s + dy * c) / ry;
      const double rho = std::sqrt(u * u + v * v);
      float alpha = static_cast<float>(std::clamp((1.0 - rho) * rmin + 0.5, 0.0, 1.0));
      if (std::isfinite(clip_y)) {
        alpha *= static_cast<float>(std::clamp((clip_y - y) / 2.0 + 0.5, 0.0, 1.0));
      }
      if (alpha <= 0) continue;
      const double r2 = std::min(1.0, rho * rho);
      const double nz = std::sqrt(1.0 - r2);
      // Back to image axes for the normal.
      const double nx = u * c - v * s, ny = u * s + v * c;
      float k = Shade(shading, nx, ny, nz);
      if (texture) k *= texture->Sample(dx + 64.0, dy + 64.0);
      Blend(layer, x, y, alpha, color * k);
    }
  }
}

void PaintBody(Layer* layer, const std::vector<cv::Point2d>& polygon, double axis_x,
               double half_width, const cv::Vec3f& color, const Texture* texture,
               const Shading& shading) {
  if (polygon.size() < 3) return;
  // Coverage from an 8x supersampled fill: exact enough for soft, anti-aliased edges.
  constexpr int kShift = 3;
  std::vector<cv::Point> pts;
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const auto& p : polygon) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  const cv::Rect box = Clip(x0 - 1, y0 - 1, x1 + 1, y1 + 1, layer->color.size());
  if (box.empty()) return;
  cv::Mat big(box.height << kShift, box.width << kShift, CV_8UC1, cv::Scalar(0));
  pts.reserve(polygon.size());
  for (const auto& p : polygon) {
    pts.emplace_back(cvRound((p.x - box.x + 0.5) * (1 << kShift) - 0.5),
                     cvRound((p.y - box.y + 0.5) * (1 << kShift) - 0.5));
  }
  cv::fillPoly(big, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar(255));
  cv::Mat cover;
  cv::resize(big, cover, box.size(), 0, 0, cv::INTER_AREA);
  for (int y = box.y; y < box.y + box.height; ++y) {
    for (int x = box.x; x < box.x + box.width; ++x) {
      const float alpha = cover.at<uchar>(y - box.y, x - box.x) / 255.0f;
      if (alpha <= 0) continue;
      const double f = std::clamp((x - axis_x) / half_width, -1.0, 1.0);
      const double nz = std::sqrt(std::max(0.0, 1.0 - f * f));
      float k = Shade(shading, f * 0.8, -0.15, nz + 0.2);
      if (texture) k *= texture->Sample(x, y);
      Blend(layer, x, y, alpha, color * k);
    }
  }
}

uint64_t Mix(uint64_t seed, uint64_t salt) {
  uint64_t z = seed * 0x9E3779B97F4A7C15ULL + salt * 0xBF58476D1CE4E5B9ULL + 0x94D049BB133111EBULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

cv::Vec3f Clamp255(const cv::Vec3f& c) {
  return {std::clamp(c[0], 0.0f, 255.0f), std::clamp(c[1], 0.0f, 255.0f),
          std::clamp(c[2], 0.0f, 255.0f)};
}

Texture MakeTexture(cv::RNG& rng, float amplitude, double blur) {
  Texture t;
  t.noise.create(64, 64, CV_32FC1);
  rng.fill(t.noise, cv::RNG::NORMAL, 0, 1);
  if (blur > 0) {
    // Blur a 3x3 tiling and keep the centre tile, so the texture stays tileable.
    cv::Mat tiled;
    cv::repeat(t.noise, 3, 3, tiled);
    cv::GaussianBlur(tiled, tiled, cv::Size(), blur, blur);
    tiled(cv::Rect(64, 64, 64, 64)).copyTo(t.noise);
  }
  cv::Scalar mean, sd;
  cv::meanStdDev(t.noise, mean, sd);
  t.noise = (t.noise - mean[0]) / std::max(1e-6, sd[0]);
  t.amplitude = amplitude;
  return t;
}

void Over(const Layer& layer, cv::Mat* dst) {
  CV_Assert(dst->type() == CV_32FC3 && layer.color.size() == dst->size());
  if (layer.alpha.empty()) {
    layer.color.copyTo(*dst);
    return;
  }
  for (int y = 0; y < dst->rows; ++y) {
    cv::Vec3f* d = dst->ptr<cv::Vec3f>(y);
    const cv::Vec3f* c = layer.color.ptr<cv::Vec3f>(y);
    const float* a = layer.alpha.ptr<float>(y);
    for (int x = 0; x < dst->cols; ++x) {
      if (a[x] <= 0) continue;
      d[x] = d[x] * (1.0f - a[x]) + c[x];
    }
  }
}

}  // namespace armmimic::synth
