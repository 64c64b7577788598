// The person of a random arm scene: body, head and the moving arm, painted from PersonModel.
#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "random_scene_model.h"

namespace armmimic::synth::random_scene {
namespace {

// Limb radii of the reference figure, units: upper arm at shoulder and elbow, forearm at elbow
// and wrist, hand at wrist and tip.
constexpr double kUpperR0 = 7.5, kUpperR1 = 5.8, kForeR0 = 5.6, kForeR1 = 4.3;
constexpr double kHandR0 = 4.6, kHandR1 = 3.6;

cv::Point2d Lerp(cv::Point2d a, cv::Point2d b, double t) { return a + (b - a) * t; }

// One arm from shoulder to hand tip: the sleeve over the first `cover` of the upper arm (the
// whole arm with long sleeves), skin below it.
void PaintArm(Layer* layer, const PersonModel& m, const PersonTextures& tex, const ArmJoints& j,
              const cv::Vec3f& sleeve) {
  const double ru0 = m.R(kUpperR0), ru1 = m.R(kUpperR1);
  const double rf0 = m.R(kForeR0), rf1 = m.R(kForeR1);
  if (m.sleeve_cover >= 1) {
    PaintCapsule(layer, j.shoulder, j.elbow, ru0, ru1, sleeve, &tex.fabric);
    PaintCapsule(layer, j.elbow, j.wrist, rf0, rf1, sleeve, &tex.fabric);
    // A darker cuff just above the wrist.
    const double len = std::max(1.0, cv::norm(j.elbow - j.wrist));
    const cv::Point2d cuff = j.wrist + (j.elbow - j.wrist) * (2.0 * m.s / len);
    PaintCapsule(layer, cuff, j.wrist, rf1 * 1.05, rf1 * 1.02, sleeve * 0.8f, &tex.fabric);
  } else {
    // Bare arm first, then the short sleeve over its top part (a little wider than the arm).
    PaintCapsule(layer, j.shoulder, j.elbow, ru0 * 0.92, ru1 * 0.92, m.skin, &tex.skin);
    PaintCapsule(layer, j.elbow, j.wrist, rf0 * 0.9, rf1 * 0.9, m.skin, &tex.skin);
    // The sleeve's rounded end reaches the hem (a share `sleeve_cover` of the upper arm).
    const double c = m.sleeve_cover;
    const double r_hem = (ru0 + (ru1 - ru0) * c) * 1.12;
    const double upper_len = std::max(1.0, cv::norm(j.elbow - j.shoulder));
    const double end = std::max(0.0, c * upper_len - r_hem) / upper_len;
    PaintCapsule(layer, j.shoulder, Lerp(j.shoulder, j.elbow, end), ru0 * 1.08, r_hem, sleeve,
                 &tex.fabric);
  }
  PaintCapsule(layer, j.wrist, j.tip, m.R(kHandR0), m.R(kHandR1), m.skin, &tex.skin);
}

}  // namespace

ArmJoints JointsOf(const PersonModel& m, const Pose& pose, cv::Point2d offset) {
  ArmJoints j;
  j.shoulder = m.Shoulder() + offset;
  j.elbow = j.shoulder + DirectionVector(pose.upper_deg) * (m.upper * m.s);
  const double fore = pose.upper_deg + pose.bend_deg;
  j.wrist = j.elbow + DirectionVector(fore) * (m.fore * m.s);
  j.tip = j.wrist + DirectionVector(fore) * (m.hand * m.s);
  return j;
}

void PaintStaticBody(Layer* layer, const PersonModel& m, const PersonTextures& tex) {
  const double w = m.w, t = m.torso_len;
  const double waist = 84 * t;
  // Legs (cut by the frame's bottom edge or ending in it), then the torso over them.
  for (double side : {-1.0, 1.0}) {
    PaintCapsule(layer, m.P(side * 0.4 * w, waist), m.P(side * 0.47 * w, waist + 120),
                 0.4 * w * m.s, 0.37 * w * m.s, m.trousers, &tex.fabric);
  }
  const std::vector<cv::Point2d> torso{
      m.P(-(w - 10), -15),   m.P(w - 10, -15),      m.P(w - 1, -11),   m.P(w + 3, -3),
      m.P(w + 1, 20 * t),    m.P(w - 5, 50 * t),    m.P(w - 6, waist), m.P(-(w - 6), waist),
      m.P(-(w - 5), 50 * t), m.P(-(w + 1), 20 * t), m.P(-(w + 3), -3), m.P(-(w - 1), -11)};
  PaintBody(layer, torso, m.cx, (w + 4) * m.s, m.shirt, &tex.fabric);
  if (m.has_belt) {
    PaintBody(layer,
              {m.P(-(w - 5.5), waist - 6), m.P(w - 5.5, waist - 6), m.P(w - 5.5, waist + 2),
               m.P(-(w - 5.5), waist + 2)},
              m.cx, (w - 4) * m.s, m.belt, nullptr);
  }
  // Neck from under the head to the collar, then the collar over its base.
  PaintCapsule(layer, m.P(0, -m.head_dy + 0.6 * m.head_ry), m.P(0, -10), m.neck_r * m.s,
               m.neck_r * 1.08 * m.s, m.skin, &tex.skin);
  PaintEllipse(layer, m.P(0, -12), (m.neck_r + 3) * m.s, 3.5 * m.s, 0, m.shirt * 0.9f, &tex.fabric);
  for (double side : {-1.0, 1.0}) {
    PaintEllipse(layer, m.P(side * (w - 3), -1), 9 * m.limb * m.s, 8.5 * m.limb * m.s, 0, m.shirt,
                 &tex.fabric);
  }
  // The other arm, hanging beside the body.
  ArmJoints other;
  other.shoulder = m.P(-w, 0);
  other.elbow = m.P(-w - 2, m.upper);
  other.wrist = m.P(-w - 3, m.upper + m.fore);
  other.tip = m.P(-w - 3.5, m.upper + m.fore + m.hand);
  PaintArm(layer, m, tex, other, m.sleeve);
}

void PaintHead(Layer* layer, const PersonModel& m, const PersonTextures& tex, cv::Point2d offset,
               double tilt_deg) {
  const cv::Point2d h = m.HeadCentre() + offset;
  const double th = tilt_deg * CV_PI / 180.0;
  const double kx = m.head_rx / 13.5, ky = m.head_ry / 16.5;
  auto rot = [&](double u, double v) {
    u *= kx, v *= ky;
    return h +
           cv::Point2d(u * std::cos(th) - v * std::sin(th), u * std::sin(th) + v * std::cos(th)) *
               m.s;
  };
  PaintEllipse(layer, h, m.head_rx * m.s, m.head_ry * m.s, tilt_deg, m.skin, &tex.skin);
  for (double side : {-1.0, 1.0}) {
    PaintEllipse(layer, rot(side * 13.5, 1), 2.2 * kx * m.s, 3.5 * ky * m.s, tilt_deg,
                 m.skin * 0.92f, nullptr);
  }
  // Hair: a cap over the top of the head, its fringe line tilting with the head.
  PaintEllipse(layer, rot(0, -5), (m.head_rx + 1.5) * m.s, 13.5 * ky * m.s, tilt_deg, m.hair,
               &tex.fabric, {}, rot(0, -5).y + 2 * m.s);
  for (double side : {-1.0, 1.0}) {
    PaintEllipse(layer, rot(side * 5, 0), 1.7 * kx * m.s, 1.1 * ky * m.s, tilt_deg, {45, 40, 40},
                 nullptr);
  }
  PaintEllipse(layer, rot(0, 9.5), 4 * kx * m.s, 1.2 * ky * m.s, tilt_deg, m.skin * 0.75f, nullptr);
}

void PaintMovingArm(Layer* layer, const PersonModel& m, const PersonTextures& tex,
                    const ArmJoints& j) {
  PaintArm(layer, m, tex, j, m.sleeve);
}

}  // namespace armmimic::synth::random_scene
