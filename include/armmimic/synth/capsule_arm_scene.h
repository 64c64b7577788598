// Capsule arm scenes (`armmimic-cli synth arm --generator capsule`): a second scene generator,
// written apart from the painted figures of ArmSceneRenderer and RandomArmScene so that an engine
// tuned on those can be measured on scenes it has never met.
//
// The person is a body of shaded 3-D capsules (sphere-swept segments: torso, neck, head, hair,
// legs, both arms and hands) standing in a room in front of a textured wall, seen through a
// perspective pinhole camera and ray cast pixel by pixel, so nearer limbs hide farther ones and
// a limb turned towards the camera looks shorter. The seed and the tier (medium or hard) draw the
// proportions, the clothing (sleeveless, short or long sleeves, patterned shirts, a shirt in the
// skin's colour), the hair, the wall's texture, the camera, where the person stands, which arm
// moves, the lighting drift and the motion (the hand over the head against the hair, across the
// torso, out of the image plane).
//
// The scenes follow the thesis protocol of ArmSceneSource: 45 empty-room frames, a 60-frame
// standstill with both arms hanging, then the motion; the arm-length image shows the moving arm
// straight and horizontal, parallel to the image plane. docs/synth.md lists what each tier draws.
#pragma once

#include <atomic>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/synth/arm_scene_source.h"
#include "armmimic/synth/random_arm_scene.h"

namespace armmimic::synth {

// Seeds the engines may be tuned on, and seeds kept for measurement only: no code or default is
// ever changed because of a capsule scene from the held-out range (docs/synth.md).
inline constexpr uint64_t kCapsuleTuningSeedFirst = 3000;
inline constexpr uint64_t kCapsuleTuningSeedLast = 3999;
inline constexpr uint64_t kCapsuleHeldOutSeedFirst = 300000;
inline constexpr uint64_t kCapsuleHeldOutSeedLast = 300999;

struct CapsuleArmSceneOptions {
  uint64_t seed = 3000;
  SceneTier tier = SceneTier::kMedium;  // medium or hard
  cv::Size size{320, 240};
  // Checks ranges; the message names the option.
  Status Check() const;
};

// Everything the seed drew for one scene. Lengths in metres unless named _px.
struct CapsuleSceneParams {
  double fps = 30;
  int background_frames = 45;
  int standstill_frames = 60;
  int motion_frames = 240;
  ArmSide side = ArmSide::kRight;  // the moving arm's side of the image
  // Camera.
  double fov_deg = 60;   // horizontal field of view
  double pitch_deg = 0;  // positive: the camera looks down
  double camera_height = 1.4;
  double distance = 2.5;  // camera to the person's body plane
  // Person.
  double height = 1.75;
  double upper = 0.30, fore = 0.26, hand = 0.09;  // shoulder-elbow, elbow-wrist, hand
  double upper_radius = 0.05, fore_radius = 0.04, hand_radius = 0.032;
  double shoulder_half_width = 0.2;  // body centre line to the shoulder joint
  double torso_radius = 0.11;
  double head_radius = 0.1;
  double neck = 0.06;
  double body_yaw_deg = 0;         // the body turned about the vertical axis
  double offcentre = 0;            // |body centre - image centre| / image width, in the image
  std::string sleeves = "long";    // sleeveless, short, long
  double sleeve_cover = 1;         // share of the arm (shoulder to wrist) inside the sleeve
  std::string pattern = "plain";   // plain, hstripes, vstripes, checks, dots
  bool shirt_like_skin = false;    // the shirt in the skin's colour
  double shirt_skin_distance = 0;  // BGR distance between the shirt and the skin
  double arm_wall_distance = 0;    // ... between the moving arm's colour (upper arm) and the wall
  double skin_tone = 0.3;          // 0 light .. 1 dark
  std::string hair = "short";      // short, long, bun, bald
  // Room and light.
  std::string wall_texture = "paint";  // paint, bricks, tiles, wallpaper, wood, concrete
  double wall_distance = 0.8;          // behind the person
  int wall_objects = 0;
  double drift = 0;            // gain change over the video (1 -> 1 + drift)
  double flicker = 0;          // amplitude of a slow gain oscillation
  double light_move = 0;       // how far the key light travels over the video, metres
  double shadow_strength = 0;  // the person's shadow on the wall (0: none)
  double vignetting = 0;
  double noise_sigma = 2;
  int jpeg_quality = 80;
  double sway = 0;  // amplitude of the body's sway during the motion, metres
  bool head_motion = false;
  // Motion.
  double speed_limit_deg = 5;  // peak change of a direction, degrees a frame
  double max_tilt_deg = 10;    // segments out of the body's plane by up to this
  double max_step_deg = 0;     // the largest change of a projected direction between frames
  bool hand_over_head = false, beside_head = false, across_torso = false, yaw_move = false;
  bool raised = false;
  double upper_length_px = 0, fore_length_px = 0;  // in the arm-length image

  // The knobs as key=value pairs (the truth file's meta line).
  AngleMeta Describe() const;
};

// What a pixel of a capsule scene shows (PartLabels).
enum CapsulePart : uint8_t {
  kPartRoom = 0,
  kPartUpperArm = 1,  // the moving arm's upper arm
  kPartForearm = 2,
  kPartHand = 3,
  kPartBody = 4,  // anything else of the person
};

// The moving arm's joints in the camera's frame (x right, y down, z away from the camera),
// metres.
struct CapsuleJoints3d {
  cv::Vec3d shoulder, elbow, wrist;
};

class CapsuleArmScene : public ArmSceneSource {
 public:
  // Throws std::invalid_argument when options.Check() fails.
  explicit CapsuleArmScene(const CapsuleArmSceneOptions& options);
  ~CapsuleArmScene() override;
  CapsuleArmScene(const CapsuleArmScene&) = delete;
  CapsuleArmScene& operator=(const CapsuleArmScene&) = delete;

  const CapsuleArmSceneOptions& options() const;
  const CapsuleSceneParams& params() const;

  cv::Size size() const override;
  double fps() const override;
  int background_frames() const override;
  int standstill_frames() const override;
  int motion_frames() const override;
  ArmTruth Truth(int frame) const override;
  // Uncompressed; the video compresses it with params().jpeg_quality.
  cv::Mat Render(int frame, ArmTruth* truth = nullptr) const override;
  cv::Mat ArmLengthImage(ArmTruth* truth = nullptr) const override;
  cv::Mat EmptyBackground() const override;
  double upper_length_px() const override;
  double fore_length_px() const override;

  // What the ray through each pixel's centre hits first in `frame` (CapsulePart), CV_8UC1.
  cv::Mat PartLabels(int frame) const;
  // The moving arm's joints in `frame` (also on the empty frames, where nobody is drawn).
  CapsuleJoints3d Joints3d(int frame) const;
  // The camera: a point of its frame to pixels (pixel centres at integer coordinates).
  cv::Point2d Project(const cv::Vec3d& camera_point) const;
  // The truth file's extra columns of `frame`, in the order of CapsuleExtraColumns().
  std::array<double, 5> Extras(int frame) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The 3-D columns the truth file adds (the angle file's optional 3-D columns, contract round 4):
// upper_az_deg, upper_el_deg, fore_az_deg, fore_el_deg, elbow_deg.
const std::array<const char*, 5>& CapsuleExtraColumns();

// The truth file's meta line: scene=arm generator=capsule seed=... tier=... then the knobs.
AngleMeta CapsuleSceneMeta(const CapsuleArmScene& scene);

// Writes the scene folder (see WriteSceneFolder): scene.avi is MJPG at params().jpeg_quality and
// truth.tsv carries the 3-D columns.
Status WriteCapsuleArmScene(const CapsuleArmSceneOptions& options, const std::string& outdir,
                            const std::function<void(int, int)>& progress,
                            const std::atomic<bool>* cancel = nullptr);

}  // namespace armmimic::synth
