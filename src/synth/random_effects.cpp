// Camera and light of a random arm scene: vignetting, a moving shadow, a global gain with a
// colour cast, sensor noise and JPEG compression; and the small colour helpers.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/image_io.h"
#include "random_scene_model.h"

namespace armmimic::synth {

cv::Mat JpegRoundTrip(const cv::Mat& image, int quality) {
  std::vector<unsigned char> bytes;
  cv::Mat decoded;
  Status st =
      EncodeImage(".jpg", image, {cv::IMWRITE_JPEG_QUALITY, std::clamp(quality, 1, 100)}, &bytes);
  if (st) st = DecodeImage(bytes, &decoded);
  // Only a broken installation (no codec module) gets here; a scene without its compression
  // would be another scene, so it is not rendered.
  if (!st) throw std::runtime_error("JPEG compression of a rendered frame: " + st.message());
  return decoded;
}

namespace random_scene {

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

namespace {

// xoshiro256**: a small, fast generator; the sensor noise needs many numbers a frame.
class FastRng {
 public:
  explicit FastRng(uint64_t seed) {
    for (uint64_t& v : s_) v = seed = Mix(seed, 0x5EED);
  }
  uint64_t Next() {
    const uint64_t out = Rotl(s_[1] * 5, 7) * 9;
    const uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0], s_[3] ^= s_[1], s_[1] ^= s_[2], s_[0] ^= s_[3], s_[2] ^= t;
    s_[3] = Rotl(s_[3], 45);
    return out;
  }

 private:
  static uint64_t Rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  uint64_t s_[4];
};

// About N(0, 1): the centred sum of four 16-bit uniforms, scaled to unit variance (Irwin-Hall;
// the tails end at +-3.46, which sensor noise does not miss).
inline float Gauss(uint64_t r) {
  const uint32_t sum = static_cast<uint32_t>(r & 0xFFFF) + static_cast<uint32_t>(r >> 16 & 0xFFFF) +
                       static_cast<uint32_t>(r >> 32 & 0xFFFF) + static_cast<uint32_t>(r >> 48);
  constexpr float kScale = 1.7320508f / 65536.0f;  // sqrt(12 / 4) per unit of 65536
  return (static_cast<float>(sum) - 2.0f * 65535.0f) * kScale;
}

}  // namespace

cv::Mat Expose(const cv::Mat& canvas, const cv::Mat& vignette, const cv::Vec3f& gain,
               const ShadowSpot& shadow, double noise_sigma, uint64_t noise_seed) {
  const int W = canvas.cols, H = canvas.rows;
  cv::Mat out(canvas.size(), CV_8UC3);
  // The shadow is a separable Gaussian: one factor per column, one per row.
  std::vector<float> across(W, 0.0f);
  if (shadow.on) {
    for (int x = 0; x < W; ++x) {
      const double dx = (x - shadow.centre.x) / shadow.sigma.width;
      across[x] = static_cast<float>(shadow.strength * std::exp(-0.5 * dx * dx));
    }
  }
  FastRng rng(noise_seed);
  const float sigma = static_cast<float>(noise_sigma);
  for (int y = 0; y < H; ++y) {
    const cv::Vec3f* in = canvas.ptr<cv::Vec3f>(y);
    const float* v = vignette.ptr<float>(y);
    cv::Vec3b* o = out.ptr<cv::Vec3b>(y);
    float down = 0;
    if (shadow.on) {
      const double dy = (y - shadow.centre.y) / shadow.sigma.height;
      down = static_cast<float>(std::exp(-0.5 * dy * dy));
    }
    for (int x = 0; x < W; ++x) {
      const float k = v[x] * (1.0f - across[x] * down);
      for (int c = 0; c < 3; ++c) {
        float value = in[x][c] * k * gain[c];
        if (sigma > 0) value += sigma * Gauss(rng.Next());
        o[x][c] = cv::saturate_cast<uchar>(value);
      }
    }
  }
  return out;
}

}  // namespace random_scene
}  // namespace armmimic::synth
