// Ray casting of the model joint (docs/synth.md, "Marker scenes"). Object frame: the pivot at the
// origin, y up along the lower part's axis, z towards the front (towards the camera at zero yaw).
// Yaw turns the object about y: world x = x cos + z sin, world z = -x sin + z cos.
#include "marker_render.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "armmimic/core/angles.h"

namespace armmimic::synth::internal {
namespace {

using V3 = cv::Vec3d;

enum class Surface { kNone, kLower, kLowerCap, kUpper, kCap, kBall };

struct Joint {
  double R, r, alpha, e, lower_len, upper_len;
  double c, s;  // cos and sin of yaw
  V3 u, v;      // upper axis and its in-plane normal, object frame
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
  return j;
}

V3 ToObject(const Joint& j, const V3& w) {
  return V3(w[0] * j.c - w[2] * j.s, w[1], w[0] * j.s + w[2] * j.c);
}
V3 ToWorld(const Joint& j, const V3& o) {
  return V3(o[0] * j.c + o[2] * j.s, o[1], -o[0] * j.s + o[2] * j.c);
}

// The ray through image point (x, y) in the object frame; `d` has unit length.
void Ray(const MarkerView& view, const Joint& j, double x, double y, V3* o, V3* d) {
  if (view.perspective) {
    const V3 dw = cv::normalize(V3((x - view.principal_px.x) / view.focal_px,
                                   (view.principal_px.y - y) / view.focal_px, -1));
    *o = ToObject(j, -view.pivot_world);
    *d = ToObject(j, dw);
  } else {
    constexpr double kFar = 1000;
    *o = ToObject(j, V3(x - view.pivot_world[0], view.pivot_world[1] - y, kFar));
    *d = ToObject(j, V3(0, 0, -1));
  }
}

// Nearest hit of the ray with the solid joint: the lower part (a capped cylinder), the upper part
// (a cylinder with a top cap; its foot lies inside the pivot ball) and the ball.
Surface Intersect(const Joint& j, const V3& o, const V3& d, double* t_hit) {
  double best = std::numeric_limits<double>::infinity();
  Surface surface = Surface::kNone;
  {  // lower part: x^2 + z^2 <= R^2 and -lower_len <= y <= 0
    const double a = d[0] * d[0] + d[2] * d[2];
    const double b = o[0] * d[0] + o[2] * d[2];
    const double cc = o[0] * o[0] + o[2] * o[2] - j.R * j.R;
    const double disc = b * b - a * cc;
    if (a > 1e-12 && disc >= 0) {
      const double side_in = (-b - std::sqrt(disc)) / a;
      const double side_out = (-b + std::sqrt(disc)) / a;
      double slab_in = -std::numeric_limits<double>::infinity();
      double slab_out = std::numeric_limits<double>::infinity();
      if (std::abs(d[1]) > 1e-12) {
        const double t1 = (-j.lower_len - o[1]) / d[1];
        const double t2 = -o[1] / d[1];
        slab_in = std::min(t1, t2);
        slab_out = std::max(t1, t2);
      } else if (o[1] < -j.lower_len || o[1] > 0) {
        slab_in = slab_out + 1;  // parallel to the caps and outside them
      }
      const double in = std::max(side_in, slab_in);
      if (in <= std::min(side_out, slab_out) && in > 0 && in < best) {
        best = in;
        surface = side_in >= slab_in ? Surface::kLower : Surface::kLowerCap;
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
      if (s >= 0 && s <= j.upper_len && t > 0 && t < best) {
        best = t;
        surface = Surface::kUpper;
      }
    }
    const double du = d.dot(j.u);
    if (std::abs(du) > 1e-9) {  // the upper part's end cap
      const double t = (j.upper_len - o.dot(j.u)) / du;
      const V3 p = o + t * d - j.upper_len * j.u;
      if (p.dot(p) <= j.R * j.R && t > 0 && t < best) {
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
      if (t > 0 && t < best) {
        best = t;
        surface = Surface::kBall;
      }
    }
  }
  *t_hit = best;
  return surface;
}

// Casts the ray through image point (x, y) (pixel centres at integers).
Sample Cast(const MarkerView& view, const Joint& j, const MarkerLight& light,
            const MarkerMaterial& mat, double x, double y) {
  V3 o, d;
  Ray(view, j, x, y, &o, &d);
  double t = 0;
  const Surface surface = Intersect(j, o, d, &t);
  Sample out;
  if (surface == Surface::kNone) return out;
  const V3 p = o + t * d;
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
    case Surface::kLowerCap:
      n = V3(0, p[1] < -0.5 * j.lower_len ? -1 : 1, 0);
      break;
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
  // Lambertian shading in the world frame: darker towards the limbs as the normal turns away.
  const double lambert = std::max(0.0, ToWorld(j, n).dot(light.dir));
  const double shade = 255.0 * light.gain * (light.ambient + (1 - light.ambient) * lambert);
  out.id = marker ? 2 : 1;
  out.bgr = marker ? cv::Vec3d::all(shade * mat.marker_albedo) : mat.cylinder_bgr * shade;
  return out;
}

// The image rectangle the joint can cover, from the projections of its bounding box.
cv::Rect JointBox(const MarkerJointModel& model, const MarkerView& view, cv::Size size) {
  const double reach = std::max(model.upper_length_px, model.lower_length_px) + model.radius_px;
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (double bx : {-reach, reach}) {
    for (double by : {-model.lower_length_px, reach}) {
      for (double bz : {-reach, reach}) {
        cv::Point2d q;
        if (view.perspective) {
          const V3 w = view.pivot_world + V3(bx, by, bz);
          if (w[2] > -1) return cv::Rect(0, 0, size.width, size.height);  // behind the camera
          q = {view.principal_px.x + view.focal_px * w[0] / -w[2],
               view.principal_px.y - view.focal_px * w[1] / -w[2]};
        } else {
          q = {view.pivot_world[0] + bx, view.pivot_world[1] - by};
        }
        x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
      }
    }
  }
  return cv::Rect(
             cv::Point(static_cast<int>(std::floor(x0)) - 2, static_cast<int>(std::floor(y0)) - 2),
             cv::Point(static_cast<int>(std::ceil(x1)) + 3, static_cast<int>(std::ceil(y1)) + 3)) &
         cv::Rect(0, 0, size.width, size.height);
}

}  // namespace

MarkerView MarkerView::Make(const MarkerJointModel& model, const MarkerCamera& camera,
                            cv::Size size) {
  MarkerView v;
  v.perspective = camera.projection == "perspective";
  v.principal_px = cv::Point2d(size.width / 2.0, size.height / 2.0);
  v.focal_px = 0.5 * size.width / std::tan(RadFromDeg(0.5 * camera.fov_deg));
  if (v.perspective) {
    v.pivot_world =
        V3(model.pivot_px.x - v.principal_px.x, v.principal_px.y - model.pivot_px.y, -v.focal_px);
  } else {
    v.pivot_world = V3(model.pivot_px.x, model.pivot_px.y, 0);
  }
  return v;
}

void RenderMarkerJoint(const MarkerJointModel& model, const MarkerView& view,
                       const MarkerPose& pose, const MarkerLight& light_in,
                       const MarkerMaterial& material, cv::Mat* canvas) {
  CV_Assert(canvas && canvas->type() == CV_32FC3);
  MarkerLight light = light_in;
  light.dir = cv::normalize(light.dir);
  const Joint j = MakeJoint(model, pose);
  const cv::Rect box = JointBox(model, view, canvas->size());
  if (box.empty()) return;
  // Pass 1: one sample per pixel centre.
  cv::Mat ids(box.size(), CV_8U);
  cv::Mat colour(box.size(), CV_32FC3);
  for (int yy = 0; yy < box.height; ++yy) {
    for (int xx = 0; xx < box.width; ++xx) {
      const Sample s = Cast(view, j, light, material, box.x + xx, box.y + yy);
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
          const Sample s = Cast(view, j, light, material, px, py);
          sum += s.id ? s.bgr : bg;
        }
      }
      sum *= 1.0 / (kSub * kSub);
      dst = cv::Vec3f(static_cast<float>(sum[0]), static_cast<float>(sum[1]),
                      static_cast<float>(sum[2]));
    }
  }
}

void ProjectMarkerJoint(const MarkerJointModel& model, const MarkerView& view,
                        const MarkerPose& pose, cv::Size size, MarkerTruth* truth) {
  const Joint j = MakeJoint(model, pose);
  // Object point -> world point relative to the camera (perspective) or image (parallel).
  auto project = [&](const V3& p) {
    const V3 w = ToWorld(j, p);
    if (!view.perspective)
      return cv::Point2d(view.pivot_world[0] + w[0], view.pivot_world[1] - w[1]);
    const V3 c = view.pivot_world + w;
    return cv::Point2d(view.principal_px.x + view.focal_px * c[0] / -c[2],
                       view.principal_px.y - view.focal_px * c[1] / -c[2]);
  };
  // cos of the angle between a surface normal at `p` and the direction to the camera.
  auto facing = [&](const V3& p, const V3& n) {
    const V3 nw = ToWorld(j, n);
    if (!view.perspective) return nw[2];
    return nw.dot(cv::normalize(-(view.pivot_world + ToWorld(j, p))));
  };
  const V3 nl(-std::sin(j.alpha), 0, std::cos(j.alpha));
  const V3 nr(std::sin(j.alpha), 0, std::cos(j.alpha));
  const V3 nu(0, 0, 1);
  const V3 pl = j.R * nl + V3(0, -j.e, 0);
  const V3 pr = j.R * nr + V3(0, -j.e, 0);
  const V3 pu = j.e * j.u + j.R * nu;
  truth->pose = pose;
  truth->yaw_deg = std::abs(pose.yaw_deg);
  truth->bend_deg = pose.bend_deg;
  truth->left_px = project(pl);
  truth->right_px = project(pr);
  truth->upper_px = project(pu);
  truth->pivot_px = project(V3(0, 0, 0));
  truth->left_cos = facing(pl, nl);
  truth->right_cos = facing(pr, nr);
  truth->upper_cos = facing(pu, nu);
  truth->min_marker_cos = std::min({truth->left_cos, truth->right_cos, truth->upper_cos});
  const cv::Rect2d inside(j.r, j.r, size.width - 2 * j.r, size.height - 2 * j.r);
  truth->left_readable = truth->left_cos >= kMarkerHiddenCos && inside.contains(truth->left_px);
  truth->right_readable = truth->right_cos >= kMarkerHiddenCos && inside.contains(truth->right_px);
  truth->upper_readable = truth->upper_cos >= kMarkerHiddenCos && inside.contains(truth->upper_px);
  truth->readable = truth->left_readable || truth->right_readable;
}

}  // namespace armmimic::synth::internal
