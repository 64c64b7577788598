// The calibration's differences in the bgsub engine's pixel model (bgsub/pixels.h: the
// standstill's standing body, an arm-length image against the empty room) tell a shadow from an
// arm: on a textured wall, a patch darkened by one factor with its texture kept is the room in
// shadow and does not differ from it; a patch of the wall's own colour, as dark, that hides the
// texture (a sleeve in the wall's colour) differs. On a wall of sparse dots, a shadow's pixels
// between them go with the region whose dots keep their texture. On a plain wall the two cannot
// be told apart, and the darker patch differs.
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "bgsub/pixels.h"

namespace armmimic {
namespace {

const cv::Size kSize(320, 240);
const cv::Scalar kWall(70, 90, 170);  // BGR: a red-brown wall

// Bricks: rows of 8 px, bricks 20 px long, each a little lighter or darker, with light mortar.
cv::Mat Bricks() {
  cv::Mat wall(kSize, CV_8UC3, kWall);
  cv::RNG rng(7);
  for (int row = 0; row * 8 < kSize.height; ++row) {
    const int shift = (row % 2) * 10;
    for (int x = -shift; x < kSize.width; x += 20) {
      const double f = rng.uniform(0.8, 1.2);
      cv::rectangle(wall, cv::Rect(x, row * 8, 20, 8), kWall * f, cv::FILLED);
      cv::line(wall, cv::Point(x, row * 8), cv::Point(x, row * 8 + 7), cv::Scalar(150, 160, 180));
    }
    cv::line(wall, cv::Point(0, row * 8), cv::Point(kSize.width - 1, row * 8),
             cv::Scalar(150, 160, 180));
  }
  return wall;
}

cv::Mat Noisy(const cv::Mat& image, cv::RNG& rng) {
  cv::Mat noise(image.size(), CV_16SC3), out;
  rng.fill(noise, cv::RNG::NORMAL, 0, 2);
  cv::Mat wide;
  image.convertTo(wide, CV_16SC3);
  wide += noise;
  wide.convertTo(out, CV_8UC3);
  return out;
}

// A model whose empty room is `room` and whose standstill frames show `standstill`.
bgsub::PixelModel ModelOf(const cv::Mat& room, const cv::Mat& standstill) {
  bgsub::PixelModel model;
  model.Begin(kSize);
  cv::RNG rng(3);
  for (int i = 0; i < 20; ++i) model.AddStandstill(Noisy(standstill, rng));
  model.Finish(room, 45);
  return model;
}

// The share of `mask`'s pixels set inside `r`, a margin of 4 px left out (the patch's edges).
double ShareSet(const cv::Mat& mask, const cv::Rect& r) {
  const cv::Rect inner(r.x + 4, r.y + 4, r.width - 8, r.height - 8);
  return static_cast<double>(cv::countNonZero(mask(inner))) / inner.area();
}

const cv::Rect kShadow(60, 80, 18, 70);
const cv::Rect kSleeve(200, 80, 18, 70);

// `room` with a shadow (darkened by 0.6, its texture kept) and a sleeve of the wall's colour as
// dark (no texture).
cv::Mat WithShadowAndSleeve(const cv::Mat& room, uint64_t seed) {
  cv::Mat image = room.clone();
  image(kShadow) *= 0.6;
  image(kSleeve).setTo(kWall * 0.6);
  cv::RNG rng(seed);
  return Noisy(image, rng);
}

// The standstill's standing body and an arm-length image against the empty room.
struct Differences {
  cv::Mat standstill_body, still;
};

Differences Measure(const cv::Mat& room, const cv::Mat& shown) {
  bgsub::PixelModel model = ModelOf(room, shown);
  Differences d;
  model.StandstillPerson(&d.standstill_body);
  model.Differ(shown, model.background(), &d.still);
  return d;
}

TEST(BgsubPixels, AShadowOnATexturedWallIsTheRoomAndASleeveInTheWallsColourIsNot) {
  const cv::Mat room = Bricks();
  const Differences d = Measure(room, WithShadowAndSleeve(room, 11));
  for (const cv::Mat* mask : {&d.standstill_body, &d.still}) {
    // Most of the shadow: a patch that lies inside one brick shows no texture, but its region
    // keeps the texture as a whole.
    EXPECT_LT(ShareSet(*mask, kShadow), 0.05);
    EXPECT_GT(ShareSet(*mask, kSleeve), 0.6);
    // Elsewhere the room is unchanged.
    cv::Mat rest = mask->clone();
    rest(cv::Rect(kShadow.x - 4, kShadow.y - 4, kShadow.width + 8, kShadow.height + 8)).setTo(0);
    rest(cv::Rect(kSleeve.x - 4, kSleeve.y - 4, kSleeve.width + 8, kSleeve.height + 8)).setTo(0);
    EXPECT_LT(cv::countNonZero(rest), 0.002 * kSize.area());
  }
}

// Dark dots 12 px apart: most 7 x 7 patches show none, and only the region tells the shadow.
cv::Mat Dots() {
  cv::Mat wall(kSize, CV_8UC3, kWall);
  for (int y = 2; y < kSize.height; y += 12) {
    for (int x = 2 + (y / 12 % 2) * 6; x < kSize.width; x += 12) {
      cv::rectangle(wall, cv::Rect(x, y, 2, 2), kWall * 0.4, cv::FILLED);
    }
  }
  return wall;
}

TEST(BgsubPixels, AShadowOnADottedWallIsTheRoomBetweenTheDotsToo) {
  const cv::Mat room = Dots();
  const Differences d = Measure(room, WithShadowAndSleeve(room, 17));
  for (const cv::Mat* mask : {&d.standstill_body, &d.still}) {
    EXPECT_LT(ShareSet(*mask, kShadow), 0.05);
    EXPECT_GT(ShareSet(*mask, kSleeve), 0.9);
  }
}

TEST(BgsubPixels, OnAPlainWallADarkerPatchOfItsColourStillDiffers) {
  const cv::Mat room(kSize, CV_8UC3, kWall);
  cv::Mat shown = room.clone();
  shown(kShadow) *= 0.6;
  cv::RNG rng(13);
  const Differences d = Measure(room, Noisy(shown, rng));
  EXPECT_GT(ShareSet(d.standstill_body, kShadow), 0.9);
  EXPECT_GT(ShareSet(d.still, kShadow), 0.9);
}

}  // namespace
}  // namespace armmimic
