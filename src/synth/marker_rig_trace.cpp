// The rig renderer's ray tracer (docs/synth.md, "The rig renderer"). Every image sample casts a
// ray through the distorting lens, meets the joint (two glossy capped cylinders of radius 1 and
// a ball at the pivot, in the joint's own frame) or the wall behind it, and is shaded with
// Lambert and Blinn-Phong terms; wall points test a ray towards the light for the joint's
// shadow.
#include "marker_rig_trace.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "armmimic/core/angles.h"

namespace armmimic::synth::rig {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = 1e-9;

enum class Part { kNone, kLowerSide, kUpperSide, kCap, kBall };

struct Hit {
  double t = kInf;
  Part part = Part::kNone;
  V3 normal;  // joint frame, unit
};

// The joint in one pose: its frame turned by the yaw about world y.
struct Pose {
  double c = 1, s = 0;  // cos, sin of the yaw
  V3 up{0, 1, 0};       // the upper part's axis (joint frame)
  V3 side{1, 0, 0};     // its in-plane normal
  V3 ToJoint(const V3& w) const { return V3(c * w[0] - s * w[2], w[1], s * w[0] + c * w[2]); }
  V3 ToWorld(const V3& j) const { return V3(c * j[0] + s * j[2], j[1], -s * j[0] + c * j[2]); }
};

Pose MakePose(const MarkerPose& p) {
  Pose out;
  const double yaw = RadFromDeg(p.yaw_deg), bend = RadFromDeg(p.bend_deg);
  out.c = std::cos(yaw);
  out.s = std::sin(yaw);
  out.up = V3(-std::sin(bend), std::cos(bend), 0);
  out.side = V3(std::cos(bend), std::sin(bend), 0);
  return out;
}

// A unit-radius cylinder about the axis `a` through the origin, between s0 and s1 along it,
// with a flat cap at s_cap (the other end lies inside the ball).
void Cylinder(const V3& o, const V3& d, const V3& a, double s0, double s1, double s_cap, Part part,
              Hit* hit) {
  const double oa = o.dot(a), da = d.dot(a);
  const V3 q = o - oa * a, w = d - da * a;
  const double A = w.dot(w), B = q.dot(w), C = q.dot(q) - 1;
  const double disc = B * B - A * C;
  if (A > kEps && disc >= 0) {
    const double t = (-B - std::sqrt(disc)) / A;
    const double s = oa + t * da;
    if (t > kEps && t < hit->t && s >= s0 && s <= s1) {
      hit->t = t;
      hit->part = part;
      const V3 p = o + t * d;
      hit->normal = p - p.dot(a) * a;
    }
  }
  if (std::abs(da) > kEps) {
    const double t = (s_cap - oa) / da;
    const V3 p = o + t * d - s_cap * a;
    if (t > kEps && t < hit->t && p.dot(p) <= 1) {
      hit->t = t;
      hit->part = Part::kCap;
      hit->normal = s_cap > 0 ? a : -a;
    }
  }
}

Hit Intersect(const RigScene& sc, const Pose& pose, const V3& o, const V3& d) {
  Hit hit;
  Cylinder(o, d, V3(0, 1, 0), -sc.lower_length, 0, -sc.lower_length, Part::kLowerSide, &hit);
  Cylinder(o, d, pose.up, 0, sc.upper_length, sc.upper_length, Part::kUpperSide, &hit);
  const double b = o.dot(d), c = o.dot(o) - 1, disc = b * b - c;
  if (disc >= 0) {
    const double t = -b - std::sqrt(disc);
    if (t > kEps && t < hit.t) {
      hit.t = t;
      hit.part = Part::kBall;
      hit.normal = o + t * d;
    }
  }
  return hit;
}

// Geodesic distance (squared) to the nearest marker centre at the joint-frame point p.
bool OnMarker(const RigScene& sc, const Pose& pose, const Hit& hit, const V3& p) {
  const double r2 = sc.marker_radius * sc.marker_radius;
  if (hit.part == Part::kLowerSide) {
    const double theta = std::atan2(p[0], p[2]), dy = p[1] + sc.e;
    for (double side : {-1.0, 1.0}) {
      const double arc = theta - side * sc.marker_angle;
      if (arc * arc + dy * dy <= r2) return true;
    }
    return false;
  }
  if (hit.part == Part::kUpperSide) {
    const double s = p.dot(pose.up);
    const V3 radial = p - s * pose.up;
    const double arc = std::atan2(radial.dot(pose.side), radial[2]);
    return arc * arc + (s - sc.e) * (s - sc.e) <= r2;
  }
  return false;
}

V3 WallAlbedo(const RigScene& sc, double x, double y) {
  V3 a = sc.wall_bgr + V3::all(sc.wall_gradient[0] * x + sc.wall_gradient[1] * y);
  if (sc.ripple > 0) {
    const cv::Vec3d& f = sc.ripple_freq;
    a += V3::all(sc.ripple *
                 (std::sin(f[0] * x + 0.3) * std::cos(f[1] * y) + 0.5 * std::sin(f[2] * (x + y))) /
                 1.5);
  }
  for (const WallRect& r : sc.posters) {
    if (r.box.contains(cv::Point2d(x, y))) a = r.bgr;
  }
  for (const WallDisc& k : sc.discs) {
    const double dx = x - k.centre.x, dy = y - k.centre.y;
    const double ca = std::cos(k.angle), sa = std::sin(k.angle);
    const double u = (ca * dx + sa * dy) / k.rx, v = (-sa * dx + ca * dy) / k.ry;
    if (u * u + v * v <= 1) a = V3::all(k.albedo);
  }
  return a;
}

V3 Shade(const RigScene& sc, const Pose& pose, const V3& origin, const V3& dir) {
  const V3 l = sc.light;
  const V3 o = pose.ToJoint(origin), d = pose.ToJoint(dir);
  const Hit hit = Intersect(sc, pose, o, d);
  if (hit.part == Part::kNone) {
    const double t = (-sc.wall_depth - origin[2]) / dir[2];
    const V3 p = origin + t * dir;
    // In the joint's shadow only the ambient share lights the wall.
    const bool shadow = Intersect(sc, pose, pose.ToJoint(p), pose.ToJoint(l)).part != Part::kNone;
    const double light = sc.ambient + (shadow ? 0 : (1 - sc.ambient) * std::max(0.0, l[2]));
    return WallAlbedo(sc, p[0], p[1]) * (255 * sc.gain * light);
  }
  const V3 p = o + hit.t * d;
  const V3 n = pose.ToWorld(cv::normalize(hit.normal));
  const bool marker = OnMarker(sc, pose, hit, p);
  const double lambert = std::max(0.0, n.dot(l));
  const V3 half = cv::normalize(l - dir);
  const double gloss = (marker ? sc.marker_gloss : 1.0) * sc.specular *
                       std::pow(std::max(0.0, n.dot(half)), sc.shininess) * (lambert > 0);
  const V3 albedo = marker ? V3::all(sc.marker_albedo) : sc.body_bgr;
  return (albedo * (sc.ambient + (1 - sc.ambient) * lambert) + V3::all(gloss)) * (255 * sc.gain);
}

}  // namespace

bool RigCamera::Project(const V3& world, cv::Point2d* px) const {
  const V3 c = from_world * (world - centre);
  if (c[2] <= kEps) return false;
  const double x = c[0] / c[2], y = c[1] / c[2], r2 = x * x + y * y;
  const double k = 1 + k1 * r2 + k2 * r2 * r2;
  *px = {principal_px.x + focal_px * k * x, principal_px.y + focal_px * k * y};
  return true;
}

V3 RigCamera::Ray(double u, double v) const {
  const double xd = (u - principal_px.x) / focal_px, yd = (v - principal_px.y) / focal_px;
  double x = xd, y = yd;
  for (int i = 0; i < 8; ++i) {
    const double r2 = x * x + y * y, k = 1 + k1 * r2 + k2 * r2 * r2;
    x = xd / k;
    y = yd / k;
  }
  return cv::normalize(from_world.t() * V3(x, y, 1));
}

void TraceRig(const RigScene& scene, const MarkerPose& pose_in, cv::Size size, cv::Mat* out) {
  const Pose pose = MakePose(pose_in);
  out->create(size, CV_32FC3);
  constexpr int kSub = 3;
  for (int y = 0; y < size.height; ++y) {
    cv::Vec3f* row = out->ptr<cv::Vec3f>(y);
    for (int x = 0; x < size.width; ++x) {
      V3 sum(0, 0, 0);
      for (int i = 0; i < kSub; ++i) {
        for (int j = 0; j < kSub; ++j) {
          const double u = x + (j + 0.5) / kSub - 0.5, v = y + (i + 0.5) / kSub - 0.5;
          sum += Shade(scene, pose, scene.camera.centre, scene.camera.Ray(u, v));
        }
      }
      sum *= 1.0 / (kSub * kSub);
      row[x] = cv::Vec3f(static_cast<float>(sum[0]), static_cast<float>(sum[1]),
                         static_cast<float>(sum[2]));
    }
  }
}

void RigTruth(const RigScene& sc, const MarkerPose& pose_in, cv::Size size, MarkerTruth* t) {
  const Pose pose = MakePose(pose_in);
  t->pose = pose_in;
  t->yaw_deg = std::abs(pose_in.yaw_deg);
  t->bend_deg = pose_in.bend_deg;
  const cv::Rect2d image(0, 0, size.width, size.height);
  // Centre and normal of each marker (joint frame): left, right, upper.
  const double a = sc.marker_angle;
  const V3 centres[3] = {V3(-std::sin(a), -sc.e, std::cos(a)), V3(std::sin(a), -sc.e, std::cos(a)),
                         sc.e * pose.up + V3(0, 0, 1)};
  const V3 normals[3] = {V3(-std::sin(a), 0, std::cos(a)), V3(std::sin(a), 0, std::cos(a)),
                         V3(0, 0, 1)};
  cv::Point2d px[3];
  double cosines[3];
  bool readable[3];
  for (int i = 0; i < 3; ++i) {
    const V3 p = pose.ToWorld(centres[i]), n = pose.ToWorld(normals[i]);
    cosines[i] = n.dot(cv::normalize(sc.camera.centre - p));
    const bool seen = sc.camera.Project(p, &px[i]);
    readable[i] = seen && cosines[i] >= kMarkerHiddenCos && image.contains(px[i]);
  }
  t->left_px = px[0];
  t->right_px = px[1];
  t->upper_px = px[2];
  t->left_cos = cosines[0];
  t->right_cos = cosines[1];
  t->upper_cos = cosines[2];
  t->min_marker_cos = std::min({cosines[0], cosines[1], cosines[2]});
  t->left_readable = readable[0];
  t->right_readable = readable[1];
  t->upper_readable = readable[2];
  t->readable = readable[0] || readable[1];
  sc.camera.Project(V3(0, 0, 0), &t->pivot_px);
}

}  // namespace armmimic::synth::rig
