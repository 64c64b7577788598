// The capsule person: its capsules in a pose, and their colours under the light.
#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "capsule_model.h"

namespace armmimic::synth::capsule {
namespace {

cv::Vec3d RotY(const cv::Vec3d& p, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {c * p[0] + s * p[2], p[1], -s * p[0] + c * p[2]};
}

// The head turns about the top of the neck: nod about the body's x axis, tilt about its z axis.
cv::Vec3d HeadPoint(const Person& p, const BodyPlacement& b, const cv::Vec3d& q) {
  const cv::Vec3d pivot(0, p.shoulder_y + p.r_shoulder + p.neck * 0.5, 0);
  cv::Vec3d d = q - pivot;
  const double cn = std::cos(b.nod_rad), sn = std::sin(b.nod_rad);
  d = {d[0], cn * d[1] - sn * d[2], sn * d[1] + cn * d[2]};
  const double ct = std::cos(b.tilt_rad), st = std::sin(b.tilt_rad);
  d = {ct * d[0] - st * d[1], st * d[0] + ct * d[1], d[2]};
  return pivot + d;
}

double Frac(double x) { return x - std::floor(x); }

// 1 where the pattern's second colour shows at surface coordinates (u, v), metres.
float PatternAt(const std::string& kind, double u, double v, double period) {
  if (kind == "hstripes") return Frac(v / period) < 0.45 ? 1.f : 0.f;
  if (kind == "vstripes") return Frac(u / period) < 0.4 ? 1.f : 0.f;
  if (kind == "checks") return ((Frac(u / period) < 0.5) != (Frac(v / period) < 0.5)) ? 1.f : 0.f;
  if (kind == "dots") {
    const double du = Frac(u / period) - 0.5,
                 dv = Frac(v / period + 0.5 * std::floor(u / period)) - 0.5;
    return du * du + dv * dv < 0.09 ? 1.f : 0.f;
  }
  return 0.f;
}

cv::Vec3f Cloth(const Person& p, const cv::Vec3f& base, double u, double v) {
  const float k = PatternAt(p.pattern, u, v, p.pattern_period);
  return base * (1 - k) + p.shirt2 * k;
}

Capsule Make(const cv::Vec3d& a, const cv::Vec3d& b, double r, CapsulePart part, Material m) {
  Capsule c;
  c.a = a;
  c.b = b;
  c.r = r;
  c.part = part;
  c.material = m;
  return c;
}

}  // namespace

cv::Vec3d BodyToWorld(const BodyPlacement& b, const cv::Vec3d& p) {
  return b.origin + RotY(p, b.yaw_rad) + b.sway;
}

void PoseDirections(const ArmPose& pose, double side, cv::Vec3d* u, cv::Vec3d* f) {
  const double au = RadFromDeg(pose.upper), tu = RadFromDeg(pose.upper_tilt);
  const double af = RadFromDeg(pose.upper + pose.bend), tf = RadFromDeg(pose.fore_tilt);
  *u = {side * std::cos(au) * std::cos(tu), std::sin(au) * std::cos(tu), std::sin(tu)};
  *f = {side * std::cos(af) * std::cos(tf), std::sin(af) * std::cos(tf), std::sin(tf)};
}

ArmPose PoseFromDirections(const cv::Vec3d& u, const cv::Vec3d& f, double side) {
  ArmPose pose;
  pose.upper = DegFromRad(std::atan2(u[1], side * u[0]));
  pose.upper_tilt = DegFromRad(std::asin(std::clamp(u[2], -1.0, 1.0)));
  const double af = DegFromRad(std::atan2(f[1], side * f[0]));
  pose.bend = Wrap180(af - pose.upper);
  pose.fore_tilt = DegFromRad(std::asin(std::clamp(f[2], -1.0, 1.0)));
  return pose;
}

ArmPoints ArmInBody(const Person& p, const ArmPose& pose, double side) {
  cv::Vec3d u, f;
  PoseDirections(pose, side, &u, &f);
  ArmPoints a;
  a.shoulder = {side * p.half_width, p.shoulder_y, 0};
  a.elbow = a.shoulder + p.upper * u;
  a.wrist = a.elbow + p.fore * f;
  a.tip = a.wrist + p.hand * f;
  return a;
}

ArmPose HangingPose(const Person& p) {
  ArmPose pose;
  pose.upper = -90 + p.hang_out_deg;
  pose.bend = -2;
  pose.fore_tilt = 6;
  return pose;
}

namespace {

double TorsoSideX(const Person& p) {
  return std::max(0.0, p.half_width - p.r_upper * 1.1 - p.r_torso * 0.85);
}

// The hand's capsule ends one radius short of the finger tips.
cv::Vec3d HandEnd(const Person& p, const ArmPoints& arm) {
  return arm.wrist + (arm.tip - arm.wrist) * ((p.hand - p.r_hand) / p.hand);
}

}  // namespace

std::vector<BodyPiece> BodyPieces(const Person& p, double side) {
  const double xs = TorsoSideX(p), r_side = p.r_torso * 0.85;
  const double top = p.shoulder_y - r_side * 0.4;
  using M = Material;
  std::vector<BodyPiece> out = {
      {{0, p.hip_y, 0}, {0, top, 0}, p.r_torso, M::kShirt},
      {{-xs, p.hip_y + 0.05, 0}, {-xs, top, 0}, r_side, M::kShirt},
      {{xs, p.hip_y + 0.05, 0}, {xs, top, 0}, r_side, M::kShirt},
      {{-p.half_width, p.shoulder_y, 0},
       {p.half_width, p.shoulder_y, 0},
       p.r_shoulder,
       M::kShirt,
       true},
      {{-xs, p.hip_y, 0}, {xs, p.hip_y, 0}, r_side, M::kTrousers},
      {{-0.1, p.hip_y, 0}, {-0.11, 0.06, 0}, p.r_leg, M::kTrousers},
      {{0.1, p.hip_y, 0}, {0.11, 0.06, 0}, p.r_leg, M::kTrousers},
      {{0, p.shoulder_y, -0.01},
       {0, p.shoulder_y + p.r_shoulder + p.neck, -0.01},
       p.r_neck,
       M::kSkin,
       true},
  };
  const cv::Vec3d hc(0, p.HeadCentreY(), 0);
  out.push_back(
      {hc - cv::Vec3d(0, 0.025, 0), hc + cv::Vec3d(0, 0.025, 0), p.head_r, M::kHead, false, true});
  if (p.hair_style != "bald") {
    const cv::Vec3d back = hc + cv::Vec3d(0, 0.012, -0.02);
    out.push_back({back, back, p.head_r * 1.05, M::kHair, false, true});
  }
  if (p.hair_style == "long") {
    out.push_back({hc + cv::Vec3d(0, 0, -0.05),
                   {0, p.shoulder_y - 0.12, -0.07},
                   p.head_r * 0.95,
                   M::kHair,
                   false,
                   true});
  } else if (p.hair_style == "bun") {
    const cv::Vec3d bun = hc + cv::Vec3d(0, p.head_r * 0.95, -0.04);
    out.push_back({bun, bun, p.head_r * 0.45, M::kHair, false, true});
  }
  const ArmPoints other = ArmInBody(p, HangingPose(p), -side);
  out.push_back({other.shoulder, other.elbow, p.r_upper, M::kArm, true});
  out.push_back({other.elbow, other.wrist, p.r_fore, M::kArm, false, false, p.upper});
  out.push_back({other.wrist, HandEnd(p, other), p.r_hand, M::kSkin});
  return out;
}

std::vector<Capsule> BuildPerson(const Person& p, const BodyPlacement& b, const ArmPose& pose,
                                 const Camera& cam, cv::Size size) {
  std::vector<Capsule> out;
  auto to_cam = [&](const cv::Vec3d& q) { return cam.ToCam(BodyToWorld(b, q)); };
  const cv::Vec3d o = to_cam({0, 0, 0});
  const cv::Vec3d ex = Unit(to_cam({1, 0, 0}) - o), ey = Unit(to_cam({0, 1, 0}) - o);
  const cv::Vec3d ho = to_cam(HeadPoint(p, b, {0, 0, 0}));
  const cv::Vec3d hx = Unit(to_cam(HeadPoint(p, b, {1, 0, 0})) - ho);
  const cv::Vec3d hy = Unit(to_cam(HeadPoint(p, b, {0, 1, 0})) - ho);
  const cv::Vec3d hc = to_cam(HeadPoint(p, b, {0, p.HeadCentreY(), 0}));
  auto add = [&](const BodyPiece& piece, CapsulePart part) {
    const auto at = [&](const cv::Vec3d& q) { return to_cam(piece.head ? HeadPoint(p, b, q) : q); };
    Capsule cap = Make(at(piece.a), at(piece.b), piece.r, part, piece.material);
    // The face's axes turn with the head; the shirt's pattern stays with the body.
    cap.ex = piece.head ? hx : ex;
    cap.ey = piece.head ? hy : ey;
    cap.origin = piece.head ? hc : o;
    cap.arm_s0 = piece.arm_s0;
    cap.box = CapsuleBox(cam, cap, size);
    if (!cap.box.empty()) out.push_back(cap);
  };
  for (const BodyPiece& piece : BodyPieces(p, b.side)) add(piece, kPartBody);
  const ArmPoints arm = ArmInBody(p, pose, b.side);
  add({arm.shoulder, arm.elbow, p.r_upper, Material::kArm}, kPartUpperArm);
  add({arm.elbow, arm.wrist, p.r_fore, Material::kArm, false, false, p.upper}, kPartForearm);
  add({arm.wrist, HandEnd(p, arm), p.r_hand, Material::kSkin}, kPartHand);
  return out;
}

cv::Vec3f Shade(const Person& p, const Capsule& c, const cv::Vec3d& hit, const cv::Vec3d& light_cam,
                const Light& light) {
  const cv::Vec3d n = CapsuleNormal(c, hit);
  cv::Vec3f albedo = p.skin;
  bool glossy = true;
  switch (c.material) {
    case Material::kShirt:
    case Material::kTrousers: {
      const cv::Vec3d q = hit - c.origin;
      const double u = Dot(q, c.ex), v = Dot(q, c.ey);
      glossy = false;
      if (c.material == Material::kTrousers || v < p.hip_y + 0.03) {
        albedo = p.trousers;
      } else if (p.sleeveless && std::abs(u) > p.half_width - p.r_upper * 0.3) {
        albedo = p.skin;  // the bare shoulder
        glossy = true;
      } else {
        albedo = Cloth(p, p.shirt, u, v);
      }
      break;
    }
    case Material::kArm: {
      const cv::Vec3d axis = c.b - c.a;
      const double len = Len(axis);
      const cv::Vec3d w = len > 0 ? cv::Vec3d(axis * (1.0 / len)) : cv::Vec3d(0, 1, 0);
      const double s = c.arm_s0 + std::clamp(Dot(hit - c.a, w), 0.0, len);
      const double cover = p.sleeve_cover * (p.upper + p.fore);
      if (s < cover) {
        cv::Vec3d r1 = c.ey - w * Dot(c.ey, w);
        if (Len(r1) < 1e-6) r1 = c.ex - w * Dot(c.ex, w);
        r1 = Unit(r1);
        const cv::Vec3d r2 = w.cross(r1);
        const double around = std::atan2(Dot(n, r2), Dot(n, r1)) * c.r;
        albedo = (p.sleeve == p.shirt) ? Cloth(p, p.sleeve, around, -s) : p.sleeve;
        if (cover - s < 0.025 && p.sleeve_cover > 0.9) albedo *= 0.8f;  // the cuff
        glossy = false;
      }
      break;
    }
    case Material::kHair:
      albedo = p.hair;
      glossy = false;
      break;
    case Material::kHead: {
      // Head-local direction of the normal: the face looks along the head's forward axis.
      const cv::Vec3d fwd = c.ex.cross(c.ey);  // towards the camera when the body faces it
      const double nx = Dot(n, c.ex), ny = Dot(n, c.ey), nz = Dot(n, fwd);
      const bool bald = p.hair_style == "bald";
      if (!bald && (ny > 0.5 || (nz < -0.15 && ny > -0.5) || (std::abs(nx) > 0.8 && ny > 0.05))) {
        albedo = p.hair;
        glossy = false;
      } else if (nz > 0.8 && std::abs(std::abs(nx) - 0.33) < 0.09 && std::abs(ny - 0.12) < 0.07) {
        albedo = cv::Vec3f(40, 35, 35);  // eyes
      } else if (nz > 0.8 && std::abs(nx) < 0.2 && std::abs(ny + 0.42) < 0.05) {
        albedo = p.skin * 0.6f + cv::Vec3f(20, 20, 60) * 0.4f;  // mouth
      }
      break;
    }
    case Material::kSkin:
      break;
  }
  const cv::Vec3d l = Unit(light_cam - hit);
  const cv::Vec3d v = Unit(-hit);
  const double diffuse = std::max(0.0, Dot(n, l));
  const double fill = 0.2 * std::max(0.0, Dot(n, v));
  const float k = static_cast<float>(light.ambient + fill);
  const float d = static_cast<float>(light.key * diffuse);
  cv::Vec3f out;
  for (int ch = 0; ch < 3; ++ch) out[ch] = albedo[ch] * (k + d * light.tint[ch]);
  if (glossy) {
    const double spec = std::pow(std::max(0.0, Dot(n, Unit(l + v))), 30.0) * 28.0;
    out += cv::Vec3f(1, 1, 1) * static_cast<float>(spec);
  }
  return out;
}

}  // namespace armmimic::synth::capsule
