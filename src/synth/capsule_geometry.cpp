// The capsule scenes' geometry: random numbers, the pinhole camera, ray-capsule intersection and
// segment distances.
#include <algorithm>
#include <cmath>

#include "capsule_model.h"

namespace armmimic::synth::capsule {

uint64_t Rng::Next() {
  uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double Rng::Uniform(double lo, double hi) {
  const double u = static_cast<double>(Next() >> 11) * (1.0 / 9007199254740992.0);
  return lo + (hi - lo) * u;
}

int Rng::Int(int lo, int hi) {
  const uint64_t span = static_cast<uint64_t>(hi - lo) + 1;
  return lo + static_cast<int>(Next() % span);
}

uint64_t MixSeed(uint64_t seed, uint64_t salt) {
  Rng r(seed ^ (salt * 0xD6E8FEB86659FD93ULL));
  r.Next();
  return r.Next();
}

cv::Vec3d Camera::ToCam(const cv::Vec3d& world) const { return DirToCam(world - position); }

cv::Vec3d Camera::DirToCam(const cv::Vec3d& d) const {
  const double c = std::cos(pitch_rad), s = std::sin(pitch_rad);
  return {d[0], -c * d[1] + s * d[2], -s * d[1] - c * d[2]};
}

double IntersectCapsule(const cv::Vec3d& o, const cv::Vec3d& d, const Capsule& c) {
  // The cylinder's body first, then the nearer end sphere (Quilez's formulation).
  const cv::Vec3d ba = c.b - c.a;
  const cv::Vec3d oa = o - c.a;
  const double baba = Dot(ba, ba), bard = Dot(ba, d), baoa = Dot(ba, oa);
  const double rdoa = Dot(d, oa), oaoa = Dot(oa, oa);
  const double qa = baba - bard * bard;
  const double qb = baba * rdoa - baoa * bard;
  const double qc = baba * oaoa - baoa * baoa - c.r * c.r * baba;
  const double h = qb * qb - qa * qc;
  if (h < 0) return -1;
  if (qa > 1e-12) {
    const double t = (-qb - std::sqrt(h)) / qa;
    const double y = baoa + t * bard;
    if (y > 0 && y < baba) return t > 0 ? t : -1;
  }
  const double y = baoa + ((qa > 1e-12) ? (-qb - std::sqrt(h)) / qa : 0) * bard;
  const cv::Vec3d oc = (y <= 0) ? oa : cv::Vec3d(o - c.b);
  const double b2 = Dot(d, oc), c2 = Dot(oc, oc) - c.r * c.r;
  const double h2 = b2 * b2 - c2;
  if (h2 <= 0) return -1;
  const double t = -b2 - std::sqrt(h2);
  return t > 0 ? t : -1;
}

cv::Vec3d CapsuleNormal(const Capsule& c, const cv::Vec3d& p) {
  const cv::Vec3d ba = c.b - c.a;
  const double baba = Dot(ba, ba);
  const double h = baba > 0 ? std::clamp(Dot(p - c.a, ba) / baba, 0.0, 1.0) : 0.0;
  return Unit(p - (c.a + h * ba));
}

double SegmentDistance(const cv::Vec3d& p0, const cv::Vec3d& p1, const cv::Vec3d& q0,
                       const cv::Vec3d& q1) {
  const cv::Vec3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = Dot(d1, d1), e = Dot(d2, d2), f = Dot(d2, r);
  double s = 0, t = 0;
  if (a <= 1e-12 && e <= 1e-12) return Len(r);
  if (a <= 1e-12) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = Dot(d1, r);
    if (e <= 1e-12) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = Dot(d1, d2), denom = a * e - b * b;
      s = denom > 1e-12 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return Len((p0 + s * d1) - (q0 + t * d2));
}

cv::Rect CapsuleBox(const Camera& cam, const Capsule& c, cv::Size size) {
  // The corners of the capsule's axis-aligned bounding box, projected.
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(c.a[k], c.b[k]) - c.r;
    hi[k] = std::max(c.a[k], c.b[k]) + c.r;
  }
  if (lo[2] <= 0.05) return {};
  double u0 = 1e18, v0 = 1e18, u1 = -1e18, v1 = -1e18;
  for (int i = 0; i < 8; ++i) {
    const cv::Point2d q =
        cam.Project({(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]});
    u0 = std::min(u0, q.x);
    u1 = std::max(u1, q.x);
    v0 = std::min(v0, q.y);
    v1 = std::max(v1, q.y);
  }
  const int x0 = std::max(0, static_cast<int>(std::floor(u0)) - 1);
  const int y0 = std::max(0, static_cast<int>(std::floor(v0)) - 1);
  const int x1 = std::min(size.width, static_cast<int>(std::ceil(u1)) + 2);
  const int y1 = std::min(size.height, static_cast<int>(std::ceil(v1)) + 2);
  if (x1 <= x0 || y1 <= y0) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace armmimic::synth::capsule
