// What a capsule scene's seed and tier draw: the person's proportions and clothing, the room,
// the camera and where the person stands in its view, the light and the motion's classes.
// docs/synth.md ("Capsule scenes") lists the ranges.
// Length: DrawScene is one list of draws in a fixed order (the order is part of what a seed
// means), kept together so the ranges can be read against the documentation.
#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "capsule_model.h"
#include "random_scene_model.h"

namespace armmimic::synth::capsule {

// The colour arithmetic is the painted generators' (random_scene::Hsv): a conversion, not a
// part of either scene's structure.
cv::Vec3f HsvColour(double hue, double sat, double val) { return random_scene::Hsv(hue, sat, val); }

double ColourDistance(const cv::Vec3f& a, const cv::Vec3f& b) {
  return random_scene::ColourDistance(a, b);
}

namespace {

template <typename T>
const T& Pick(const std::vector<T>& items, Rng* rng) {
  return items[static_cast<size_t>(rng->Int(0, static_cast<int>(items.size()) - 1))];
}

cv::Vec3f Jitter(const cv::Vec3f& c, double amount, Rng* rng) {
  cv::Vec3f out;
  for (int k = 0; k < 3; ++k) {
    out[k] = static_cast<float>(std::clamp(c[k] * (1 + rng->Uniform(-amount, amount)), 0.0, 255.0));
  }
  return out;
}

void DrawPerson(bool hard, Person* p, CapsuleSceneParams* q, Rng* rng) {
  p->height = rng->Uniform(1.5, 1.95);
  p->shoulder_y = p->height * rng->Uniform(0.80, 0.83);
  p->hip_y = p->height * rng->Uniform(0.50, 0.55);
  p->half_width = p->height * (hard ? rng->Uniform(0.085, 0.135) : rng->Uniform(0.095, 0.125));
  p->upper = p->height * rng->Uniform(0.16, 0.195);
  p->fore = p->height * rng->Uniform(0.14, 0.168);
  p->hand = p->height * rng->Uniform(0.095, 0.11);
  p->r_upper = hard ? rng->Uniform(0.036, 0.066) : rng->Uniform(0.042, 0.06);
  p->r_fore = p->r_upper * rng->Uniform(0.72, 0.88);
  p->r_hand = p->r_fore * rng->Uniform(0.75, 0.95);
  p->r_shoulder = p->r_upper * rng->Uniform(1.0, 1.2);
  p->r_torso = std::min(rng->Uniform(0.09, 0.13), p->half_width - 1.15 * p->r_upper);
  p->r_neck = rng->Uniform(0.04, 0.055);
  p->r_leg = rng->Uniform(0.065, 0.09);
  p->head_r = rng->Uniform(0.085, 0.11);
  p->neck = rng->Uniform(0.03, 0.09);
  p->hang_out_deg = rng->Uniform(3, 10);
  // Skin from light to dark, hair from a palette.
  q->skin_tone = rng->Uniform(0, 1);
  const cv::Vec3f light_skin(165, 190, 235), dark_skin(45, 62, 98);
  p->skin = Jitter(light_skin * (1 - q->skin_tone) + dark_skin * q->skin_tone, 0.06, rng);
  const std::vector<cv::Vec3f> hair = {{25, 25, 30},    {30, 45, 70},  {45, 75, 120},
                                       {110, 175, 210}, {40, 80, 160}, {150, 150, 155}};
  p->hair = Jitter(Pick(hair, rng), 0.1, rng);
  const double style = rng->Uniform(0, 1);
  p->hair_style = style < 0.45 ? "short" : style < 0.75 ? "long" : style < 0.9 ? "bun" : "bald";
  // Clothing.
  const double sl = rng->Uniform(0, 1);
  q->sleeves = sl < (hard ? 0.35 : 0.25) ? "sleeveless"
               : sl < (hard ? 0.7 : 0.6) ? "short"
                                         : "long";
  p->sleeveless = q->sleeves == "sleeveless";
  p->sleeve_cover = p->sleeveless           ? 0
                    : q->sleeves == "short" ? rng->Uniform(0.15, 0.45)
                                            : rng->Uniform(0.95, 1.0);
  q->shirt_like_skin = rng->Chance(hard ? 0.4 : 0.25);
  p->shirt = q->shirt_like_skin
                 ? Jitter(p->skin, 0.07, rng)
                 : HsvColour(rng->Uniform(0, 360), rng->Uniform(0.1, 0.8), rng->Uniform(0.25, 0.9));
  p->shirt2 = HsvColour(rng->Uniform(0, 360), rng->Uniform(0.0, 0.7), rng->Uniform(0.2, 0.95));
  p->sleeve = rng->Chance(0.8) ? p->shirt
                               : HsvColour(rng->Uniform(0, 360), rng->Uniform(0.1, 0.7),
                                           rng->Uniform(0.25, 0.85));
  const double pat = rng->Uniform(0, 1);
  const double plain = hard ? 0.4 : 0.55, step = (1 - plain) / 4;
  p->pattern = pat < plain              ? "plain"
               : pat < plain + step     ? "hstripes"
               : pat < plain + 2 * step ? "vstripes"
               : pat < plain + 3 * step ? "checks"
                                        : "dots";
  p->pattern_period = rng->Uniform(0.03, 0.08);
  p->trousers = HsvColour(rng->Uniform(0, 360), rng->Uniform(0.1, 0.6), rng->Uniform(0.15, 0.6));
  q->pattern = p->pattern;
  q->sleeve_cover = p->sleeve_cover;
  q->shirt_skin_distance = ColourDistance(p->shirt, p->skin);
  q->hair = p->hair_style;
  q->height = p->height;
  q->upper = p->upper;
  q->fore = p->fore;
  q->hand = p->hand;
  q->upper_radius = p->r_upper;
  q->fore_radius = p->r_fore;
  q->hand_radius = p->r_hand;
  q->shoulder_half_width = p->half_width;
  q->torso_radius = p->r_torso;
  q->head_radius = p->head_r;
  q->neck = p->neck;
}

void DrawRoom(bool hard, const Person& person, Room* room, CapsuleSceneParams* q, Rng* rng) {
  room->salt = rng->Next();
  const std::vector<std::string> textures = {"paint",     "bricks", "tiles",
                                             "wallpaper", "wood",   "concrete"};
  room->texture = Pick(textures, rng);
  room->texture_strength = hard ? rng->Uniform(1.0, 2.0) : rng->Uniform(0.6, 1.2);
  room->texture_scale = rng->Uniform(0.7, 1.5);
  room->wall = HsvColour(rng->Uniform(0, 360), rng->Uniform(0, hard ? 0.5 : 0.4),
                         rng->Uniform(hard ? 0.3 : 0.4, 0.95));
  // Camouflage: the wall in the moving arm's colour.
  const cv::Vec3f arm = person.sleeve_cover > 0.3 ? person.sleeve : person.skin;
  if (rng->Chance(hard ? 0.3 : 0.12)) room->wall = Jitter(arm, 0.12, rng);
  room->wall2 = room->texture == "bricks" ? Jitter(cv::Vec3f(175, 180, 185), 0.1, rng)
                : room->texture == "tiles"
                    ? room->wall * static_cast<float>(rng->Uniform(0.6, 1.3))
                    : HsvColour(rng->Uniform(0, 360), rng->Uniform(0, 0.5), rng->Uniform(0.3, 0.9));
  room->dado_y = rng->Chance(0.3) ? rng->Uniform(0.8, 1.1) : 0;
  room->dado = HsvColour(rng->Uniform(20, 40), rng->Uniform(0.2, 0.6), rng->Uniform(0.3, 0.8));
  room->floor = HsvColour(rng->Uniform(15, 45), rng->Uniform(0.2, 0.6), rng->Uniform(0.25, 0.7));
  room->floor_kind = rng->Chance(0.6) ? "planks" : "carpet";
  room->ceiling = Jitter(cv::Vec3f(225, 228, 230), 0.05, rng);
  room->ceiling_y = rng->Uniform(2.5, 3.0);
  q->wall_texture = room->texture;
  q->arm_wall_distance = ColourDistance(arm, room->wall);
}

// Objects on the wall around the person at `centre_x`; in hard scenes one behind the arm's
// reach (beside the shoulder on the moving side), sometimes in the arm's colour.
void DrawObjects(bool hard, const Person& p, double centre_x, double side, double half_view,
                 Room* room, Rng* rng) {
  const int n = hard ? rng->Int(2, 4) : rng->Int(1, 3);
  const std::vector<std::string> kinds = {"picture", "door", "shelf", "window", "panel"};
  for (int i = 0; i < n; ++i) {
    WallObject o;
    o.kind = Pick(kinds, rng);
    o.salt = rng->Next();
    o.colour = HsvColour(rng->Uniform(0, 360), rng->Uniform(0.1, 0.8), rng->Uniform(0.3, 0.95));
    o.accent = HsvColour(rng->Uniform(0, 360), rng->Uniform(0.0, 0.6), rng->Uniform(0.1, 0.8));
    double w = rng->Uniform(0.3, 0.8), h = rng->Uniform(0.25, 0.6);
    double y = rng->Uniform(0.9, 1.8);
    if (o.kind == "door") w = 0.85, h = 2.0, y = 0.02;
    if (o.kind == "shelf") w = rng->Uniform(0.6, 1.0), h = rng->Uniform(0.5, 1.0);
    if (o.kind == "window") {
      w = rng->Uniform(0.6, 1.2), h = rng->Uniform(0.6, 1.0);
      o.colour = HsvColour(rng->Uniform(190, 220), rng->Uniform(0.05, 0.3), rng->Uniform(0.8, 1.0));
    }
    double x = centre_x + rng->Uniform(-half_view, half_view) - w / 2;
    if (i == 0 && (hard || rng->Chance(0.5))) {
      // Behind the arm's reach.
      x = centre_x + side * (p.half_width + rng->Uniform(0.1, 0.5)) - w / 2;
      y = p.shoulder_y + rng->Uniform(-0.5, 0.2);
      if (o.kind == "door") o.kind = "panel";
      if (o.kind == "panel" || rng->Chance(hard ? 0.35 : 0.15)) {
        o.kind = "panel";
        o.colour = Jitter(p.sleeve_cover > 0.3 ? p.sleeve : p.skin, 0.08, rng);
      }
    }
    o.box = {x, y, w, h};
    room->objects.push_back(o);
  }
}

}  // namespace

SceneModel DrawScene(const CapsuleArmSceneOptions& options) {
  SceneModel m;
  CapsuleSceneParams& q = m.params;
  Rng rng(MixSeed(options.seed, options.tier == SceneTier::kHard ? 0xC0DE2 : 0xC0DE1));
  const bool hard = options.tier == SceneTier::kHard;
  const double w = options.size.width, h = options.size.height;
  // Recording.
  q.fps = hard ? Pick(std::vector<double>{15, 20, 24, 25, 30}, &rng) : 30;
  q.background_frames = 45;
  q.standstill_frames = 60;
  q.motion_frames =
      static_cast<int>(std::round((hard ? rng.Uniform(8, 11) : rng.Uniform(7, 9)) * q.fps));
  q.side = rng.Chance(0.5) ? ArmSide::kRight : ArmSide::kLeft;
  const double side = q.side == ArmSide::kRight ? 1 : -1;
  DrawPerson(hard, &m.person, &q, &rng);
  DrawRoom(hard, m.person, &m.room, &q, &rng);
  const Person& p = m.person;
  // Camera: the straight arm spans `frac` of the frame height at the body's distance.
  q.fov_deg = rng.Uniform(50, 72);
  Camera& cam = m.camera;
  cam.f = (w / 2) / std::tan(RadFromDeg(q.fov_deg) / 2);
  cam.cx = (w - 1) / 2;
  cam.cy = (h - 1) / 2;
  const double arm = p.upper + p.fore;
  const double frac = hard ? rng.Uniform(0.24, 0.48) : rng.Uniform(0.28, 0.42);
  q.distance = cam.f * arm / (frac * h);
  const double half_h = (h / 2) / cam.f * q.distance, half_w = (w / 2) / cam.f * q.distance;
  // Vertically: the hanging wrist in the frame, the head mostly, room above when possible.
  const double lo_aim = p.HeadCentreY() + p.head_r - 0.95 * half_h;
  const double hi_aim = p.shoulder_y - arm + 0.9 * half_h - 0.03;
  // Room for the hand over the head where the framing allows it.
  const double headroom = p.HeadCentreY() + p.head_r + 0.3 - 0.92 * half_h;
  const double lo = std::max(lo_aim, headroom);
  const double aim_y = lo < hi_aim ? rng.Uniform(lo, hi_aim) : hi_aim;
  q.camera_height = p.shoulder_y + rng.Uniform(-0.35, 0.15);
  q.pitch_deg = DegFromRad(std::atan2(q.camera_height - aim_y, q.distance));
  cam.pitch_rad = RadFromDeg(q.pitch_deg);
  // Horizontally: the straight horizontal arm and its hand in the frame; in medium scenes the
  // whole body, in hard ones the far side may leave it.
  const double reach = p.half_width + arm + p.hand + p.r_hand;
  const double hi_x = 0.94 * half_w - reach;
  const double lo_x =
      hard ? -half_w + p.head_r * 1.5 : -0.94 * half_w + p.half_width + 2 * p.r_upper;
  double body_x = lo_x < hi_x ? rng.Uniform(lo_x, hi_x) : (lo_x + hi_x) / 2;
  body_x *= side;
  cam.position = {0, q.camera_height, q.distance};
  m.placement.origin = {body_x, 0, 0};
  m.placement.side = side;
  q.body_yaw_deg = hard ? rng.Uniform(-20, 20) : rng.Uniform(-8, 8);
  m.placement.yaw_rad = RadFromDeg(q.body_yaw_deg);
  q.offcentre = std::abs(cam.Project(cam.ToCam({body_x, p.shoulder_y, 0})).x - cam.cx) / w;
  // Room: the wall behind, objects around the person.
  q.wall_distance = rng.Uniform(0.4, 1.6);
  m.room.wall_z = -q.wall_distance;
  DrawObjects(hard, p, body_x, side, half_w * 1.2, &m.room, &rng);
  q.wall_objects = static_cast<int>(m.room.objects.size());
  // Light: a key light in front of the person, above, to one side.
  Light& la = m.light_a;
  la.position = {body_x + rng.Uniform(-1.5, 1.5), rng.Uniform(1.9, 2.6), rng.Uniform(0.8, 2.0)};
  la.ref_distance = Len(la.position - cv::Vec3d(body_x, p.shoulder_y - 0.2, 0));
  la.ambient = rng.Uniform(0.35, 0.55);
  la.key = rng.Uniform(0.55, 0.8);
  for (int k = 0; k < 3; ++k) la.tint[k] = static_cast<float>(1 + rng.Uniform(-0.06, 0.06));
  m.light_b = la;
  q.light_move = hard ? rng.Uniform(0.3, 0.9) : (rng.Chance(0.5) ? rng.Uniform(0.0, 0.2) : 0);
  const double az = rng.Uniform(0, 2 * kPi);
  m.light_b.position +=
      cv::Vec3d(std::cos(az), rng.Uniform(-0.3, 0.3), std::sin(az)) * q.light_move;
  q.shadow_strength =
      rng.Chance(hard ? 0.7 : 0.4) ? (hard ? rng.Uniform(0.25, 0.45) : rng.Uniform(0.15, 0.3)) : 0;
  q.drift = hard ? rng.Sign() * rng.Uniform(0.12, 0.3) : rng.Uniform(-0.08, 0.08);
  q.flicker = hard ? rng.Uniform(0, 0.04) : 0;
  for (int k = 0; k < 3; ++k)
    m.cast[k] = static_cast<float>(rng.Uniform(-1, 1) * (hard ? 0.05 : 0.02));
  q.vignetting = hard ? rng.Uniform(0.15, 0.35) : rng.Uniform(0.05, 0.2);
  q.noise_sigma = hard ? rng.Uniform(4, 7) : rng.Uniform(2, 4);
  q.jpeg_quality = hard ? rng.Int(30, 55) : rng.Int(60, 85);
  q.sway = hard ? rng.Uniform(0.01, 0.03) : (rng.Chance(0.5) ? rng.Uniform(0.003, 0.01) : 0);
  q.head_motion = rng.Chance(hard ? 0.8 : 0.5);
  m.sway_phase = rng.Uniform(0, 2 * kPi);
  m.nod_amp_rad = q.head_motion ? RadFromDeg(rng.Uniform(4, 12)) : 0;
  m.tilt_amp_rad = q.head_motion ? RadFromDeg(rng.Uniform(2, 8)) : 0;
  // Motion.
  MotionSpec& ms = m.motion;
  ms.fps = q.fps;
  ms.frames = q.motion_frames;
  ms.speed_limit_deg = q.speed_limit_deg = hard ? rng.Uniform(5, 12) : rng.Uniform(3, 6);
  ms.max_tilt_deg = q.max_tilt_deg = hard ? 25 : 10;
  ms.max_yaw_deg = hard ? 60 : 40;
  ms.upper_max_deg = hard ? 120 : 100;
  ms.over_head = rng.Chance(hard ? 0.6 : 0.4);
  ms.beside_head = rng.Chance(hard ? 0.5 : 0.3);
  ms.across_torso = rng.Chance(hard ? 0.55 : 0.35);
  ms.yaw = rng.Chance(hard ? 0.4 : 0.25);
  return m;
}

}  // namespace armmimic::synth::capsule

namespace armmimic::synth {

AngleMeta CapsuleSceneParams::Describe() const {
  auto num = [](double v, int d) { return FormatNumber(v, d); };
  return {{"fps", num(fps, 3)},
          {"background_frames", std::to_string(background_frames)},
          {"standstill_frames", std::to_string(standstill_frames)},
          {"motion_frames", std::to_string(motion_frames)},
          {"side", ArmSideName(side)},
          {"fov_deg", num(fov_deg, 1)},
          {"pitch_deg", num(pitch_deg, 1)},
          {"camera_height_m", num(camera_height, 2)},
          {"distance_m", num(distance, 2)},
          {"height_m", num(height, 2)},
          {"upper_m", num(upper, 3)},
          {"fore_m", num(fore, 3)},
          {"hand_m", num(hand, 3)},
          {"upper_radius_m", num(upper_radius, 3)},
          {"fore_radius_m", num(fore_radius, 3)},
          {"shoulder_half_width_m", num(shoulder_half_width, 3)},
          {"torso_radius_m", num(torso_radius, 3)},
          {"head_radius_m", num(head_radius, 3)},
          {"body_yaw_deg", num(body_yaw_deg, 1)},
          {"offcentre", num(offcentre, 3)},
          {"sleeves", sleeves},
          {"sleeve_cover", num(sleeve_cover, 2)},
          {"pattern", pattern},
          {"shirt_like_skin", shirt_like_skin ? "yes" : "no"},
          {"shirt_skin_distance", num(shirt_skin_distance, 1)},
          {"arm_wall_distance", num(arm_wall_distance, 1)},
          {"skin_tone", num(skin_tone, 2)},
          {"hair", hair},
          {"wall_texture", wall_texture},
          {"wall_distance_m", num(wall_distance, 2)},
          {"wall_objects", std::to_string(wall_objects)},
          {"drift", num(drift, 3)},
          {"flicker", num(flicker, 3)},
          {"light_move_m", num(light_move, 2)},
          {"shadow_strength", num(shadow_strength, 2)},
          {"vignetting", num(vignetting, 2)},
          {"noise", num(noise_sigma, 2)},
          {"jpeg_quality", std::to_string(jpeg_quality)},
          {"sway_m", num(sway, 3)},
          {"head_motion", head_motion ? "yes" : "no"},
          {"speed_limit_deg", num(speed_limit_deg, 1)},
          {"max_tilt_deg", num(max_tilt_deg, 1)},
          {"max_step_deg", num(max_step_deg, 2)},
          {"hand_over_head", hand_over_head ? "yes" : "no"},
          {"beside_head", beside_head ? "yes" : "no"},
          {"across_torso", across_torso ? "yes" : "no"},
          {"yaw_move", yaw_move ? "yes" : "no"},
          {"raised", raised ? "yes" : "no"}};
}

}  // namespace armmimic::synth
