// The room of a random arm scene: a textured wall, a floor, and furniture, posters, doors,
// windows and shelves painted from a RoomSpec.
#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "random_scene_model.h"

namespace armmimic::synth::random_scene {
namespace {

const Shading kFlat{1.0f, 0.0f};

// An axis-aligned filled rectangle, flat lit, optionally textured.
void FillRect(Layer* layer, const cv::Rect2d& r, const cv::Vec3f& colour, const Texture* tex) {
  if (r.width <= 0 || r.height <= 0) return;
  PaintBody(
      layer,
      {{r.x, r.y}, {r.x + r.width, r.y}, {r.x + r.width, r.y + r.height}, {r.x, r.y + r.height}},
      r.x + r.width / 2, std::max(1.0, r.width), colour, tex, kFlat);
}

cv::Rect2d Inset(const cv::Rect2d& r, double d) {
  return {r.x + d, r.y + d, std::max(0.0, r.width - 2 * d), std::max(0.0, r.height - 2 * d)};
}

void PaintWall(cv::Mat* img, const RoomSpec& room, cv::RNG& rng) {
  const cv::Size size = img->size();
  const int W = size.width, H = size.height;
  cv::Mat low(5, 7, CV_32FC1);
  rng.fill(low, cv::RNG::NORMAL, 0, 1);
  cv::resize(low, low, size, 0, 0, cv::INTER_CUBIC);
  cv::Mat grain(size, CV_32FC1);
  rng.fill(grain, cv::RNG::NORMAL, 0, 1);
  cv::GaussianBlur(grain, grain, cv::Size(), 0.8);
  const double k = room.texture_strength;
  const double period = rng.uniform(7.0, 20.0) * H / 240.0;   // stripes, tiles
  const double brick_h = rng.uniform(7.0, 11.0) * H / 240.0;  // bricks
  const double panel_top = H * rng.uniform(0.5, 0.75);        // panel
  std::vector<float> brick_shade(4096);
  for (float& b : brick_shade) b = static_cast<float>(rng.uniform(-1.0, 1.0));
  const double lx = rng.uniform(0.2, 0.8) * W;  // where the room's light is brightest
  for (int y = 0; y < H; ++y) {
    cv::Vec3f* row = img->ptr<cv::Vec3f>(y);
    for (int x = 0; x < W; ++x) {
      const double gx = (x - lx) / W;
      double f =
          (1.06 - 0.14 * y / H) * (1 - 0.12 * gx * gx) * (1 + 0.035 * k * low.at<float>(y, x));
      double add = 3.0 * k * grain.at<float>(y, x);
      if (room.texture == "stripes") {
        f *= 1 + 0.05 * k * (std::fmod(x / period, 2.0) < 1.0 ? 1 : -1);
      } else if (room.texture == "tiles") {
        const bool grout = std::fmod(x, period * 2) < 1.2 || std::fmod(y, period * 2) < 1.2;
        if (grout) f *= 1 - 0.18 * k;
      } else if (room.texture == "bricks") {
        const int r = static_cast<int>(y / brick_h);
        const double bw = brick_h * 2.6;
        const double xs = x + (r % 2) * bw / 2;
        const int c = static_cast<int>(xs / bw);
        const bool mortar = std::fmod(y, brick_h) < 1.2 || std::fmod(xs, bw) < 1.2;
        f *= mortar ? 1 + 0.15 * k : 1 + 0.08 * k * brick_shade[(r * 131 + c) & 4095];
      } else if (room.texture == "panel" && y > panel_top) {
        f *= (std::fmod(x, period * 3) < 1.5 ? 0.8 : 0.93) - 0.03 * k;
        if (y < panel_top + 2.5 * H / 240.0) f *= 1.08;  // the dado rail
      }
      cv::Vec3f c = room.wall * static_cast<float>(f) + cv::Vec3f::all(static_cast<float>(add));
      if (y >= room.floor_y) {
        const double plank = std::fmod((y - room.floor_y) / (9.0 * H / 240.0), 1.0);
        c = room.floor *
                static_cast<float>((plank < 0.12 ? 0.82 : 1.0) * (1 + 0.06 * low.at<float>(y, x))) +
            cv::Vec3f::all(static_cast<float>(4 * grain.at<float>(y, x)));
      } else if (y >= room.floor_y - 5.0 * H / 240.0) {
        c = room.wall * 1.1f + cv::Vec3f::all(8.0f);  // skirting board
      }
      row[x] = Clamp255(c);
    }
  }
}

void PaintObject(Layer* bg, const RoomObject& o, double unit) {
  cv::RNG rng(Mix(o.salt, 0x0B1EC7));
  Texture tex = MakeTexture(rng, 0.05f, 0.8);
  const cv::Rect2d& b = o.box;
  switch (o.kind) {
    case ObjectKind::kCabinet: {
      FillRect(bg, b, o.colour, &tex);
      FillRect(bg, {b.x - 2 * unit, b.y - 3 * unit, b.width + 4 * unit, 4 * unit}, o.colour * 1.1f,
               &tex);
      const int shelves = rng.uniform(1, 4);
      for (int i = 1; i <= shelves; ++i) {
        const double yy = b.y + b.height * i / (shelves + 1);
        FillRect(bg, {b.x + 3 * unit, yy, b.width - 6 * unit, 1.2 * unit}, o.accent, nullptr);
      }
      PaintEllipse(bg, {b.x + b.width - 6 * unit, b.y + 0.2 * b.height}, 1.8 * unit, 1.8 * unit, 0,
                   o.accent * 1.3f, nullptr);
      break;
    }
    case ObjectKind::kShelf: {
      // A board with books standing on it.
      double x = b.x + 2 * unit;
      const double board_y = b.y + b.height - 3 * unit;
      while (x < b.x + b.width - 5 * unit) {
        const double bw = rng.uniform(2.5, 6.0) * unit;
        const double bh = rng.uniform(0.55, 1.0) * (b.height - 3 * unit);
        const cv::Vec3f c =
            Hsv(rng.uniform(0.0, 360.0), rng.uniform(0.2, 0.8), rng.uniform(0.25, 0.85));
        FillRect(bg, {x, board_y - bh, bw, bh}, c, &tex);
        x += bw + rng.uniform(0.0, 1.5) * unit;
      }
      FillRect(bg, {b.x, board_y, b.width, 3 * unit}, o.colour, &tex);
      break;
    }
    case ObjectKind::kPoster: {
      FillRect(bg, b, o.accent, nullptr);  // the frame
      const cv::Rect2d in = Inset(b, 2.5 * unit);
      FillRect(bg, in, o.colour, &tex);
      const int shapes = o.plain ? 0 : rng.uniform(0, 4);
      for (int i = 0; i < shapes; ++i) {
        const cv::Vec3f c =
            Hsv(rng.uniform(0.0, 360.0), rng.uniform(0.1, 0.9), rng.uniform(0.2, 0.95));
        const cv::Point2d ctr(in.x + rng.uniform(0.2, 0.8) * in.width,
                              in.y + rng.uniform(0.2, 0.8) * in.height);
        PaintEllipse(bg, ctr, rng.uniform(0.1, 0.3) * in.width, rng.uniform(0.1, 0.3) * in.height,
                     rng.uniform(0.0, 180.0), c, nullptr, kFlat);
      }
      break;
    }
    case ObjectKind::kDoor: {
      FillRect(bg, b, o.accent, &tex);  // the frame
      const cv::Rect2d leaf(b.x + 3 * unit, b.y + 3 * unit, b.width - 6 * unit, b.height);
      FillRect(bg, leaf, o.colour, &tex);
      for (double f : {0.08, 0.55}) {
        FillRect(
            bg,
            {leaf.x + 0.15 * leaf.width, leaf.y + f * leaf.height, 0.7 * leaf.width, 1.0 * unit},
            o.colour * 0.85f, nullptr);
      }
      PaintEllipse(bg, {leaf.x + 0.85 * leaf.width, leaf.y + 0.5 * leaf.height}, 2 * unit,
                   1.3 * unit, 0, o.accent * 0.6f + cv::Vec3f(60, 60, 60), nullptr);
      break;
    }
    case ObjectKind::kWindow: {
      FillRect(bg, b, o.accent, nullptr);
      const cv::Rect2d glass = Inset(b, 3 * unit);
      FillRect(bg, glass, o.colour, &tex);
      FillRect(bg, {glass.x + glass.width / 2 - unit, glass.y, 2 * unit, glass.height}, o.accent,
               nullptr);
      FillRect(bg, {glass.x, glass.y + glass.height / 2 - unit, glass.width, 2 * unit}, o.accent,
               nullptr);
      break;
    }
  }
}

// Does `r` overlap the disc of radius `rad` around `c`?
bool Overlaps(const cv::Rect2d& r, cv::Point2d c, double rad) {
  const double dx = c.x - std::clamp(c.x, r.x, r.x + r.width);
  const double dy = c.y - std::clamp(c.y, r.y, r.y + r.height);
  return dx * dx + dy * dy < rad * rad;
}

cv::Vec3f WoodOrPaint(cv::RNG& rng) {
  if (rng.uniform(0.0, 1.0) < 0.5) {
    return Hsv(rng.uniform(18.0, 40.0), rng.uniform(0.35, 0.75), rng.uniform(0.25, 0.7));
  }
  return Hsv(rng.uniform(0.0, 360.0), rng.uniform(0.0, 0.6), rng.uniform(0.2, 0.95));
}

// An object of `kind` of a plausible size, its box centred at `at` (x) and at its usual height
// unless `at_y` is set.
RoomObject MakeObject(cv::RNG& rng, ObjectKind kind, cv::Point2d at, bool at_y, cv::Size size,
                      double floor_y) {
  const double W = size.width, H = size.height;
  RoomObject o;
  o.kind = kind;
  o.salt = static_cast<uint64_t>(rng.next()) << 32 | rng.next();
  o.colour = WoodOrPaint(rng);
  o.accent = Hsv(rng.uniform(0.0, 360.0), rng.uniform(0.0, 0.5), rng.uniform(0.1, 0.95));
  const double floor = std::min(floor_y, H * 1.05);
  double w = 0, h = 0, y = 0;
  switch (kind) {
    case ObjectKind::kCabinet:
      w = rng.uniform(0.14, 0.3) * W, h = rng.uniform(0.25, 0.5) * H, y = floor - h;
      break;
    case ObjectKind::kShelf:
      w = rng.uniform(0.18, 0.35) * W, h = rng.uniform(0.08, 0.13) * H;
      y = rng.uniform(0.15, 0.55) * H;
      break;
    case ObjectKind::kPoster:
      w = rng.uniform(0.1, 0.3) * W, h = rng.uniform(0.15, 0.35) * H;
      y = rng.uniform(0.05, 0.45) * H;
      o.colour = Hsv(rng.uniform(0.0, 360.0), rng.uniform(0.0, 0.9), rng.uniform(0.2, 0.95));
      break;
    case ObjectKind::kDoor:
      w = rng.uniform(0.17, 0.28) * W, h = rng.uniform(0.75, 1.0) * floor, y = floor - h;
      break;
    case ObjectKind::kWindow:
      w = rng.uniform(0.18, 0.35) * W, h = rng.uniform(0.22, 0.4) * H;
      y = rng.uniform(0.05, 0.3) * H;
      o.colour = Hsv(rng.uniform(190.0, 220.0), rng.uniform(0.05, 0.35), rng.uniform(0.8, 1.0));
      o.accent = Hsv(0, 0, rng.uniform(0.75, 0.98));
      break;
  }
  if (at_y) y = at.y - h / 2;
  o.box = cv::Rect2d(at.x - w / 2, y, w, h);
  return o;
}

}  // namespace

RoomSpec DrawRoom(cv::RNG& rng, const RoomRequest& req, const PersonModel& m, cv::Size size,
                  const cv::Vec3f& wall) {
  RoomSpec room;
  room.wall = wall;
  const double H = size.height, W = size.width;
  static const char* const kTextures[] = {"plaster", "stripes", "panel", "bricks", "tiles"};
  const int kinds = req.tier == SceneTier::kEasy ? 1 : req.tier == SceneTier::kMedium ? 3 : 5;
  room.texture = kTextures[rng.uniform(0, kinds)];
  room.texture_strength = req.tier == SceneTier::kEasy     ? rng.uniform(0.3, 0.8)
                          : req.tier == SceneTier::kMedium ? rng.uniform(0.6, 1.3)
                                                           : rng.uniform(1.0, 2.0);
  room.floor_y = H * rng.uniform(0.7, 1.1);
  room.floor = Hsv(rng.uniform(15.0, 40.0), rng.uniform(0.3, 0.7), rng.uniform(0.25, 0.6));
  const cv::Point2d sh = m.Shoulder();
  const double reach = (m.upper + m.fore + m.hand) * m.s;
  auto random_kind = [&rng] { return static_cast<ObjectKind>(rng.uniform(0, 5)); };
  for (int i = 0; i < req.pieces; ++i) {
    const bool behind = req.behind_arm && i == 0;
    for (int attempt = 0; attempt < 30; ++attempt) {
      RoomObject o;
      if (behind) {
        // Somewhere the arm passes: around the shoulder on the arm's side.
        const double th = rng.uniform(-70.0, 80.0) * CV_PI / 180.0;
        const double r = rng.uniform(0.35, 0.95) * reach;
        o = MakeObject(rng, random_kind(), sh + cv::Point2d(std::cos(th), -std::sin(th)) * r, true,
                       size, room.floor_y);
      } else {
        o = MakeObject(rng, random_kind(), {rng.uniform(0.0, W), 0}, false, size, room.floor_y);
        if (req.keep_clear && Overlaps(o.box, sh, reach * 1.05)) continue;
      }
      room.objects.push_back(o);
      break;
    }
  }
  if (req.camouflage_object) {
    // Behind a segment of the arm at one moment of its motion, in that segment's colour.
    const ObjectKind kinds_camo[] = {ObjectKind::kPoster, ObjectKind::kDoor, ObjectKind::kCabinet};
    RoomObject o =
        MakeObject(rng, kinds_camo[rng.uniform(0, 3)], req.camo_at, true, size, room.floor_y);
    // About one segment in size, so the rest of the arm stays in view.
    const double side = req.camo_size * rng.uniform(req.camo_scale.first, req.camo_scale.second);
    const double height = side * rng.uniform(0.7, 1.3);
    o.box = cv::Rect2d(req.camo_at.x - side * rng.uniform(0.3, 0.7),
                       req.camo_at.y - height * rng.uniform(0.3, 0.7), side, height);
    o.kind = ObjectKind::kPoster;  // a flat surface in one colour
    o.colour = req.camo_colour;
    const cv::Vec3f jitter(static_cast<float>(rng.uniform(-8.0, 8.0)),
                           static_cast<float>(rng.uniform(-8.0, 8.0)),
                           static_cast<float>(rng.uniform(-8.0, 8.0)));
    o.colour = Clamp255(o.colour + jitter);
    o.accent = o.colour * 0.9f;
    o.plain = true;
    room.objects.push_back(o);
  }
  return room;
}

cv::Mat PaintRoom(const RoomSpec& room, cv::Size size, uint64_t seed) {
  cv::RNG rng(Mix(seed, 0x200A));
  cv::Mat img(size, CV_32FC3);
  PaintWall(&img, room, rng);
  Layer bg{img, cv::Mat()};
  const double unit = size.height / 240.0;
  for (const RoomObject& o : room.objects) PaintObject(&bg, o, unit);
  return img;
}

}  // namespace armmimic::synth::random_scene
