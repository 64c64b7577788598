// RandomArmScene: a scene drawn from a seed and a tier (random_scene_params.cpp), its motion
// (random_motion.cpp) and room (random_room.cpp), rendered frame by frame.
#include "armmimic/synth/random_arm_scene.h"
#include "armmimic/core/text.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "random_scene_model.h"

namespace armmimic::synth {

using namespace random_scene;  // NOLINT: this file implements the random_scene model

const char* SceneTierName(SceneTier tier) {
  switch (tier) {
    case SceneTier::kEasy:
      return "easy";
    case SceneTier::kMedium:
      return "medium";
    case SceneTier::kHard:
      return "hard";
  }
  return "medium";
}

bool ParseSceneTier(const std::string& name, SceneTier* out) {
  return ParseByName(name, {SceneTier::kEasy, SceneTier::kMedium, SceneTier::kHard}, SceneTierName,
                     out);
}

Status RandomArmSceneOptions::Check() const {
  if (size.width < 160 || size.height < 120 || size.width > 4096 || size.height > 4096) {
    return Status::Error("arm_scene.size", "size " + std::to_string(size.width) + "x" +
                                               std::to_string(size.height) +
                                               " is out of range (160x120 to 4096x4096)");
  }
  if (size.width * 3 < size.height * 4) {
    return Status::Error("arm_scene.size",
                         "size " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                             " is narrower than 4:3 (the straight arm must fit beside the body)");
  }
  return Status::Ok();
}

struct RandomArmScene::Impl {
  RandomArmSceneOptions opt;
  SceneDraw d;
  RandomMotion motion;
  cv::Mat room;       // canonical, CV_32FC3
  cv::Mat room_body;  // the room with the body standing still in it
  cv::Rect body_box;  // where the body layer has any coverage
  cv::Mat vignette;   // CV_32FC1
  PersonTextures tex;
  Layer body;
  uint64_t noise_seed = 0;

  const RandomSceneParams& p() const { return d.params; }
  int first_motion() const { return p().background_frames + p().standstill_frames; }
  int frame_count() const { return first_motion() + p().motion_frames; }
  double MotionTime(int frame) const { return (frame - first_motion()) / p().fps; }

  Pose PoseAt(int frame) const {
    const int i = frame - first_motion();
    return i < 0 ? Pose{} : motion.At(i);
  }

  // The body's sway: zero until the motion starts, then growing in over a second.
  cv::Point2d Sway(int frame) const {
    const double t = MotionTime(frame);
    if (t <= 0 || p().sway_px <= 0) return {0, 0};
    const double r = std::min(1.0, t) * p().sway_px;
    return {r * std::sin(2 * CV_PI * t / d.sway_period_s[0] + d.sway_phase[0]),
            0.4 * r * std::sin(2 * CV_PI * t / d.sway_period_s[1] + d.sway_phase[1])};
  }

  double Nod(int frame) const {
    const double t = MotionTime(frame);
    if (t <= 0 || d.nod_deg <= 0) return 0;
    return std::min(1.0, t) * d.nod_deg * std::sin(2 * CV_PI * t / d.nod_period_s);
  }

  cv::Vec3f Gain(int frame) const {
    const double u = frame_count() > 1 ? static_cast<double>(frame) / (frame_count() - 1) : 0.0;
    const double g = 1 + p().drift * u +
                     p().flicker * std::sin(2 * CV_PI * frame / (p().fps * d.flicker_period_s) +
                                            d.flicker_phase);
    cv::Vec3f out;
    for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(g * (1 + d.colour_cast[c] * u));
    return out;
  }

  ShadowSpot ShadowAt(int frame) const {
    ShadowSpot s;
    const int i = frame - first_motion();
    if (!p().shadow || i < 0) return s;
    const double u = static_cast<double>(i) / std::max(1, p().motion_frames);
    s.on = true;
    s.centre = d.shadow_from + (d.shadow_to - d.shadow_from) * u;
    s.sigma = d.shadow_sigma;
    s.strength = p().shadow_strength * std::min(1.0, i / std::max(1.0, 0.3 * p().fps));
    return s;
  }

  // Places the camouflage object behind one segment of the arm at one moment of its motion.
  // A moment is drawn where that segment's middle is clear of the torso (an object there would
  // hide behind the body).
  void AimCamouflage(cv::RNG& rng) {
    const int n = p().motion_frames;
    const bool fore = p().short_sleeves || rng.uniform(0, 2) == 1;
    const PersonModel& m = d.person;
    cv::Point2d a, b;
    for (int attempt = 0; attempt < 20; ++attempt) {
      const int i = rng.uniform(n / 4, std::max(n / 4 + 1, 3 * n / 4));
      const ArmJoints j = JointsOf(m, motion.At(i), {0, 0});
      a = fore ? j.elbow : j.shoulder, b = fore ? j.wrist : j.elbow;
      const cv::Point2d mid = (a + b) * 0.5;
      if (std::fabs(mid.x - m.cx) > (m.w + 8) * m.s || mid.y < m.ysh - 15 * m.s) break;
    }
    d.room.camo_at = (a + b) * 0.5;
    d.room.camo_size = cv::norm(b - a);
    const cv::Vec3f& c = fore && p().short_sleeves ? d.person.skin : d.person.sleeve;
    d.room.camo_colour = c * kLimbShade;
  }

  // Motion features measured on the drawn motion and the painted room.
  void MeasureFeatures(const RoomSpec& room) {
    RandomSceneParams& q = d.params;
    q.furniture = static_cast<int>(room.objects.size()) - (q.camouflage == "object" ? 1 : 0);
    Pose prev = PoseAt(first_motion() - 1);
    for (int f = first_motion(); f < frame_count(); ++f) {
      const Pose pose = PoseAt(f);
      q.max_step_deg =
          std::max({q.max_step_deg, std::fabs(pose.upper_deg - prev.upper_deg),
                    std::fabs(pose.upper_deg + pose.bend_deg - prev.upper_deg - prev.bend_deg)});
      q.raised |= pose.upper_deg > 10;
      prev = pose;
      const ArmJoints j = JointsOf(d.person, pose, {0, 0});
      for (const RoomObject& o : room.objects) {
        for (const cv::Point2d& pt :
             {(j.shoulder + j.elbow) * 0.5, j.elbow, (j.elbow + j.wrist) * 0.5, j.wrist}) {
          q.furniture_behind_arm |= o.box.contains(pt);
        }
      }
    }
  }

  cv::Mat Compose(int frame, bool person, const Pose& pose, bool effects, uint64_t salt,
                  cv::Mat* arm_mask) const {
    const cv::Size size = opt.size;
    thread_local cv::Mat canvas;  // reused: a frame's light is built in place
    const cv::Point2d offset = effects ? Sway(frame) : cv::Point2d(0, 0);
    const bool swayed = person && offset != cv::Point2d(0, 0);
    (person && !swayed ? room_body : room).copyTo(canvas);
    if (swayed) {
      // The body moved by a sub-pixel offset: warp only its bounding box.
      const int margin = cvCeil(std::max(std::fabs(offset.x), std::fabs(offset.y))) + 2;
      const cv::Rect r = (body_box + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin)) &
                         cv::Rect(0, 0, size.width, size.height);
      const cv::Matx23d shift(1, 0, offset.x, 0, 1, offset.y);
      Layer moved;
      cv::warpAffine(body.color(r), moved.color, shift, r.size(), cv::INTER_LINEAR,
                     cv::BORDER_CONSTANT, cv::Scalar::all(0));
      cv::warpAffine(body.alpha(r), moved.alpha, shift, r.size(), cv::INTER_LINEAR,
                     cv::BORDER_CONSTANT, cv::Scalar::all(0));
      cv::Mat under = canvas(r);
      Over(moved, &under);
    }
    if (person) {
      Layer layer{canvas, cv::Mat()};
      PaintHead(&layer, d.person, tex, offset, effects ? Nod(frame) : 0.0);
      const ArmJoints j = JointsOf(d.person, pose, offset);
      PaintMovingArm(&layer, d.person, tex, j);
      if (arm_mask) {
        Layer mask{cv::Mat(size, CV_32FC3, cv::Scalar::all(0)), cv::Mat(size, CV_32FC1, 0.0f)};
        PaintMovingArm(&mask, d.person, tex, j);
        *arm_mask = mask.alpha;
      }
    } else if (arm_mask) {
      *arm_mask = cv::Mat(size, CV_32FC1, 0.0f);
    }
    cv::Mat out =
        Expose(canvas, vignette, effects ? Gain(frame) : cv::Vec3f(1, 1, 1),
               effects ? ShadowAt(frame) : ShadowSpot{}, p().noise_sigma, Mix(noise_seed, salt));
    if (p().side == ArmSide::kLeft) {
      cv::flip(out, out, 1);
      if (arm_mask) cv::flip(*arm_mask, *arm_mask, 1);
    }
    return out;
  }

  ArmTruth MakeTruth(int frame, bool person, const Pose& pose, cv::Point2d offset) const {
    ArmTruth t;
    t.frame = frame;
    t.time_s = frame / p().fps;
    t.person = person;
    if (!person) return t;
    const ArmJoints j = JointsOf(d.person, pose, offset);
    cv::Point2d sh = j.shoulder, e = j.elbow, w = j.wrist;
    double upper = pose.upper_deg, fore = pose.upper_deg + pose.bend_deg;
    if (p().side == ArmSide::kLeft) {
      const double W1 = opt.size.width - 1;
      sh.x = W1 - sh.x, e.x = W1 - e.x, w.x = W1 - w.x;
      upper = 180 - upper, fore = 180 - fore;
    }
    t.upper_deg = Wrap180(upper);
    t.fore_deg = Wrap180(fore);
    t.bend_deg = AngleDiff(t.fore_deg, t.upper_deg);
    t.yaw_deg = 0;
    t.shoulder_px = sh;
    t.elbow_px = e;
    t.wrist_px = w;
    return t;
  }
};

RandomArmScene::RandomArmScene(const RandomArmSceneOptions& options)
    : impl_(std::make_unique<Impl>()) {
  const Status st = options.Check();
  if (!st.ok()) throw std::invalid_argument("RandomArmSceneOptions: " + st.message());
  Impl& m = *impl_;
  m.opt = options;
  m.d = DrawScene(options);
  const uint64_t scene_seed = Mix(options.seed, 0x5CE4E + static_cast<uint64_t>(options.tier));
  m.noise_seed = Mix(scene_seed, 0x4015E);
  cv::RNG motion_rng(Mix(scene_seed, 0x307104));
  m.motion = PlanRandomMotion(motion_rng, m.d.motion, m.d.person, options.size, &m.d.params);
  cv::RNG room_rng(Mix(scene_seed, 0x2003));
  if (m.d.room.camouflage_object) m.AimCamouflage(room_rng);
  const RoomSpec room = DrawRoom(room_rng, m.d.room, m.d.person, options.size, m.d.wall);
  m.room = PaintRoom(room, options.size, scene_seed);
  m.MeasureFeatures(room);
  m.d.params.wall_texture = room.texture;
  m.vignette = VignetteMap(options.size, m.p().vignetting);
  cv::RNG tex_rng(Mix(scene_seed, 0x7E47));
  m.tex.fabric = MakeTexture(tex_rng, 0.06f, 0.7);
  m.tex.skin = MakeTexture(tex_rng, 0.025f, 1.2);
  m.body.color = cv::Mat(options.size, CV_32FC3, cv::Scalar::all(0));
  m.body.alpha = cv::Mat(options.size, CV_32FC1, cv::Scalar(0));
  PaintStaticBody(&m.body, m.d.person, m.tex);
  m.body_box = cv::boundingRect(m.body.alpha > 0);
  m.room_body = m.room.clone();
  Over(m.body, &m.room_body);
}

RandomArmScene::~RandomArmScene() = default;

const RandomArmSceneOptions& RandomArmScene::options() const { return impl_->opt; }
const RandomSceneParams& RandomArmScene::params() const { return impl_->p(); }
cv::Size RandomArmScene::size() const { return impl_->opt.size; }
double RandomArmScene::fps() const { return impl_->p().fps; }
int RandomArmScene::background_frames() const { return impl_->p().background_frames; }
int RandomArmScene::standstill_frames() const { return impl_->p().standstill_frames; }
int RandomArmScene::motion_frames() const { return impl_->p().motion_frames; }
double RandomArmScene::upper_length_px() const { return impl_->p().upper_px; }
double RandomArmScene::fore_length_px() const { return impl_->p().fore_px; }

ArmTruth RandomArmScene::Truth(int frame) const {
  const bool person = frame >= background_frames();
  return impl_->MakeTruth(frame, person, impl_->PoseAt(frame), impl_->Sway(frame));
}

cv::Mat RandomArmScene::Render(int frame, ArmTruth* truth) const {
  if (frame < 0 || frame >= frame_count()) {
    throw std::out_of_range("RandomArmScene::Render: frame " + std::to_string(frame) +
                            " outside 0.." + std::to_string(frame_count() - 1));
  }
  const bool person = frame >= background_frames();
  const Pose pose = impl_->PoseAt(frame);
  if (truth) *truth = impl_->MakeTruth(frame, person, pose, impl_->Sway(frame));
  return impl_->Compose(frame, person, pose, true, static_cast<uint64_t>(frame) + 1, nullptr);
}

cv::Mat RandomArmScene::ArmMask(int frame) const {
  if (frame < 0 || frame >= frame_count()) {
    throw std::out_of_range("RandomArmScene::ArmMask: frame " + std::to_string(frame) +
                            " outside 0.." + std::to_string(frame_count() - 1));
  }
  cv::Mat mask;
  impl_->Compose(frame, frame >= background_frames(), impl_->PoseAt(frame), true, 1, &mask);
  return mask;
}

cv::Mat RandomArmScene::ArmLengthImage(ArmTruth* truth) const {
  const Pose pose{0, 0};
  if (truth) {
    *truth = impl_->MakeTruth(0, true, pose, {0, 0});
    truth->time_s = 0;
  }
  return impl_->Compose(0, true, pose, false, 0xA11E57ULL, nullptr);
}

cv::Mat RandomArmScene::EmptyBackground() const {
  cv::Mat out = Expose(impl_->room, impl_->vignette, {1, 1, 1}, ShadowSpot{}, 0, 0);
  if (impl_->p().side == ArmSide::kLeft) cv::flip(out, out, 1);
  return out;
}

cv::Vec3f RandomArmScene::LimbColour(double along) const {
  const PersonModel& m = impl_->d.person;
  const double units = along * (m.upper + m.fore);
  return m.sleeve_cover >= 1 || units <= m.upper * m.sleeve_cover ? m.sleeve : m.skin;
}

}  // namespace armmimic::synth
