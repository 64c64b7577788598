// Anti-aliased, softly shaded shapes painted on float BGR images: the building blocks of the arm
// scenes. Private to the synth layer.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <opencv2/core.hpp>

namespace armmimic::synth {

// A float BGR image (CV_32FC3, 0..255) and optionally its coverage (CV_32FC1, 0..1). With an
// alpha plane the colour is premultiplied, so layers can be composited later with Over().
struct Layer {
  cv::Mat color;  // CV_32FC3
  cv::Mat alpha;  // CV_32FC1 or empty (an opaque canvas)
};

// Fabric/skin texture: a small tileable noise pattern, mean 0, roughly unit amplitude.
struct Texture {
  cv::Mat noise;        // CV_32FC1, square, power-of-two side
  float amplitude = 0;  // relative brightness variation
  float Sample(double u, double v) const;
};

// Light comes from the upper left, slightly in front.
struct Shading {
  float ambient = 0.42f;
  float diffuse = 0.62f;
};

// A tapered capsule from `a` (radius ra) to `b` (radius rb): a limb. Shaded as a cylinder.
void PaintCapsule(Layer* layer, cv::Point2d a, cv::Point2d b, double ra, double rb,
                  const cv::Vec3f& color, const Texture* texture, const Shading& shading = {});

// A rotated ellipse shaded as a sphere; rows below `clip_y` (if finite) fade out over 2 px.
void PaintEllipse(Layer* layer, cv::Point2d center, double rx, double ry, double angle_deg,
                  const cv::Vec3f& color, const Texture* texture, const Shading& shading = {},
                  double clip_y = std::numeric_limits<double>::quiet_NaN());

// A filled polygon (anti-aliased edges), shaded as a horizontal cylinder around `axis_x` with
// half-width `half_width` (a torso).
void PaintBody(Layer* layer, const std::vector<cv::Point2d>& polygon, double axis_x,
               double half_width, const cv::Vec3f& color, const Texture* texture,
               const Shading& shading = {});

// dst = layer over dst (dst opaque CV_32FC3).
void Over(const Layer& layer, cv::Mat* dst);

// A tileable noise texture with the given relative amplitude, blurred by `blur` pixels.
Texture MakeTexture(cv::RNG& rng, float amplitude, double blur);

// A 64-bit mix of a seed and a salt (splitmix64 finaliser): independent random streams.
uint64_t Mix(uint64_t seed, uint64_t salt);

cv::Vec3f Clamp255(const cv::Vec3f& c);

}  // namespace armmimic::synth
