// The model of a capsule arm scene (capsule_arm_scene.h), shared by the files that draw, move and
// ray cast it. Private to the synth layer; nothing here is shared with the painted generators.
//
// Frames: the world has X to the image's right, Y up and Z towards the camera, the floor at
// Y = 0. The body frame is the world's turned by the body's yaw about the vertical through the
// body centre. The camera frame has x right, y down and z away from the camera.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/synth/capsule_arm_scene.h"

namespace armmimic::synth::capsule {

// splitmix64: the same numbers on every platform and standard library.
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t Next();
  double Uniform(double lo, double hi);  // [lo, hi)
  int Int(int lo, int hi);               // [lo, hi]
  bool Chance(double p) { return Uniform(0, 1) < p; }
  double Sign() { return Chance(0.5) ? 1.0 : -1.0; }

 private:
  uint64_t state_;
};

uint64_t MixSeed(uint64_t seed, uint64_t salt);

inline double Dot(const cv::Vec3d& a, const cv::Vec3d& b) { return a.dot(b); }
inline double Len(const cv::Vec3d& a) { return std::sqrt(a.dot(a)); }
inline cv::Vec3d Unit(const cv::Vec3d& a) { return a * (1.0 / Len(a)); }

// A level-or-pitched pinhole camera at `position` (world).
struct Camera {
  double f = 300, cx = 160, cy = 120;
  double pitch_rad = 0;  // positive looks down
  cv::Vec3d position;    // world
  cv::Vec3d ToCam(const cv::Vec3d& world) const;
  cv::Vec3d DirToCam(const cv::Vec3d& world_dir) const;
  cv::Point2d Project(const cv::Vec3d& cam) const {
    return {cx + f * cam[0] / cam[2], cy + f * cam[1] / cam[2]};
  }
  cv::Vec3d Ray(double u, double v) const { return Unit({(u - cx) / f, (v - cy) / f, 1.0}); }
};

// What a capsule is made of; Shade() picks colours from it.
enum class Material : uint8_t { kShirt, kArm, kSkin, kHead, kHair, kTrousers };

// A sphere-swept segment in the camera frame.
struct Capsule {
  cv::Vec3d a, b;
  double r = 0.05;
  CapsulePart part = kPartBody;
  Material material = Material::kSkin;
  // Surface coordinates: the body's right and up axes (camera frame) and its origin, for the
  // shirt's pattern and the face; for arm segments, the distance from the shoulder at `a`.
  cv::Vec3d ex, ey, origin;
  double arm_s0 = 0;
  cv::Rect box;  // pixels it can cover (conservative)
};

// Nearest t > 0 where the ray o + t d (d unit) meets the capsule, or -1.
double IntersectCapsule(const cv::Vec3d& o, const cv::Vec3d& d, const Capsule& c);
// The outward surface normal at `p` on the capsule.
cv::Vec3d CapsuleNormal(const Capsule& c, const cv::Vec3d& p);
// Shortest distance between segments [p0, p1] and [q0, q1].
double SegmentDistance(const cv::Vec3d& p0, const cv::Vec3d& p1, const cv::Vec3d& q0,
                       const cv::Vec3d& q1);
// The pixel box a capsule can cover (clipped to `size`; empty when behind the camera).
cv::Rect CapsuleBox(const Camera& cam, const Capsule& c, cv::Size size);

// A pose of the moving arm, in the body frame mirrored so that +out points away from the body on
// the moving arm's side. Angles in degrees: `upper` the upper arm's direction in the body's
// plane (-90 hanging, 0 out, 90 up), `upper_tilt` out of that plane (+ towards the camera),
// `bend` the forearm's direction in the plane relative to the upper arm, `fore_tilt` its tilt.
struct ArmPose {
  double upper = -85, upper_tilt = 0, bend = 0, fore_tilt = 0;
};

// The person: proportions, clothing and the colours (BGR 0..255) the seed drew.
struct Person {
  double height = 1.75, shoulder_y = 1.42, hip_y = 0.92;
  double half_width = 0.2;  // centre line to the shoulder joint
  double upper = 0.3, fore = 0.26, hand = 0.09;
  double r_upper = 0.05, r_fore = 0.04, r_hand = 0.032;
  double r_torso = 0.11, r_shoulder = 0.055, r_neck = 0.05, r_leg = 0.08;
  double head_r = 0.1, neck = 0.06;
  double hang_out_deg = 6;  // the hanging arms' angle out from the vertical
  double sleeve_cover = 1;  // share of shoulder..wrist in the sleeve
  bool sleeveless = false;
  std::string pattern = "plain", hair_style = "short";
  double pattern_period = 0.06;
  cv::Vec3f shirt, shirt2, sleeve, skin, trousers, hair;
  double HeadCentreY() const { return shoulder_y + r_shoulder + neck + head_r * 0.9; }
};

// Where the person stands and how they move apart from the arm: the body frame's origin (world),
// its yaw, and the sway and nod of the moment.
struct BodyPlacement {
  cv::Vec3d origin;  // floor point under the body centre
  double yaw_rad = 0;
  cv::Vec3d sway;       // added to every point (world)
  double nod_rad = 0;   // the head's nod
  double tilt_rad = 0;  // the head's sideways tilt
  double side = 1;      // +1: the moving arm on the image's right
};

// Body frame to world.
cv::Vec3d BodyToWorld(const BodyPlacement& b, const cv::Vec3d& p);
// The moving arm's shoulder, elbow, wrist and hand tip in the body frame.
struct ArmPoints {
  cv::Vec3d shoulder, elbow, wrist, tip;
};
ArmPoints ArmInBody(const Person& p, const ArmPose& pose, double side);
// Both arms hanging beside the body, as in the standstill.
ArmPose HangingPose(const Person& p);
// Unit directions of the upper arm and forearm of a pose, body frame.
void PoseDirections(const ArmPose& pose, double side, cv::Vec3d* u, cv::Vec3d* f);
// The pose whose upper arm and forearm point along `u` and `f` (body frame).
ArmPose PoseFromDirections(const cv::Vec3d& u, const cv::Vec3d& f, double side);

// Every capsule of the person (camera frame) with the moving arm in `pose` and the other arm
// hanging. `person` false gives none (the empty room).
std::vector<Capsule> BuildPerson(const Person& p, const BodyPlacement& b, const ArmPose& pose,
                                 const Camera& cam, cv::Size size);
// The person's capsules apart from the moving arm, in the body frame (before placement): torso,
// shoulders, hips, legs, neck, head, hair and the other arm hanging. The moving arm keeps clear
// of them.
struct BodyPiece {
  cv::Vec3d a, b;
  double r = 0;
  Material material = Material::kSkin;
  bool at_shoulders = false;  // the moving upper arm starts inside or beside it
  bool head = false;          // turns with the head
  double arm_s0 = 0;          // arm pieces: distance from the shoulder at `a`
};
std::vector<BodyPiece> BodyPieces(const Person& p, double side);

// A point light and the ambient share; positions in world. The key light falls off with the
// square of the distance, relative to `ref_distance` (the light to the person's chest).
struct Light {
  cv::Vec3d position;
  double ambient = 0.4, key = 0.75;
  double ref_distance = 2;
  cv::Vec3f tint{1, 1, 1};
  double Falloff(double distance) const {
    const double k = ref_distance / std::max(distance, 1e-3);
    return std::min(1.6, k * k);
  }
};

// The room behind the person: a textured wall at Z = wall_z, a floor at Y = 0 and a ceiling,
// with objects on the wall. Coordinates in metres (world).
struct WallObject {
  std::string kind;  // picture, door, shelf, window, panel
  cv::Rect2d box;    // x, y (bottom edge), width, height on the wall
  cv::Vec3f colour, accent;
  uint64_t salt = 0;
};

struct Room {
  double wall_z = -0.8, ceiling_y = 2.7;
  std::string texture = "paint";
  double texture_strength = 1;
  double texture_scale = 1;  // bricks, tiles, boards and stripes larger or smaller
  cv::Vec3f wall, wall2;     // the wall's colours (mortar, grout, second stripe, ...)
  double dado_y = 0;         // below this the wall is panelled in `dado` (0: none)
  cv::Vec3f dado, floor, ceiling;
  std::string floor_kind = "planks";
  std::vector<WallObject> objects;
  uint64_t salt = 0;
};

// The room as the camera sees it, lit by `light` and averaged over 2x2 samples a pixel
// (CV_32FC3), and each pixel's centre point on the room's surfaces in the camera frame
// (CV_32FC3) with its surface normal (CV_32FC3, camera frame).
struct RoomView {
  cv::Mat colour, point, normal;
};
RoomView RenderRoom(const Room& room, const Camera& cam, const Light& light, cv::Size size);

// Smooth value noise in [-1, 1] and a sum of octaves of it.
double ValueNoise(double x, double y, uint64_t salt);
double Fbm(double x, double y, uint64_t salt, int octaves);

// The colour of the person at a hit point (camera frame) on capsule `c`, lit by `light_cam`
// (the light's position in the camera frame).
cv::Vec3f Shade(const Person& person, const Capsule& c, const cv::Vec3d& hit,
                const cv::Vec3d& light_cam, const Light& light);

// What the motion may do, and how fast.
struct MotionSpec {
  double fps = 30;
  int frames = 240;
  double speed_limit_deg = 5;  // peak change of a direction in one move, degrees a frame
  double max_tilt_deg = 10;    // ordinary poses: segments out of the body's plane
  double max_yaw_deg = 40;     // the straight arm turned out of the plane
  double upper_max_deg = 100;  // how far above the horizontal ordinary reaches go
  bool over_head = false, beside_head = false, across_torso = false, yaw = false;
};

struct MotionPlan {
  std::vector<ArmPose> poses;  // one per motion frame
  bool over_head = false, beside_head = false, across_torso = false, yaw = false, raised = false;
};

// Keyframe poses joined by minimum-jerk moves, starting from the hanging arm. Every pose keeps
// the moving arm clear of the body and `in_frame(points, keyframe)` true (the arm's points in
// the body frame; a keyframe keeps the hand in the frame as well, a pose between keyframes the
// elbow and the wrist).
MotionPlan PlanMotion(const Person& person, double side, const MotionSpec& spec,
                      const std::function<bool(const ArmPoints&, bool)>& in_frame, Rng* rng);

// Everything the seed and the tier drew, before the motion is planned.
struct SceneModel {
  CapsuleSceneParams params;
  Person person;
  Camera camera;
  Room room;
  Light light_a, light_b;   // the key light at the first and the last frame
  BodyPlacement placement;  // at rest
  MotionSpec motion;
  cv::Vec3f cast{0, 0, 0};  // colour cast reached at the last frame, per channel
  double sway_phase = 0, nod_amp_rad = 0, tilt_amp_rad = 0;
};

SceneModel DrawScene(const CapsuleArmSceneOptions& options);

// A colour from hue (degrees), saturation and value (0..1): BGR 0..255.
cv::Vec3f HsvColour(double hue, double sat, double val);
double ColourDistance(const cv::Vec3f& a, const cv::Vec3f& b);

}  // namespace armmimic::synth::capsule
