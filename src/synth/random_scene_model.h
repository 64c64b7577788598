// The drawn model of a random arm scene, shared by the files that draw and paint it. Private to
// the synth layer. Everything is laid out for a moving arm on the right of the image (the
// "canonical" image); a scene with the arm on the left is the mirror image.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/synth/random_arm_scene.h"
#include "paint.h"

namespace armmimic::synth::random_scene {

// A colour from hue (degrees), saturation and value (0..1), BGR 0..255.
cv::Vec3f Hsv(double hue, double sat, double val);
double ColourDistance(const cv::Vec3f& a, const cv::Vec3f& b);

// Limbs are shaded as cylinders: their lit middle shows about this share of their colour.
inline constexpr float kLimbShade = 0.854f;

// The person in body units (the reference figure: a 240-unit tall frame, shoulder to wrist 82
// units); `s` pixels per unit.
struct PersonModel {
  double s = 1;
  double cx = 160, ysh = 100;  // centre line and shoulder-joint line, canonical pixels
  double w = 30;               // shoulder joint's distance from the centre line, units
  double upper = 44, fore = 38, hand = 12;
  double limb = 1;  // limb radius factor
  double head_rx = 13.5, head_ry = 16.5;
  double head_dy = 42;  // head centre above the shoulder line, units
  double neck_r = 6.5;
  double torso_len = 1;
  double sleeve_cover = 1;  // share of the upper arm in the sleeve
  cv::Vec3f shirt, sleeve, skin, trousers, hair, belt;
  bool has_belt = true;

  cv::Point2d P(double u, double v) const { return {cx + u * s, ysh + v * s}; }
  cv::Point2d Shoulder() const { return P(w, 0); }
  cv::Point2d HeadCentre() const { return P(0, -head_dy); }
  double ArmPx() const { return (upper + fore) * s; }
  // Upper-arm radius at the shoulder and elbow, forearm at elbow and wrist, hand, pixels.
  double R(double units) const { return units * limb * s; }
};

// A pose of the moving arm in the canonical image: directions on screen (contract convention),
// kept unwrapped so that keyframes interpolate without jumps.
struct Pose {
  double upper_deg = -90;
  double bend_deg = 0;  // forearm = upper + bend
};

struct ArmJoints {
  cv::Point2d shoulder, elbow, wrist, tip;
};

ArmJoints JointsOf(const PersonModel& m, const Pose& pose, cv::Point2d offset);

enum class ObjectKind { kCabinet, kShelf, kPoster, kDoor, kWindow };

struct RoomObject {
  ObjectKind kind = ObjectKind::kPoster;
  cv::Rect2d box;      // canonical pixels
  cv::Vec3f colour;    // main surface
  cv::Vec3f accent;    // frame, knob, books, picture content
  uint64_t salt = 0;   // its own texture and content
  bool plain = false;  // one colour, no picture (a camouflage surface)
};

struct RoomSpec {
  cv::Vec3f wall;
  std::string texture = "plaster";
  double texture_strength = 1;
  double floor_y = 1e9;  // canonical pixels; below the frame when the floor is not seen
  cv::Vec3f floor;
  std::vector<RoomObject> objects;  // painted in order
};

// What the room must contain, decided with the person and the motion.
struct RoomRequest {
  SceneTier tier = SceneTier::kEasy;
  int pieces = 0;           // furniture, posters, doors, windows, shelves
  bool behind_arm = false;  // the first piece is placed where the arm moves
  bool keep_clear = false;  // the others stay out of the arm's reach
  bool camouflage_object = false;
  cv::Vec3f camo_colour;                           // the lit colour of the segment it hides
  cv::Point2d camo_at;                             // where that segment passes
  double camo_size = 0;                            // the segment's length, pixels
  std::pair<double, double> camo_scale{0.5, 0.9};  // the object's side over camo_size
};

RoomSpec DrawRoom(cv::RNG& rng, const RoomRequest& req, const PersonModel& m, cv::Size size,
                  const cv::Vec3f& wall);

// Paints the empty room, canonical orientation, CV_32FC3.
cv::Mat PaintRoom(const RoomSpec& room, cv::Size size, uint64_t seed);

struct PersonTextures {
  Texture fabric, skin;
};

// The parts of the person that do not move with the arm: legs, torso, neck, the other arm
// (hanging) and the shoulder caps, onto a transparent layer.
void PaintStaticBody(Layer* layer, const PersonModel& m, const PersonTextures& tex);
// The head with hair, ears, eyes and mouth, moved by `offset` pixels and tilted.
void PaintHead(Layer* layer, const PersonModel& m, const PersonTextures& tex, cv::Point2d offset,
               double tilt_deg);
// The moving arm: sleeve, bare skin below a short sleeve, cuff and hand.
void PaintMovingArm(Layer* layer, const PersonModel& m, const PersonTextures& tex,
                    const ArmJoints& j);

// Keyframed motion: poses joined by minimum-jerk moves, with pauses.
struct MotionKey {
  Pose pose;
  double frame = 0;  // motion frame at which the pose is reached
  int kind = 0;      // the pose class it was drawn from (random_motion.cpp)
};

class RandomMotion {
 public:
  RandomMotion() = default;
  explicit RandomMotion(std::vector<MotionKey> keys) : keys_(std::move(keys)) {}
  Pose At(double i) const;
  const std::vector<MotionKey>& keys() const { return keys_; }

 private:
  std::vector<MotionKey> keys_;
};

// Which pose classes a scene's motion visits and how fast it may move.
struct MotionPlanSpec {
  bool by_head = false, above_head = false, across_torso = false, raised = true;
  double raised_max_deg = 115;          // the raised arm's upper-arm direction goes up to this
  double speed_min = 1, speed_max = 4;  // peak degrees a frame of each move, drawn per move
  bool one_fast_move = false;           // at least one move at 0.8..1 of speed_max
  double pause_chance = 0.3;
  int frames = 180;
  double fps = 30;
};

RandomMotion PlanRandomMotion(cv::RNG& rng, const MotionPlanSpec& spec, const PersonModel& m,
                              cv::Size size, RandomSceneParams* params);

// Everything drawn from the seed before the motion and the room: the knobs, the person, what
// the motion and the room must contain, and how light and body move over time.
struct SceneDraw {
  RandomSceneParams params;
  PersonModel person;
  MotionPlanSpec motion;
  RoomRequest room;
  cv::Vec3f wall;
  cv::Point2d shadow_from, shadow_to;  // the shadow's centre at the motion's start and end
  cv::Size2d shadow_sigma;
  double sway_period_s[2] = {2, 1.5}, sway_phase[2] = {0, 0};
  double nod_deg = 0, nod_period_s = 2;
  double flicker_period_s = 3, flicker_phase = 0;
  cv::Vec3f colour_cast{0, 0, 0};  // per-channel gain change over the video
};

// Draws a scene from options.seed and options.tier (random_scene_params.cpp).
SceneDraw DrawScene(const RandomArmSceneOptions& options);

// Light and sensor: a per-pixel gain (vignetting, a moving shadow) and a per-channel gain.
struct ShadowSpot {
  bool on = false;
  cv::Point2d centre;
  cv::Size2d sigma;
  double strength = 0;
};
cv::Mat VignetteMap(cv::Size size, double strength);
// The frame the camera delivers from the scene's light (`canvas`, CV_32FC3): vignetting, the
// shadow, the per-channel gain and Gaussian sensor noise (sigma 0: none), rounded to CV_8UC3.
cv::Mat Expose(const cv::Mat& canvas, const cv::Mat& vignette, const cv::Vec3f& gain,
               const ShadowSpot& shadow, double noise_sigma, uint64_t noise_seed);

}  // namespace armmimic::synth::random_scene
