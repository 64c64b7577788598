// The capsule scenes' motion: keyframe poses in 3-D (ordinary reaches, the hand over the head,
// beside the head, across the torso, the straight arm turned out of the image plane), solved
// with two-link inverse kinematics where the class names a wrist position, and joined by
// minimum-jerk moves that keep the arm clear of the body.
#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "capsule_model.h"

namespace armmimic::synth::capsule {
namespace {

enum class PoseClass { kReach, kOverHead, kBesideHead, kAcrossTorso, kYaw };

// The moving arm keeps clear of every body capsule (the upper arm's first third starts inside
// the shoulders), and the elbow bends at most 150 degrees.
bool Clear(const Person& p, double side, const std::vector<BodyPiece>& body, const ArmPose& pose) {
  const ArmPoints a = ArmInBody(p, pose, side);
  const cv::Vec3d u = (a.elbow - a.shoulder) * (1.0 / p.upper);
  const cv::Vec3d f = (a.wrist - a.elbow) * (1.0 / p.fore);
  if (Dot(u, f) < std::cos(RadFromDeg(150))) return false;
  const cv::Vec3d upper_from = a.shoulder + u * (p.upper * 0.35);
  for (const BodyPiece& piece : body) {
    const double margin = 0.006;
    if (!piece.at_shoulders &&
        SegmentDistance(upper_from, a.elbow, piece.a, piece.b) < p.r_upper + piece.r + margin) {
      return false;
    }
    if (SegmentDistance(a.elbow, a.wrist, piece.a, piece.b) < p.r_fore + piece.r + margin) {
      return false;
    }
    if (SegmentDistance(a.wrist, a.tip, piece.a, piece.b) < p.r_hand + piece.r + margin) {
      return false;
    }
  }
  return true;
}

// The pose that puts the wrist at `target` with the elbow bent towards `pole` (body frame).
ArmPose SolveArm(const Person& p, double side, const cv::Vec3d& target, const cv::Vec3d& pole) {
  const cv::Vec3d s(side * p.half_width, p.shoulder_y, 0);
  const cv::Vec3d d = target - s;
  double dist = Len(d);
  const double reach = p.upper + p.fore - 1e-3, inner = std::abs(p.upper - p.fore) + 0.05;
  dist = std::clamp(dist, inner, reach);
  const cv::Vec3d e = Unit(d);
  const double ca = (p.upper * p.upper + dist * dist - p.fore * p.fore) / (2 * p.upper * dist);
  const double sa = std::sqrt(std::max(0.0, 1 - ca * ca));
  const cv::Vec3d perp = Unit(pole - e * Dot(pole, e));
  const cv::Vec3d elbow = s + p.upper * (ca * e + sa * perp);
  const cv::Vec3d wrist = s + dist * e;
  return PoseFromDirections(Unit(elbow - s), Unit(wrist - elbow), side);
}

// A pose in the class's ranges whose hand lands where the class puts it: over the head (the
// wrist above its top, the forearm or the hand in front of the hair) or beside it.
ArmPose DrawHeadPose(const Person& p, double side, bool over, Rng* rng) {
  const double hc = p.HeadCentreY(), hr = p.head_r;
  const double top = hc + hr * (p.hair_style == "bun" ? 1.4 : 1.08);
  ArmPose pose;
  for (int i = 0; i < 400; ++i) {
    pose.upper = over ? rng->Uniform(85, 150) : rng->Uniform(20, 115);
    pose.bend = over ? rng->Uniform(20, 130) : rng->Uniform(30, 150);
    pose.upper_tilt = rng->Uniform(-5, 20);
    pose.fore_tilt = pose.upper_tilt + rng->Uniform(-10, 15);
    const ArmPoints a = ArmInBody(p, pose, side);
    const double wx = a.wrist[0] * side, tx = a.tip[0] * side;
    if (over && a.wrist[1] > top + 0.02 && std::min(std::abs(wx), std::abs(tx)) < 1.1 * hr) {
      return pose;
    }
    if (!over && std::abs(a.wrist[1] - hc) < 1.1 * hr && wx > 1.2 * hr && wx < 2.6 * hr) {
      return pose;
    }
  }
  return pose;
}

ArmPose DrawPose(const Person& p, double side, const MotionSpec& spec, PoseClass kind, Rng* rng) {
  switch (kind) {
    case PoseClass::kOverHead:
      return DrawHeadPose(p, side, true, rng);
    case PoseClass::kBesideHead:
      return DrawHeadPose(p, side, false, rng);
    case PoseClass::kAcrossTorso: {
      const cv::Vec3d target(side * rng->Uniform(-0.85, 0.25) * p.half_width,
                             p.shoulder_y - rng->Uniform(0.12, 0.42),
                             p.r_torso + p.r_fore + rng->Uniform(0.02, 0.1));
      return SolveArm(p, side, target, {side, -0.6, rng->Uniform(0.2, 0.6)});
    }
    case PoseClass::kYaw: {
      ArmPose pose;
      pose.upper = rng->Uniform(-12, 12);
      pose.upper_tilt =
          rng->Sign() * rng->Uniform(std::min(20.0, spec.max_yaw_deg), spec.max_yaw_deg);
      pose.bend = rng->Uniform(-4, 4);
      pose.fore_tilt = pose.upper_tilt + rng->Uniform(-3, 3);
      return pose;
    }
    case PoseClass::kReach:
      break;
  }
  ArmPose pose;
  pose.upper = rng->Uniform(-85, spec.upper_max_deg);
  pose.bend = rng->Chance(0.7) ? rng->Uniform(0, 140) : rng->Uniform(-110, 0);
  pose.upper_tilt = rng->Uniform(-spec.max_tilt_deg, spec.max_tilt_deg);
  pose.fore_tilt = pose.upper_tilt + rng->Uniform(-spec.max_tilt_deg, spec.max_tilt_deg);
  return pose;
}

double MinJerk(double t) { return t * t * t * (10 + t * (-15 + 6 * t)); }

ArmPose Lerp(const ArmPose& a, const ArmPose& b, double s) {
  return {a.upper + (b.upper - a.upper) * s, a.upper_tilt + (b.upper_tilt - a.upper_tilt) * s,
          a.bend + (b.bend - a.bend) * s, a.fore_tilt + (b.fore_tilt - a.fore_tilt) * s};
}

double MoveSize(const ArmPose& a, const ArmPose& b) {
  const double du = b.upper - a.upper, db = b.bend - a.bend;
  return std::max({std::abs(du), std::abs(du + db), std::abs(db) * 0.7,
                   std::abs(b.upper_tilt - a.upper_tilt), std::abs(b.fore_tilt - a.fore_tilt)});
}

}  // namespace

MotionPlan PlanMotion(const Person& person, double side, const MotionSpec& spec,
                      const std::function<bool(const ArmPoints&, bool)>& in_frame, Rng* rng) {
  const std::vector<BodyPiece> body = BodyPieces(person, side);
  auto valid = [&](const ArmPose& pose, bool keyframe) {
    return Clear(person, side, body, pose) && in_frame(ArmInBody(person, pose, side), keyframe);
  };
  // The scene's classes first, in random order, then any class now and then.
  std::vector<PoseClass> todo;
  if (spec.over_head) todo.push_back(PoseClass::kOverHead);
  if (spec.beside_head) todo.push_back(PoseClass::kBesideHead);
  if (spec.across_torso) todo.push_back(PoseClass::kAcrossTorso);
  if (spec.yaw) todo.push_back(PoseClass::kYaw);
  for (size_t i = todo.size(); i > 1; --i)
    std::swap(todo[i - 1], todo[rng->Int(0, static_cast<int>(i) - 1)]);

  MotionPlan plan;
  ArmPose current = HangingPose(person);
  size_t next_class = 0;
  while (static_cast<int>(plan.poses.size()) < spec.frames) {
    PoseClass kind = PoseClass::kReach;
    if (next_class < todo.size() && (rng->Chance(0.6) || plan.poses.empty())) {
      kind = todo[next_class];
    } else if (next_class >= todo.size() && !todo.empty() && rng->Chance(0.35)) {
      kind = todo[rng->Int(0, static_cast<int>(todo.size()) - 1)];
    }
    std::vector<ArmPose> move;
    bool found = false;
    for (int attempt = 0; attempt < 60 && !found; ++attempt) {
      const PoseClass k = attempt < 40 ? kind : PoseClass::kReach;
      ArmPose target = DrawPose(person, side, spec, k, rng);
      target.upper = current.upper + Wrap180(target.upper - current.upper);
      if (!valid(target, true)) continue;
      const double speed = spec.speed_limit_deg * rng->Uniform(0.4, 1.0);
      const int n =
          std::max(6, static_cast<int>(std::ceil(1.875 * MoveSize(current, target) / speed)));
      move.clear();
      found = true;
      for (int i = 1; i <= n && found; ++i) {
        move.push_back(Lerp(current, target, MinJerk(static_cast<double>(i) / n)));
        found = valid(move.back(), false);
      }
      if (found) {
        if (k == kind && next_class < todo.size() && kind == todo[next_class]) ++next_class;
        plan.over_head |= k == PoseClass::kOverHead;
        plan.beside_head |= k == PoseClass::kBesideHead;
        plan.across_torso |= k == PoseClass::kAcrossTorso;
        plan.yaw |= k == PoseClass::kYaw;
      }
    }
    if (!found) {
      // Out to the side in front of the body: reachable from anywhere without crossing it.
      ArmPose via;
      via.upper = current.upper + Wrap180(-current.upper);
      via.upper_tilt = 25;
      via.fore_tilt = 25;
      move.clear();
      for (int i = 1; i <= 30; ++i) move.push_back(Lerp(current, via, MinJerk(i / 30.0)));
    }
    for (const ArmPose& pose : move) {
      plan.raised |= pose.upper > 0;
      plan.poses.push_back(pose);
    }
    current = move.back();
    if (rng->Chance(0.3)) {
      const int hold = static_cast<int>(rng->Uniform(0.2, 0.8) * spec.fps);
      for (int i = 0; i < hold; ++i) plan.poses.push_back(current);
    }
  }
  plan.poses.resize(static_cast<size_t>(spec.frames));
  return plan;
}

}  // namespace armmimic::synth::capsule
