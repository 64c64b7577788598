// The capsule scenes' room: a textured wall (paint, bricks, tiles, wallpaper, wood, concrete),
// objects on it, a floor and a ceiling, ray cast through the same camera as the person.
#include <algorithm>
#include <cmath>

#include "capsule_model.h"

namespace armmimic::synth::capsule {
namespace {

double Hash01(int64_t ix, int64_t iy, uint64_t salt) {
  Rng r(salt ^ (static_cast<uint64_t>(ix) * 0x9E3779B97F4A7C15ULL) ^
        (static_cast<uint64_t>(iy) * 0xC2B2AE3D27D4EB4FULL));
  return r.Uniform(0, 1);
}

double Frac(double x) { return x - std::floor(x); }

// Pattern value of a brick or tile lattice: the cell's index and whether (x, y) lies on the
// joint between cells (`joint` metres wide).
struct Cell {
  int64_t ix = 0, iy = 0;
  bool joint = false;
};

Cell Lattice(double x, double y, double w, double h, double joint, bool stagger) {
  Cell c;
  c.iy = static_cast<int64_t>(std::floor(y / h));
  const double xo = stagger && (c.iy & 1) ? x + w * 0.5 : x;
  c.ix = static_cast<int64_t>(std::floor(xo / w));
  const double fx = Frac(xo / w) * w, fy = Frac(y / h) * h;
  c.joint = fx < joint || fy < joint;
  return c;
}

cv::Vec3f WallAlbedo(const Room& room, double x, double y) {
  const double k = room.texture_strength, s = room.texture_scale;
  const uint64_t salt = room.salt;
  if (room.dado_y > 0 && y < room.dado_y) {
    if (y < 0.1) return room.dado * 0.85f;  // skirting board
    const double board = Frac(x / (0.12 * s));
    return room.dado * static_cast<float>(
                           board < 0.04 ? 0.8 : 1.0 + 0.05 * k * Fbm(x * 2, y * 30, salt + 9, 2));
  }
  if (y < 0.1) return room.wall2 * 0.9f;  // skirting board
  const std::string& t = room.texture;
  if (t == "bricks") {
    const Cell c = Lattice(x, y, 0.225 * s, 0.075 * s, 0.011 * s, true);
    if (c.joint) return room.wall2;
    const double v = 1 + 0.16 * k * (Hash01(c.ix, c.iy, salt) - 0.5) +
                     0.05 * k * Fbm(x * 60, y * 60, salt + 1, 2);
    return room.wall * static_cast<float>(v);
  }
  if (t == "tiles") {
    const Cell c = Lattice(x, y, 0.15 * s, 0.15 * s, 0.006 * s, false);
    if (c.joint) return room.wall2;
    const bool alt = ((c.ix + c.iy) & 1) != 0;
    const double v = 1 + 0.05 * k * (Hash01(c.ix, c.iy, salt) - 0.5);
    return (alt && k > 1.2 ? room.wall * 0.8f + room.wall2 * 0.2f : room.wall) *
           static_cast<float>(v);
  }
  if (t == "wallpaper") {
    const double p = 0.09 * s;
    const double sx = std::sin(x / p * 2 * 3.14159), sy = std::sin(y / p * 2 * 3.14159);
    const double motif = sx * sy + 0.4 * std::sin((x + y) / p * 3.14159);
    const bool stripe = Frac(x / (2.2 * p)) < 0.3;
    const float m =
        static_cast<float>(std::clamp((motif - 0.55) * 4.0, 0.0, 1.0) * std::min(1.0, k));
    cv::Vec3f c = room.wall * (1 - m) + room.wall2 * m;
    if (stripe) c = c * 0.92f + room.wall2 * 0.08f;
    return c;
  }
  if (t == "wood") {
    const double w = 0.13 * s;
    const int64_t ix = static_cast<int64_t>(std::floor(x / w));
    if (Frac(x / w) < 0.03) return room.wall * 0.55f;
    const double grain = std::sin((x * 90 + 6 * Fbm(x * 4, y * 0.8, salt + ix, 3)) * 3.0);
    const double v = 1 + 0.18 * k * (Hash01(ix, 0, salt) - 0.5) + 0.07 * k * grain;
    return room.wall * static_cast<float>(v);
  }
  if (t == "concrete") {
    const double v =
        1 + 0.12 * k * Fbm(x * 6, y * 6, salt, 4) + 0.06 * k * Fbm(x * 50, y * 50, salt + 3, 2);
    return room.wall * static_cast<float>(v);
  }
  const double v = 1 + 0.05 * k * Fbm(x * 2.5, y * 2.5, salt, 3);  // paint
  return room.wall * static_cast<float>(v);
}

// An object's colour at (x, y) on the wall, or false where the wall shows.
bool ObjectAlbedo(const WallObject& o, double x, double y, cv::Vec3f* out) {
  const cv::Rect2d& b = o.box;
  if (x < b.x || x > b.x + b.width || y < b.y || y > b.y + b.height) return false;
  const double u = (x - b.x) / b.width, v = (y - b.y) / b.height;
  const double edge = std::min({x - b.x, b.x + b.width - x, y - b.y, b.y + b.height - y});
  if (o.kind == "picture") {
    if (edge < 0.03) {
      *out = o.accent;
    } else {
      const double n = Fbm(u * 3, v * 3, o.salt, 3);
      *out = n > 0.1 ? o.colour
                     : (n < -0.2 ? o.accent * 0.5f + cv::Vec3f(200, 210, 220) * 0.5f
                                 : o.colour * 0.5f + o.accent * 0.5f);
    }
  } else if (o.kind == "door") {
    *out =
        edge < 0.04 ? o.accent : o.colour * static_cast<float>(Frac(v * 2.2) < 0.04 ? 0.85 : 1.0);
    if (std::hypot(u - 0.88, v - 0.45) * b.width < 0.03) *out = cv::Vec3f(60, 170, 200);
  } else if (o.kind == "shelf") {
    const double row = Frac(v * 3);
    if (row < 0.1 || edge < 0.02) {
      *out = o.colour;
    } else {
      const int64_t book = static_cast<int64_t>(std::floor(u * 14 + std::floor(v * 3) * 5));
      const double h = Hash01(book, 1, o.salt);
      *out = h < 0.2 ? o.colour * 0.6f
                     : cv::Vec3f(static_cast<float>(60 + 160 * Hash01(book, 2, o.salt)),
                                 static_cast<float>(60 + 160 * Hash01(book, 3, o.salt)),
                                 static_cast<float>(60 + 160 * Hash01(book, 4, o.salt)));
    }
  } else if (o.kind == "window") {
    const bool bar =
        edge < 0.05 || std::abs(u - 0.5) * b.width < 0.025 || std::abs(v - 0.5) * b.height < 0.025;
    *out =
        bar ? o.accent : o.colour * static_cast<float>(1.0 + 0.05 * Fbm(u * 4, v * 4, o.salt, 2));
  } else {  // a plain panel or poster in one colour
    *out = o.colour;
  }
  return true;
}

cv::Vec3f FloorAlbedo(const Room& room, double x, double z) {
  if (room.floor_kind == "carpet") {
    return room.floor * static_cast<float>(1 + 0.08 * Fbm(x * 30, z * 30, room.salt + 7, 2));
  }
  const double w = 0.14;
  const int64_t iz = static_cast<int64_t>(std::floor(z / w));
  const double gap = Frac(z / w) < 0.05 ? 0.7 : 1.0;
  const double v =
      1 + 0.15 * (Hash01(iz, 3, room.salt) - 0.5) + 0.05 * Fbm(x * 20, z * 3, room.salt + iz, 2);
  return room.floor * static_cast<float>(v * gap);
}

}  // namespace

double ValueNoise(double x, double y, uint64_t salt) {
  const double fx = std::floor(x), fy = std::floor(y);
  const int64_t ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy);
  double tx = x - fx, ty = y - fy;
  tx = tx * tx * (3 - 2 * tx);
  ty = ty * ty * (3 - 2 * ty);
  const double a = Hash01(ix, iy, salt), b = Hash01(ix + 1, iy, salt);
  const double c = Hash01(ix, iy + 1, salt), d = Hash01(ix + 1, iy + 1, salt);
  return 2 * ((a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty) - 1;
}

double Fbm(double x, double y, uint64_t salt, int octaves) {
  double sum = 0, amp = 0.5, norm = 0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * ValueNoise(x, y, salt + static_cast<uint64_t>(i) * 131);
    norm += amp;
    x *= 2.03;
    y *= 2.03;
    amp *= 0.5;
  }
  return sum / norm;
}

RoomView RenderRoom(const Room& room, const Camera& cam, const Light& light, cv::Size size) {
  RoomView view;
  view.colour.create(size, CV_32FC3);
  view.point.create(size, CV_32FC3);
  view.normal.create(size, CV_32FC3);
  const double c = std::cos(cam.pitch_rad), s = std::sin(cam.pitch_rad);
  const double offs[5][2] = {{0, 0}, {-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}};
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      cv::Vec3f sum(0, 0, 0);
      for (int k = 0; k < 5; ++k) {
        const cv::Vec3d d = cam.Ray(x + offs[k][0], y + offs[k][1]);
        // The ray in the world (the camera's rotation transposed).
        const cv::Vec3d dw(d[0], -c * d[1] - s * d[2], s * d[1] - c * d[2]);
        const cv::Vec3d& o = cam.position;
        double t = 1e9;
        cv::Vec3d n(0, 0, 1);
        int surface = 0;  // 0 wall, 1 floor, 2 ceiling
        if (dw[2] < -1e-9) t = (room.wall_z - o[2]) / dw[2];
        if (dw[1] < -1e-9 && -o[1] / dw[1] < t) {
          t = -o[1] / dw[1];
          n = {0, 1, 0};
          surface = 1;
        }
        if (dw[1] > 1e-9 && (room.ceiling_y - o[1]) / dw[1] < t) {
          t = (room.ceiling_y - o[1]) / dw[1];
          n = {0, -1, 0};
          surface = 2;
        }
        const cv::Vec3d p = o + t * dw;
        cv::Vec3f albedo;
        if (surface == 1) {
          albedo = FloorAlbedo(room, p[0], p[2]);
        } else if (surface == 2) {
          albedo = room.ceiling;
        } else {
          bool on_object = false;
          for (const WallObject& obj : room.objects) {
            if (ObjectAlbedo(obj, p[0], p[1], &albedo)) on_object = true;
          }
          if (!on_object) albedo = WallAlbedo(room, p[0], p[1]);
        }
        const cv::Vec3d to_light = light.position - p;
        const double dist = Len(to_light);
        const double diffuse = std::max(0.0, Dot(n, to_light) / dist) * light.Falloff(dist);
        for (int ch = 0; ch < 3; ++ch) {
          sum[ch] +=
              albedo[ch] * static_cast<float>(light.ambient + light.key * diffuse * light.tint[ch]);
        }
        if (k == 0) {
          view.point.at<cv::Vec3f>(y, x) = cam.ToCam(p);
          view.normal.at<cv::Vec3f>(y, x) = cam.DirToCam(n);
          sum = cv::Vec3f(0, 0, 0);  // the centre ray gives the point; four rays the colour
        }
      }
      view.colour.at<cv::Vec3f>(y, x) = sum * 0.25f;
    }
  }
  return view;
}

}  // namespace armmimic::synth::capsule
