// What a seed draws for a random arm scene, per tier: the recording, the person and their
// clothing, what the room and the motion must contain, the camera and the light. The ranges are
// the ones docs/synth.md lists; keep the two in step.
#include <algorithm>
#include <cmath>

#include "random_scene_model.h"

namespace armmimic::synth::random_scene {
namespace {

struct Range {
  double lo, hi;
  double Draw(cv::RNG& rng) const { return lo >= hi ? lo : rng.uniform(lo, hi); }
};

// The knobs of one tier (zero: the feature is off).
struct TierKnobs {
  std::vector<double> fps;  // drawn from these
  Range seconds{6, 6};      // motion length
  Range arm{0.35, 0.35};    // shoulder-to-wrist length over the frame height
  Range upper_share{0.54, 0.54}, body{1, 1}, head{1, 1}, neck{1, 1}, limb{1, 1};
  double centre_spread = 0;  // the body centre within this share of the width of the middle
  double edge_chance = 0;    // the body placed near the frame's edge (else anywhere it fits)
  double short_sleeves = 0;
  Range cover{1, 1};           // share of the upper arm a short sleeve covers
  double distinct_sleeve = 0;  // sleeves of another cloth than the shirt
  double camo_object = 0, camo_wall = 0, camo_shirt = 0;
  Range camo_wall_distance{0, 0};
  Range camo_object_scale{0.5, 0.9};  // a camouflage object's side over the segment it hides
  double min_sleeve_wall = 60;        // lit sleeve to wall, when not camouflaged
  Range wall_sat{0, 0}, wall_val{0.8, 0.8};
  int pieces_lo = 0, pieces_hi = 0;
  double behind_chance = 0;
  Range vignette{0, 0}, noise{1, 1}, quality{90, 90}, drift{0, 0}, flicker{0, 0}, cast{0, 0};
  double shadow_chance = 0;
  Range shadow_strength{0, 0};
  double sway_chance = 0;
  Range sway{0, 0};  // pixels at a frame height of 240
  double head_motion = 0;
  Range speed{1, 4};  // peak degrees a frame of each move
  bool one_fast = false;
  double by_head = 0, above_head = 0, across_torso = 0, raised = 0;
  double raised_max = 115;  // the raised arm's upper-arm direction up to this (90: straight up)
};

TierKnobs EasyKnobs() {
  TierKnobs k;
  k.fps = {30};
  k.seconds = {5, 7};
  k.arm = {0.30, 0.40}, k.upper_share = {0.52, 0.56};
  k.body = {0.9, 1.1}, k.head = {0.9, 1.1}, k.neck = {0.8, 1.2}, k.limb = {0.9, 1.1};
  k.centre_spread = 0.08;
  k.distinct_sleeve = 0.2;
  k.min_sleeve_wall = 100;
  k.wall_sat = {0, 0.25}, k.wall_val = {0.65, 0.95};
  k.pieces_lo = 0, k.pieces_hi = 2;
  k.vignette = {0, 0.1}, k.noise = {1, 2}, k.quality = {90, 95};
  k.speed = {1.5, 4};
  k.raised = 0.5, k.raised_max = 95;
  return k;
}

TierKnobs MediumKnobs() {
  TierKnobs k;
  k.fps = {15, 20, 24, 25, 30};
  k.seconds = {6, 9};
  k.arm = {0.25, 0.50}, k.upper_share = {0.48, 0.60};
  k.body = {0.8, 1.25}, k.head = {0.8, 1.25}, k.neck = {0.5, 1.5}, k.limb = {0.8, 1.25};
  k.short_sleeves = 0.4, k.cover = {0.3, 0.9};
  k.distinct_sleeve = 0.25;
  k.camo_object = 0.2, k.camo_wall = 0.15, k.camo_wall_distance = {35, 60};
  k.min_sleeve_wall = 60;
  k.wall_sat = {0, 0.45}, k.wall_val = {0.45, 0.95};
  k.pieces_lo = 1, k.pieces_hi = 4, k.behind_chance = 0.5;
  k.vignette = {0.05, 0.25}, k.noise = {2, 4}, k.quality = {60, 85}, k.drift = {-0.1, 0.1};
  k.shadow_chance = 0.25, k.shadow_strength = {0.15, 0.3};
  k.sway_chance = 0.5, k.sway = {0.3, 1};
  k.head_motion = 0.5;
  k.speed = {2, 8};
  k.by_head = 0.4, k.above_head = 0.2, k.across_torso = 0.35, k.raised = 0.6;
  return k;
}

TierKnobs HardKnobs() {
  TierKnobs k;
  k.fps = {10, 12, 15};
  k.seconds = {8, 12};
  k.arm = {0.25, 0.60}, k.upper_share = {0.45, 0.62};
  k.body = {0.75, 1.3}, k.head = {0.8, 1.3}, k.neck = {0.4, 1.6}, k.limb = {0.7, 1.35};
  k.edge_chance = 0.5;
  k.short_sleeves = 0.5, k.cover = {0.2, 0.9};
  k.distinct_sleeve = 0.2;
  k.camo_object = 0.45, k.camo_wall = 0.25, k.camo_shirt = 0.30, k.camo_wall_distance = {25, 45};
  k.camo_object_scale = {0.7, 1.2};
  k.min_sleeve_wall = 60;
  k.wall_sat = {0, 0.45}, k.wall_val = {0.35, 0.95};
  k.pieces_lo = 2, k.pieces_hi = 5, k.behind_chance = 1;
  k.vignette = {0.15, 0.4}, k.noise = {4, 8}, k.quality = {25, 50};
  k.drift = {0.15, 0.35}, k.flicker = {0, 0.04}, k.cast = {0, 0.05};
  k.shadow_chance = 0.7, k.shadow_strength = {0.25, 0.45};
  k.sway_chance = 1, k.sway = {1.5, 4};
  k.head_motion = 0.8;
  k.speed = {3, 15}, k.one_fast = true;
  k.by_head = 0.5, k.above_head = 0.5, k.across_torso = 0.5, k.raised = 0.6;
  return k;
}

const TierKnobs& Knobs(SceneTier tier) {
  static const TierKnobs easy = EasyKnobs(), medium = MediumKnobs(), hard = HardKnobs();
  switch (tier) {
    case SceneTier::kEasy:
      return easy;
    case SceneTier::kMedium:
      return medium;
    case SceneTier::kHard:
      return hard;
  }
  return medium;
}

double Sign(cv::RNG& rng) { return rng.uniform(0, 2) ? 1.0 : -1.0; }

// Body proportions, size and place in the frame.
// `headroom`: leave room for the hand above the head where the frame allows it.
void DrawPerson(cv::RNG& rng, const TierKnobs& k, cv::Size size, bool headroom, SceneDraw* d) {
  RandomSceneParams& p = d->params;
  PersonModel& m = d->person;
  const double W = size.width, H = size.height;
  p.arm_fraction = k.arm.Draw(rng);
  p.body_width = k.body.Draw(rng);
  p.head_size = k.head.Draw(rng);
  p.neck = k.neck.Draw(rng);
  p.limb_thickness = k.limb.Draw(rng);
  const double share = k.upper_share.Draw(rng);
  m.upper = 82 * share;
  m.fore = 82 - m.upper;
  m.hand = 0.3 * m.fore;
  m.w = 30 * p.body_width;
  m.limb = p.limb_thickness;
  m.head_rx = 13.5 * p.head_size;
  m.head_ry = 16.5 * p.head_size * rng.uniform(0.95, 1.1);
  m.head_dy = m.head_ry + 25.5 * p.neck;
  m.neck_r = 6.5 * rng.uniform(0.85, 1.15);
  m.torso_len = rng.uniform(0.9, 1.1);
  // The largest arm that fits: the straight horizontal arm (the arm-length image) in the frame.
  double cx_lo = 0, cx_hi = -1;
  for (int shrink = 0; shrink < 40 && cx_hi < cx_lo; ++shrink) {
    if (shrink > 0) p.arm_fraction *= 0.95;
    m.s = p.arm_fraction * H / 82.0;
    cx_hi = W - 3 - (m.w + m.upper + m.fore + m.hand + 5) * m.s;
    cx_lo = k.edge_chance > 0 ? 0.5 * m.w * m.s : (m.w + 8) * m.s;
  }
  double cx = rng.uniform(cx_lo, std::max(cx_lo, cx_hi));
  if (k.centre_spread > 0) {
    cx = std::clamp(W / 2 + rng.uniform(-k.centre_spread, k.centre_spread) * W, cx_lo, cx_hi);
  } else if (rng.uniform(0.0, 1.0) < k.edge_chance) {
    const double f = rng.uniform(0.0, 0.2);
    cx = rng.uniform(0, 2) ? cx_lo + f * (cx_hi - cx_lo) : cx_hi - f * (cx_hi - cx_lo);
  }
  m.cx = cx;
  // Vertically: the hanging wrist in the frame; the hand and at least most of the head too
  // where the arm's size allows.
  const double y_hi_wrist = H - 3 - (m.upper + m.fore) * m.s;
  const double y_hi_hand = H - 3 - (m.upper + m.fore + m.hand + 4) * m.s;
  double y_lo = (m.head_dy + 0.8 * m.head_ry) * m.s;
  const double y_room = (m.head_dy + m.head_ry + 16 + m.hand) * m.s;
  if (headroom && y_room <= y_hi_wrist) y_lo = std::max(y_lo, y_room);
  // The easy tier keeps the whole head in the frame.
  if (k.centre_spread > 0) y_lo = std::max(y_lo, (m.head_dy + m.head_ry) * m.s + 4);
  if (y_lo <= y_hi_hand) {
    m.ysh = rng.uniform(y_lo, y_hi_hand);
  } else {
    m.ysh = std::min(y_hi_wrist, std::max(y_lo, y_hi_hand));
  }
  p.upper_px = m.upper * m.s;
  p.fore_px = m.fore * m.s;
  p.hand_px = m.hand * m.s;
  p.side = rng.uniform(0, 2) ? ArmSide::kLeft : ArmSide::kRight;
  p.offcentre = std::fabs(cx - W / 2) / W;
}

// A cloth colour whose lit version is at least `min_dist` from the wall.
cv::Vec3f ClothFarFrom(cv::RNG& rng, const cv::Vec3f& wall, double min_dist) {
  cv::Vec3f c;
  for (int attempt = 0; attempt < 100; ++attempt) {
    c = Hsv(rng.uniform(0.0, 360.0), rng.uniform(0.0, 0.85), rng.uniform(0.15, 0.95));
    if (ColourDistance(c * kLimbShade, wall) >= min_dist) break;
  }
  return c;
}

void DrawClothing(cv::RNG& rng, const TierKnobs& k, SceneDraw* d) {
  RandomSceneParams& p = d->params;
  PersonModel& m = d->person;
  d->wall = Hsv(rng.uniform(0.0, 360.0), k.wall_sat.Draw(rng), k.wall_val.Draw(rng));
  p.skin_tone = rng.uniform(0.0, 1.0);
  const cv::Vec3f light(150, 175, 225), dark(45, 65, 100);
  m.skin = Clamp255(light + (dark - light) * static_cast<float>(p.skin_tone) +
                    cv::Vec3f(static_cast<float>(rng.uniform(-6.0, 6.0)),
                              static_cast<float>(rng.uniform(-6.0, 6.0)),
                              static_cast<float>(rng.uniform(-6.0, 6.0))));
  m.trousers = Hsv(rng.uniform(0.0, 360.0), rng.uniform(0.0, 0.5), rng.uniform(0.12, 0.5));
  m.hair = rng.uniform(0.0, 1.0) < 0.15
               ? Hsv(0, 0, rng.uniform(0.5, 0.8))
               : Hsv(rng.uniform(20.0, 40.0), rng.uniform(0.2, 0.7), rng.uniform(0.08, 0.6));
  m.has_belt = rng.uniform(0, 2) == 1;
  m.belt = Hsv(rng.uniform(0.0, 360.0), rng.uniform(0.0, 0.6), rng.uniform(0.1, 0.4));
  p.short_sleeves = rng.uniform(0.0, 1.0) < k.short_sleeves;
  p.sleeve_cover = p.short_sleeves ? k.cover.Draw(rng) : 1.0;
  m.sleeve_cover = p.sleeve_cover;

  const double u = rng.uniform(0.0, 1.0);
  p.camouflage = u < k.camo_object                                ? "object"
                 : u < k.camo_object + k.camo_wall                ? "wall"
                 : u < k.camo_object + k.camo_wall + k.camo_shirt ? "shirt"
                                                                  : "none";
  m.shirt = ClothFarFrom(rng, d->wall, k.min_sleeve_wall);
  m.sleeve = m.shirt;
  p.sleeve_match = "shirt";
  if (p.camouflage == "wall") {
    // The lit sleeve a set distance from the wall, on the way to a cloth colour far from it.
    const cv::Vec3f base = ClothFarFrom(rng, d->wall, 2 * k.camo_wall_distance.hi) * kLimbShade;
    const double dist = k.camo_wall_distance.Draw(rng);
    const double full = std::max(1.0, ColourDistance(base, d->wall));
    const cv::Vec3f lit =
        d->wall + (base - d->wall) * static_cast<float>(std::min(1.0, dist / full));
    m.sleeve = Clamp255(lit / kLimbShade);
    p.sleeve_match = "wall";
  } else if (p.camouflage != "shirt" && rng.uniform(0.0, 1.0) < k.distinct_sleeve) {
    for (int attempt = 0; attempt < 50; ++attempt) {
      m.sleeve = ClothFarFrom(rng, d->wall, k.min_sleeve_wall);
      if (ColourDistance(m.sleeve, m.shirt) > 60) break;
    }
    p.sleeve_match = "distinct";
  } else {
    // The shirt's own cloth, a little lighter or darker on the sleeve.
    m.sleeve = Clamp255(m.shirt * static_cast<float>(rng.uniform(0.95, 1.05)));
  }
  p.sleeve_wall_distance = ColourDistance(m.sleeve * kLimbShade, d->wall);
  p.skin_wall_distance = ColourDistance(m.skin * kLimbShade, d->wall);
}

void DrawCamera(cv::RNG& rng, const TierKnobs& k, cv::Size size, SceneDraw* d) {
  RandomSceneParams& p = d->params;
  const double H = size.height, W = size.width;
  p.vignetting = k.vignette.Draw(rng);
  p.noise_sigma = k.noise.Draw(rng);
  p.jpeg_quality = static_cast<int>(std::lround(k.quality.Draw(rng)));
  p.drift = k.drift.lo < 0 ? k.drift.Draw(rng) : Sign(rng) * k.drift.Draw(rng);
  p.flicker = k.flicker.Draw(rng);
  d->flicker_period_s = rng.uniform(2.0, 5.0);
  d->flicker_phase = rng.uniform(0.0, 2 * CV_PI);
  for (int c = 0; c < 3; ++c) d->colour_cast[c] = static_cast<float>(Sign(rng) * k.cast.Draw(rng));
  p.shadow = rng.uniform(0.0, 1.0) < k.shadow_chance;
  p.shadow_strength = p.shadow ? k.shadow_strength.Draw(rng) : 0.0;
  d->shadow_from = {rng.uniform(-0.1, 1.1) * W, rng.uniform(0.3, 0.7) * H};
  d->shadow_to = {rng.uniform(-0.1, 1.1) * W, rng.uniform(0.3, 0.7) * H};
  d->shadow_sigma = {rng.uniform(0.1, 0.2) * W, rng.uniform(0.2, 0.4) * H};
  p.sway_px = rng.uniform(0.0, 1.0) < k.sway_chance ? k.sway.Draw(rng) * H / 240.0 : 0.0;
  for (int i = 0; i < 2; ++i) {
    d->sway_period_s[i] = rng.uniform(1.2, 3.0);
    d->sway_phase[i] = rng.uniform(0.0, 2 * CV_PI);
  }
  p.head_motion = rng.uniform(0.0, 1.0) < k.head_motion;
  d->nod_deg = p.head_motion ? rng.uniform(2.0, 7.0) : 0.0;
  d->nod_period_s = rng.uniform(1.5, 3.5);
}

}  // namespace

SceneDraw DrawScene(const RandomArmSceneOptions& options) {
  cv::RNG rng(Mix(options.seed, 0x7A11 + static_cast<uint64_t>(options.tier)));
  const TierKnobs& k = Knobs(options.tier);
  SceneDraw d;
  RandomSceneParams& p = d.params;
  p.fps = k.fps[static_cast<std::size_t>(rng.uniform(0, static_cast<int>(k.fps.size())))];
  p.background_frames = static_cast<int>(std::lround(p.fps * rng.uniform(1.0, 1.5)));
  p.standstill_frames = static_cast<int>(std::lround(p.fps * rng.uniform(1.5, 2.0)));
  p.motion_frames = static_cast<int>(std::lround(p.fps * k.seconds.Draw(rng)));
  if (options.tier == SceneTier::kEasy) p.background_frames = 45, p.standstill_frames = 60;
  MotionPlanSpec& mo = d.motion;
  mo.frames = p.motion_frames;
  mo.fps = p.fps;
  mo.speed_min = k.speed.lo;
  mo.speed_max = k.speed.hi;
  mo.one_fast_move = k.one_fast;
  mo.by_head = rng.uniform(0.0, 1.0) < k.by_head;
  mo.above_head = rng.uniform(0.0, 1.0) < k.above_head;
  mo.across_torso = rng.uniform(0.0, 1.0) < k.across_torso;
  mo.raised = rng.uniform(0.0, 1.0) < k.raised;
  mo.raised_max_deg = k.raised_max;
  p.speed_limit_deg = k.speed.hi;
  DrawPerson(rng, k, options.size, mo.above_head || mo.raised, &d);
  DrawClothing(rng, k, &d);
  DrawCamera(rng, k, options.size, &d);
  mo.across_torso |= p.camouflage == "shirt";

  RoomRequest& room = d.room;
  room.tier = options.tier;
  room.pieces = rng.uniform(k.pieces_lo, k.pieces_hi + 1);
  room.behind_arm = room.pieces > 0 && rng.uniform(0.0, 1.0) < k.behind_chance;
  room.keep_clear = options.tier == SceneTier::kEasy;
  room.camouflage_object = p.camouflage == "object";
  room.camo_scale = {k.camo_object_scale.lo, k.camo_object_scale.hi};
  return d;
}

}  // namespace armmimic::synth::random_scene
