// The per-pixel model of the bgsub engine (bgsub/pixels.h) tells a shadow from an arm: on a
// textured wall, a patch darkened by one factor with its texture kept is the room in shadow and
// does not differ from it; a patch of the wall's own colour, as dark, that hides the texture (a
// sleeve in the wall's colour) differs. On a plain wall the two cannot be told apart, and the
// darker patch differs.
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

// A model whose empty room and standstill are `room` (the person is left out: only the wall).
bgsub::PixelModel ModelOf(const cv::Mat& room) {
  bgsub::PixelModel model;
  model.Begin(kSize);
  cv::RNG rng(3);
  for (int i = 0; i < 20; ++i) model.AddStandstill(Noisy(room, rng));
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

TEST(BgsubPixels, AShadowOnATexturedWallIsTheRoomAndASleeveInTheWallsColourIsNot) {
  const cv::Mat room = Bricks();
  bgsub::PixelModel model = ModelOf(room);
  cv::Mat frame = room.clone();
  frame(kShadow) *= 0.6;                          // the room in shadow: its texture kept
  frame(kSleeve).setTo(kWall * 0.6);              // the wall's colour, as dark, no texture
  cv::RNG rng(11);
  frame = Noisy(frame, rng);
  cv::Mat person, moved;
  model.Compare(frame, cv::Rect(cv::Point(), kSize), cv::Mat(), &person, &moved);
  // Most of the shadow: a patch that lies inside one brick shows no texture, and stays.
  EXPECT_LT(ShareSet(person, kShadow), 0.25);
  EXPECT_LT(ShareSet(moved, kShadow), 0.25);
  EXPECT_GT(ShareSet(person, kSleeve), 0.6);
  EXPECT_GT(ShareSet(moved, kSleeve), 0.6);
  // Elsewhere the room is unchanged.
  cv::Mat rest = person.clone();
  rest(cv::Rect(kShadow.x - 4, kShadow.y - 4, kShadow.width + 8, kShadow.height + 8)).setTo(0);
  rest(cv::Rect(kSleeve.x - 4, kSleeve.y - 4, kSleeve.width + 8, kSleeve.height + 8)).setTo(0);
  EXPECT_LT(cv::countNonZero(rest), 0.002 * kSize.area());
}

TEST(BgsubPixels, OnAPlainWallADarkerPatchOfItsColourStillDiffers) {
  const cv::Mat room(kSize, CV_8UC3, kWall);
  bgsub::PixelModel model = ModelOf(room);
  cv::Mat frame = room.clone();
  frame(kShadow) *= 0.6;
  cv::RNG rng(13);
  frame = Noisy(frame, rng);
  cv::Mat person, moved;
  model.Compare(frame, cv::Rect(cv::Point(), kSize), cv::Mat(), &person, &moved);
  EXPECT_GT(ShareSet(person, kShadow), 0.9);
  EXPECT_GT(ShareSet(moved, kShadow), 0.9);
}

}  // namespace
}  // namespace armmimic
