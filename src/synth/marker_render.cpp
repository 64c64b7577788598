// Ray casting of the model joint (docs/marker.md, "The model joint"). Object frame: the pivot at
// the origin, y up along the lower part's axis, z towards the camera at zero yaw. The camera is
// orthographic and looks along -z of the world; yaw turns the object about y.
#include "marker_render.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "armmimic/core/angles.h"

namespace armmimic::synth::internal {
namespace {

using V3 = cv::Vec3d;

enum class Surface { kNone, kLower, kUpper, kCap, kBall };

struct Joint {
  double R, r, alpha, e, lower_len, upper_len;
  double c, s;  // cos and sin of yaw
  V3 u, v;      // upper axis and its in-plane normal, object frame
  cv::Point2d pivot;
};

struct Sample {
  int id = 0;  // 0 background, 1 joint surface, 2 marker
  cv::Vec3d bgr;
};

Joint MakeJoint(const MarkerJointModel& m, const MarkerPose& pose) {
  Joint j;
  j.R = m.radius_px;
  j.r = m.marker_radius_px;
  j.alpha = RadFromDeg(m.marker_angle_deg);
  j.e = m.pivot_distance_px;
  j.lower_len = m.lower_length_px;
  j.upper_len = m.upper_length_px;
  const double yaw = RadFromDeg(pose.yaw_deg);
  const double bend = RadFromDeg(pose.bend_deg);
  j.c = std::cos(yaw);
  j.s = std::sin(yaw);
  j.u = V3(-std::sin(bend), std::cos(bend), 0);
  j.v = V3(std::cos(bend), std::sin(bend), 0);
  j.pivot = m.pivot_px;
  return j;
}

// Casts the ray through image point (x, y) (pixel centres at integers).
Sample Cast(const Joint& j, const MarkerLight& light, const MarkerMaterial& mat, double x,
            double y) {
  constexpr double kFar = 1000;
  const double X = x - j.pivot.x;
  const double Y = j.pivot.y - y;
  const V3 o(X * j.c - kFar * j.s, Y, X * j.s + kFar * j.c);
  const V3 d(j.s, 0, -j.c);
  double best = std::numeric_limits<double>::infinity();
  Surface surface = Surface::kNone;

  {  // lower part: x^2 + z^2 = R^2, -lower_len <= y <= 0
    const double b = o[0] * d[0] + o[2] * d[2];
    const double cc = o[0] * o[0] + o[2] * o[2] - j.R * j.R;
    const double disc = b * b - cc;
    if (disc >= 0 && Y >= -j.lower_len && Y <= 0) {
      const double t = -b - std::sqrt(disc);
      if (t < best) {
        best = t;
        surface = Surface::kLower;
      }
    }
  }
  {  // upper part: distance R from the axis u, 0 <= s <= upper_len
    const V3 q = o - o.dot(j.u) * j.u;
    const V3 ev = d - d.dot(j.u) * j.u;
    const double a = ev.dot(ev);
    const double b = q.dot(ev);
    const double cc = q.dot(q) - j.R * j.R;
    const double disc = b * b - a * cc;
    if (a > 1e-12 && disc >= 0) {
      const double t = (-b - std::sqrt(disc)) / a;
      const double s = (o + t * d).dot(j.u);
      if (s >= 0 && s <= j.upper_len && t < best) {
        best = t;
        surface = Surface::kUpper;
      }
    }
    const double du = d.dot(j.u);
    if (std::abs(du) > 1e-9) {  // the upper part's end cap
      const double t = (j.upper_len - o.dot(j.u)) / du;
      const V3 p = o + t * d - j.upper_len * j.u;
      if (p.dot(p) <= j.R * j.R && t < best) {
        best = t;
        surface = Surface::kCap;
      }
    }
  }
  {  // the pivot ball
    const double b = o.dot(d);
    const double cc = o.dot(o) - j.R * j.R;
    const double disc = b * b - cc;
    if (disc >= 0) {
      const double t = -b - std::sqrt(disc);
      if (t < best) {
        best = t;
        surface = Surface::kBall;
      }
    }
  }
  Sample out;
  if (surface == Surface::kNone) return out;
  const V3 p = o + best * d;
  V3 n;
  bool marker = false;
  switch (surface) {
    case Surface::kLower: {
      n = V3(p[0] / j.R, 0, p[2] / j.R);
      const double theta = std::atan2(p[0], p[2]);
      const double dy = p[1] + j.e;
      for (double side : {-1.0, 1.0}) {
        const double arc = j.R * (theta - side * j.alpha);
        if (arc * arc + dy * dy <= j.r * j.r) marker = true;
      }
      break;
    }
    case Surface::kUpper: {
      const double s = p.dot(j.u);
      const V3 radial = p - s * j.u;
      n = radial * (1.0 / j.R);
      const double arc = j.R * std::atan2(radial.dot(j.v), radial[2]);
      const double ds = s - j.e;
      marker = arc * arc + ds * ds <= j.r * j.r;
      break;
    }
    case Surface::kCap:
      n = j.u;
      break;
    case Surface::kBall:
      n = p * (1.0 / j.R);
      break;
    case Surface::kNone:
      break;
  }
  // Normal to the world frame; Lambertian shading.
  const V3 nw(n[0] * j.c + n[2] * j.s, n[1], -n[0] * j.s + n[2] * j.c);
  const double lambert = std::max(0.0, nw.dot(light.dir));
  const double shade = 255.0 * light.gain * (light.ambient + (1 - light.ambient) * lambert);
  out.id = marker ? 2 : 1;
  if (marker) {
    out.bgr = cv::Vec3d::all(shade * mat.marker_albedo);
  } else {
    out.bgr = mat.cylinder_bgr * shade;
  }
  return out;
}

}  // namespace

void RenderMarkerJoint(const MarkerJointModel& model, const MarkerPose& pose,
                       const MarkerLight& light_in, const MarkerMaterial& material,
                       cv::Mat* canvas) {
  CV_Assert(canvas && canvas->type() == CV_32FC3);
  MarkerLight light = light_in;
  light.dir = cv::normalize(light.dir);
  const Joint j = MakeJoint(model, pose);
  const double reach = std::max(model.upper_length_px, model.lower_length_px) + model.radius_px;
  const cv::Rect box =
      cv::Rect(cv::Point(static_cast<int>(std::floor(j.pivot.x - reach)) - 2,
                         static_cast<int>(std::floor(j.pivot.y - reach)) - 2),
               cv::Point(static_cast<int>(std::ceil(j.pivot.x + reach)) + 3,
                         static_cast<int>(std::ceil(j.pivot.y + model.lower_length_px)) + 3)) &
      cv::Rect(0, 0, canvas->cols, canvas->rows);
  if (box.empty()) return;
  // Pass 1: one sample per pixel centre.
  cv::Mat ids(box.size(), CV_8U);
  cv::Mat colour(box.size(), CV_32FC3);
  for (int yy = 0; yy < box.height; ++yy) {
    for (int xx = 0; xx < box.width; ++xx) {
      const Sample s = Cast(j, light, material, box.x + xx, box.y + yy);
      ids.at<uchar>(yy, xx) = static_cast<uchar>(s.id);
      colour.at<cv::Vec3f>(yy, xx) = s.bgr;
    }
  }
  // Pass 2: pixels next to a change of surface are supersampled (antialiased edges).
  constexpr int kSub = 4;
  for (int yy = 0; yy < box.height; ++yy) {
    for (int xx = 0; xx < box.width; ++xx) {
      const int id = ids.at<uchar>(yy, xx);
      bool edge = false;
      for (int dy = -1; dy <= 1 && !edge; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int ny = yy + dy, nx = xx + dx;
          if (ny < 0 || nx < 0 || ny >= box.height || nx >= box.width) continue;
          if (ids.at<uchar>(ny, nx) != id) {
            edge = true;
            break;
          }
        }
      }
      cv::Vec3f& dst = canvas->at<cv::Vec3f>(box.y + yy, box.x + xx);
      if (!edge) {
        if (id != 0) dst = colour.at<cv::Vec3f>(yy, xx);
        continue;
      }
      cv::Vec3d sum(0, 0, 0);
      const cv::Vec3d bg(dst[0], dst[1], dst[2]);
      for (int sy = 0; sy < kSub; ++sy) {
        for (int sx = 0; sx < kSub; ++sx) {
          const double px = box.x + xx - 0.5 + (sx + 0.5) / kSub;
          const double py = box.y + yy - 0.5 + (sy + 0.5) / kSub;
          const Sample s = Cast(j, light, material, px, py);
          sum += s.id ? s.bgr : bg;
        }
      }
      sum *= 1.0 / (kSub * kSub);
      dst = cv::Vec3f(static_cast<float>(sum[0]), static_cast<float>(sum[1]),
                      static_cast<float>(sum[2]));
    }
  }
}

void ProjectMarkerJoint(const MarkerJointModel& model, const MarkerPose& pose, cv::Size size,
                        MarkerTruth* truth) {
  const Joint j = MakeJoint(model, pose);
  auto project = [&](const V3& p) {
    const double xw = p[0] * j.c + p[2] * j.s;
    return cv::Point2d(j.pivot.x + xw, j.pivot.y - p[1]);
  };
  auto facing = [&](const V3& n) { return -n[0] * j.s + n[2] * j.c; };
  const V3 nl(-std::sin(j.alpha), 0, std::cos(j.alpha));
  const V3 nr(std::sin(j.alpha), 0, std::cos(j.alpha));
  const V3 nu(0, 0, 1);
  truth->pose = pose;
  truth->yaw_deg = std::abs(pose.yaw_deg);
  truth->bend_deg = pose.bend_deg;
  truth->left_px = project(j.R * nl + V3(0, -j.e, 0));
  truth->right_px = project(j.R * nr + V3(0, -j.e, 0));
  truth->upper_px = project(j.e * j.u + j.R * nu);
  truth->pivot_px = j.pivot;
  truth->min_marker_cos = std::min({facing(nl), facing(nr), facing(nu)});
  const cv::Rect2d inside(j.r, j.r, size.width - 2 * j.r, size.height - 2 * j.r);
  truth->readable = truth->min_marker_cos >= kMarkerHiddenCos && inside.contains(truth->left_px) &&
                    inside.contains(truth->right_px) && inside.contains(truth->upper_px);
}

}  // namespace armmimic::synth::internal
