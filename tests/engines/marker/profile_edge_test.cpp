// FitProfileEdge (docs/marker.md, "Calibration", step 2) on drawn column profiles with a known
// silhouette edge: a surface whose grey level runs like p + q sqrt(d) + r d from the limb, a flat
// or sloping wall beyond it, each pixel's own width, the lens' blur and noise.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "marker/cylinder.h"

namespace armmimic::internal {
namespace {

struct Scene {
  double edge = 30.35;  // image column of the limb
  int inside = 1;       // +1: the surface lies to the right of the edge
  double surface = 45, q = 13, r = 2;
  double wall = 42, wall_slope = 0;  // grey level and its change per pixel away from the edge
  double blur = 0;                   // the optics' Gaussian, pixels
  double noise = 0;
};

// The profile over columns 0..63: the scene integrated over each pixel's width and seen through
// the blur (fine samples, the Gaussian applied to them), plus noise.
std::vector<double> DrawProfile(const Scene& s, uint64_t seed) {
  constexpr int kColumns = 64, kSub = 40;
  constexpr double kStep = 1.0 / kSub;
  const int fine = kColumns * kSub;
  std::vector<double> scene(fine);
  for (int k = 0; k < fine; ++k) {
    const double x = -0.5 + (k + 0.5) * kStep;
    const double d = s.inside * (x - s.edge);
    scene[k] = d > 0 ? s.surface + s.q * std::sqrt(d) + s.r * d : s.wall - s.wall_slope * d;
  }
  std::vector<double> seen = scene;
  if (s.blur > 0) {
    const int half = static_cast<int>(std::ceil(4 * s.blur * kSub));
    for (int k = 0; k < fine; ++k) {
      double sum = 0, weight = 0;
      for (int j = -half; j <= half; ++j) {
        const int m = std::clamp(k + j, 0, fine - 1);
        const double v = j * kStep / s.blur;
        const double w = std::exp(-0.5 * v * v);
        sum += w * scene[m];
        weight += w;
      }
      seen[k] = sum / weight;
    }
  }
  std::vector<double> profile(kColumns, 0.0);
  cv::RNG rng(seed);
  for (int x = 0; x < kColumns; ++x) {
    for (int k = 0; k < kSub; ++k) profile[x] += seen[x * kSub + k] / kSub;
    profile[x] += rng.gaussian(s.noise);
  }
  return profile;
}

// The edge found from a start 1.2 px off, on the scene of `s` drawn with either side inside.
void ExpectEdgeWithin(Scene s, double tolerance) {
  for (int inside : {1, -1}) {
    s.inside = inside;
    for (uint64_t seed : {1, 2, 3}) {
      const std::vector<double> profile = DrawProfile(s, seed);
      const double edge = FitProfileEdge(profile, 0, s.edge + 1.2 * inside, 2.0, inside);
      EXPECT_NEAR(edge, s.edge, tolerance)
          << "inside " << inside << " blur " << s.blur << " seed " << seed;
    }
  }
}

TEST(MarkerProfileEdge, AnUnblurredLimbDarkerThanTheWall) {
  Scene s;
  s.surface = 20;
  s.wall = 60;
  ExpectEdgeWithin(s, 0.1);
}

// A limb about as bright as the wall behind it (the kink remains) seen through the blur the rig
// renderer draws (0.85 px): the model without the blur had put this edge 3.2 px off, inside the
// limb where the blurred start of the shading is as steep as a step. (With noise the kink
// alone places such an edge to about a pixel; the calibration tries the markers' symmetry there.)
TEST(MarkerProfileEdge, ABlurredLimbAsBrightAsTheWall) {
  Scene s;
  s.blur = 0.85;
  ExpectEdgeWithin(s, 0.1);
}

// A limb darker than a wall whose level slopes away from it, a wider blur, and the noise of a
// profile averaged over some forty rows of a noisy image (the model without the blur: 0.6-1.9 px
// inside the limb).
TEST(MarkerProfileEdge, ABlurredLimbBeforeASlopingWall) {
  Scene s;
  s.surface = 70;
  s.wall = 110;
  s.wall_slope = 1.5;
  s.blur = 1.2;
  s.noise = 0.5;
  ExpectEdgeWithin(s, 0.35);
}

}  // namespace
}  // namespace armmimic::internal
