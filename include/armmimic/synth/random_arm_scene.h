// Randomised arm scenes (`armmimic-cli synth arm --random`): a seed and a tier draw the whole
// scene, not just its colours: where the person stands and how big they are, their proportions
// and clothing (long or short sleeves, skin tone), the room and its furniture (some of it behind
// the arm's path, some coloured like the sleeve or the skin), the camera (noise, vignetting,
// compression, lighting drift, a moving shadow), the frame rate and the motion (the hand beside
// and above the head, the forearm across the torso, fast swings, a swaying body).
//
// The scenes keep the thesis protocol of ArmSceneSource. docs/synth.md lists what each tier
// draws; docs/accuracy.md the seed ranges for tuning and for held-out measurements.
#pragma once

#include <atomic>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/synth/arm_scene_source.h"

namespace armmimic::synth {

enum class SceneTier { kEasy, kMedium, kHard };

const char* SceneTierName(SceneTier tier);  // "easy", "medium", "hard"
bool ParseSceneTier(const std::string& name, SceneTier* out);

// Seeds the engines may be tuned on, and seeds kept for measurement only: no code or default is
// ever changed because of a scene from the held-out range (docs/accuracy.md).
inline constexpr uint64_t kTuningSeedFirst = 1000;
inline constexpr uint64_t kTuningSeedLast = 1999;
inline constexpr uint64_t kHeldOutSeedFirst = 100000;
inline constexpr uint64_t kHeldOutSeedLast = 100999;
// Seeds of the fixed scenes the unit tests hold to a bound; open for tuning as well.
inline constexpr uint64_t kUnitSeedFirst = 7000;
inline constexpr uint64_t kUnitSeedLast = 7999;

struct RandomArmSceneOptions {
  uint64_t seed = 1;
  SceneTier tier = SceneTier::kMedium;
  cv::Size size{320, 240};
  // Checks ranges; the message names the option ("size 100x80 is out of range ...").
  Status Check() const;
};

// Everything the seed drew for one scene. Lengths are in pixels of the scene's frame size.
struct RandomSceneParams {
  // Recording.
  double fps = 30;
  int background_frames = 45;
  int standstill_frames = 60;
  int motion_frames = 180;
  // Person.
  ArmSide side = ArmSide::kRight;
  double arm_fraction = 0.35;  // shoulder-to-wrist length over the frame height
  double upper_px = 44, fore_px = 38, hand_px = 12;
  double offcentre = 0;       // |body centre - frame centre| / frame width
  double body_width = 1;      // shoulder width, relative to the reference figure
  double head_size = 1;       // head radius, relative
  double neck = 1;            // neck length, relative
  double limb_thickness = 1;  // limb radii, relative
  bool short_sleeves = false;
  double sleeve_cover = 1;  // share of the upper arm inside the sleeve (1: long sleeves)
  double skin_tone = 0.3;   // 0 light .. 1 dark
  // Clothing against its surroundings: the sleeve is the shirt's cloth ("shirt"), another cloth
  // ("distinct") or close to the wall's colour ("wall").
  std::string sleeve_match = "shirt";
  // What the arm is camouflaged against: "none", "object" (a piece of furniture or a poster
  // behind the arm's path in the sleeve's or skin's colour), "wall" (the sleeve close to the
  // wall's colour) or "shirt" (the sleeve in the shirt's cloth with the forearm across it).
  std::string camouflage = "none";
  double sleeve_wall_distance = 0;  // BGR distance between the lit sleeve and the wall behind
  double skin_wall_distance = 0;    // the same for the skin
  // Room.
  std::string wall_texture = "plaster";  // plaster, stripes, panel, bricks, tiles
  int furniture = 0;                     // pieces of furniture, posters, doors, windows, shelves
  bool furniture_behind_arm = false;     // at least one of them overlaps the arm's reach
  // Camera and light.
  double vignetting = 0;   // darkening at the corners, 0..1
  double noise_sigma = 1;  // Gaussian sensor noise, grey levels
  int jpeg_quality = 90;   // compression of the video (MJPG) and of the benchmark's frames
  double drift = 0;        // gain change over the video (1 -> 1 + drift), plus flicker in hard
  double flicker = 0;      // amplitude of a slow gain oscillation
  bool shadow = false;     // a soft shadow crossing the wall and the person during the motion
  double shadow_strength = 0;
  double sway_px = 0;  // amplitude of the body's sway during the motion
  bool head_motion = false;
  // Motion: the tier's speed limit and what the drawn motion does.
  double speed_limit_deg = 4;  // peak change of a segment's direction, degrees a frame
  double max_step_deg = 0;     // the largest change between two frames in this scene
  bool hand_by_head = false;
  bool hand_above_head = false;
  bool across_torso = false;
  bool raised = false;  // the arm raised above the horizontal

  // The knobs as key=value pairs: the truth file's meta line and the benchmark's columns.
  AngleMeta Describe() const;
};

class RandomArmScene : public ArmSceneSource {
 public:
  // Throws std::invalid_argument when options.Check() fails.
  explicit RandomArmScene(const RandomArmSceneOptions& options);
  ~RandomArmScene() override;
  RandomArmScene(const RandomArmScene&) = delete;
  RandomArmScene& operator=(const RandomArmScene&) = delete;

  const RandomArmSceneOptions& options() const;
  const RandomSceneParams& params() const;

  cv::Size size() const override;
  double fps() const override;
  int background_frames() const override;
  int standstill_frames() const override;
  int motion_frames() const override;
  ArmTruth Truth(int frame) const override;
  // Uncompressed; the video (and the benchmark) compress it with params().jpeg_quality.
  cv::Mat Render(int frame, ArmTruth* truth = nullptr) const override;
  cv::Mat ArmLengthImage(ArmTruth* truth = nullptr) const override;
  cv::Mat EmptyBackground() const override;
  double upper_length_px() const override;
  double fore_length_px() const override;
  // Coverage of the moving arm (upper arm, forearm and hand) in `frame`, CV_32FC1 0..1, in the
  // frame's orientation; zero on the empty frames.
  cv::Mat ArmMask(int frame) const;
  // The colour the moving arm was painted with at `along` (0 shoulder .. 1 wrist), before
  // shading and lighting: the sleeve or the skin.
  cv::Vec3f LimbColour(double along) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The image after a JPEG encode and decode at `quality` (1..100), as a compressed video frame.
cv::Mat JpegRoundTrip(const cv::Mat& image, int quality);

// The truth file's meta line of a random scene: scene=arm random=1 seed=... tier=... and the
// segment lengths, then the knobs.
AngleMeta RandomSceneMeta(const RandomArmScene& scene);

// Writes the scene folder (see WriteSceneFolder): scene.avi is MJPG at params().jpeg_quality.
Status WriteRandomArmScene(const RandomArmSceneOptions& options, const std::string& outdir,
                           const std::function<void(int, int)>& progress,
                           const std::atomic<bool>* cancel = nullptr);

}  // namespace armmimic::synth
