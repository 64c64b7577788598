// Camera and light of a random arm scene: vignetting, a moving shadow, a global gain with a
// colour cast, sensor noise and JPEG compression; and the small colour helpers.
#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "random_scene_model.h"

namespace armmimic::synth {

cv::Mat JpegRoundTrip(const cv::Mat& image, int quality) {
  std::vector<uchar> bytes;
  cv::imencode(".jpg", image, bytes, {cv::IMWRITE_JPEG_QUALITY, std::clamp(quality, 1, 100)});
  return cv::imdecode(bytes, cv::IMREAD_COLOR);
}

namespace random_scene {

uint64_t Mix(uint64_t seed, uint64_t salt) {
  uint64_t z = seed * 0x9E3779B97F4A7C15ULL + salt * 0xBF58476D1CE4E5B9ULL + 0x94D049BB133111EBULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

cv::Vec3f Hsv(double hue, double sat, double val) {
  hue = std::fmod(std::fmod(hue, 360.0) + 360.0, 360.0);
  const double c = val * sat;
  const double x = c * (1 - std::fabs(std::fmod(hue / 60.0, 2.0) - 1));
  const double mm = val - c;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue / 60.0)) {
    case 0:
      r = c, g = x;
      break;
    case 1:
      r = x, g = c;
      break;
    case 2:
      g = c, b = x;
      break;
    case 3:
      g = x, b = c;
      break;
    case 4:
      r = x, b = c;
      break;
    default:
      r = c, b = x;
      break;
  }
  return {static_cast<float>((b + mm) * 255), static_cast<float>((g + mm) * 255),
          static_cast<float>((r + mm) * 255)};
}

double ColourDistance(const cv::Vec3f& a, const cv::Vec3f& b) { return cv::norm(a - b); }

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

cv::Mat VignetteMap(cv::Size size, double strength) {
  cv::Mat map(size, CV_32FC1);
  const double cx = (size.width - 1) / 2.0, cy = (size.height - 1) / 2.0;
  const double r2max = cx * cx + cy * cy;
  for (int y = 0; y < size.height; ++y) {
    float* row = map.ptr<float>(y);
    for (int x = 0; x < size.width; ++x) {
      const double r2 = ((x - cx) * (x - cx) + (y - cy) * (y - cy)) / r2max;
      row[x] = static_cast<float>(1 - strength * r2 * r2 * 0.6 - strength * r2 * 0.4);
    }
  }
  return map;
}

void ApplyLight(cv::Mat* canvas, const cv::Mat& vignette, const cv::Vec3f& gain,
                const ShadowSpot& shadow) {
  const int W = canvas->cols, H = canvas->rows;
  for (int y = 0; y < H; ++y) {
    cv::Vec3f* row = canvas->ptr<cv::Vec3f>(y);
    const float* v = vignette.ptr<float>(y);
    double dy2 = 0;
    const bool shade_row = shadow.on && std::fabs(y - shadow.centre.y) < 3 * shadow.sigma.height;
    if (shade_row) {
      const double dy = (y - shadow.centre.y) / shadow.sigma.height;
      dy2 = dy * dy;
    }
    for (int x = 0; x < W; ++x) {
      float k = v[x];
      if (shade_row) {
        const double dx = (x - shadow.centre.x) / shadow.sigma.width;
        k *= static_cast<float>(1 - shadow.strength * std::exp(-0.5 * (dx * dx + dy2)));
      }
      cv::Vec3f& p = row[x];
      p[0] *= k * gain[0];
      p[1] *= k * gain[1];
      p[2] *= k * gain[2];
    }
  }
}

void AddSensorNoise(cv::Mat* canvas, double sigma, uint64_t seed) {
  if (sigma <= 0) return;
  cv::RNG rng(seed);
  cv::Mat noise(canvas->size(), CV_32FC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
  *canvas += noise;
}

}  // namespace random_scene
}  // namespace armmimic::synth
