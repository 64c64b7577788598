// CapsuleArmScene: the capsule person in the room, frame by frame: the pose and placement of the
// moment, the ray-cast person over the room (with the person's shadow on the wall), then the
// camera: lighting drift, vignetting and sensor noise. Also the truth and the scene folder.
#include "armmimic/synth/capsule_arm_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "capsule_model.h"

namespace armmimic::synth {

using capsule::ArmPose;
using capsule::Capsule;

Status CapsuleArmSceneOptions::Check() const {
  if (tier == SceneTier::kEasy) {
    return Status::Error("arm_scene.tier",
                         "tier easy: capsule scenes have the tiers medium and hard");
  }
  if (size.width < 160 || size.height < 120 || size.width > 3840 || size.height > 2160) {
    return Status::Error("arm_scene.size", "size " + std::to_string(size.width) + "x" +
                                               std::to_string(size.height) +
                                               " is out of range (160x120 to 3840x2160)");
  }
  if (size.width * 3 < size.height * 4) {
    return Status::Error("arm_scene.size", "size " + std::to_string(size.width) + "x" +
                                               std::to_string(size.height) +
                                               " is narrower than 4:3");
  }
  return Status::Ok();
}

struct CapsuleArmScene::Impl {
  CapsuleArmSceneOptions options;
  capsule::SceneModel m;
  std::vector<ArmPose> poses;  // one per motion frame
  capsule::RoomView room_a, room_b;
  cv::Mat vignette;  // CV_32FC3 gain per pixel
  int total = 0;

  int First() const { return m.params.background_frames + m.params.standstill_frames; }
  double T01(int frame) const { return total > 1 ? static_cast<double>(frame) / (total - 1) : 0; }

  ArmPose PoseAt(int frame) const {
    const int i = frame - First();
    return i >= 0 ? poses[static_cast<size_t>(i)] : capsule::HangingPose(m.person);
  }

  // The body sways and the head nods during the motion, easing in over the first second.
  capsule::BodyPlacement PlacementAt(int frame) const {
    capsule::BodyPlacement b = m.placement;
    const double t = (frame - First()) / m.params.fps;
    if (t <= 0) return b;
    const double ease = std::min(1.0, t);
    const double ph = m.sway_phase;
    b.sway = cv::Vec3d(std::sin(2 * kPi * t / 2.7 + ph), 0.3 * std::sin(2 * kPi * t / 1.9 + ph),
                       0.4 * std::sin(2 * kPi * t / 3.3)) *
             (m.params.sway * ease);
    b.nod_rad = m.nod_amp_rad * ease * std::sin(2 * kPi * t / 2.3 + ph);
    b.tilt_rad = m.tilt_amp_rad * ease * std::sin(2 * kPi * t / 3.1);
    return b;
  }

  double LightMix(int frame) const {
    const double t = T01(frame);
    return t * t * (3 - 2 * t);
  }

  capsule::Light LightAt(int frame) const {
    capsule::Light l = m.light_a;
    l.position = m.light_a.position + (m.light_b.position - m.light_a.position) * LightMix(frame);
    return l;
  }

  capsule::ArmPoints JointsWorld(const ArmPose& pose, const capsule::BodyPlacement& b) const {
    capsule::ArmPoints a = capsule::ArmInBody(m.person, pose, b.side);
    a.shoulder = m.camera.ToCam(capsule::BodyToWorld(b, a.shoulder));
    a.elbow = m.camera.ToCam(capsule::BodyToWorld(b, a.elbow));
    a.wrist = m.camera.ToCam(capsule::BodyToWorld(b, a.wrist));
    a.tip = m.camera.ToCam(capsule::BodyToWorld(b, a.tip));
    return a;
  }

  ArmTruth TruthOf(int frame, const ArmPose& pose, const capsule::BodyPlacement& b) const {
    ArmTruth t;
    t.frame = frame;
    t.time_s = frame / m.params.fps;
    t.person = true;
    const capsule::ArmPoints a = JointsWorld(pose, b);
    t.shoulder_px = m.camera.Project(a.shoulder);
    t.elbow_px = m.camera.Project(a.elbow);
    t.wrist_px = m.camera.Project(a.wrist);
    t.upper_deg = DirectionDeg(t.shoulder_px, t.elbow_px);
    t.fore_deg = DirectionDeg(t.elbow_px, t.wrist_px);
    t.bend_deg = AngleDiff(t.fore_deg, t.upper_deg);
    const cv::Vec3d chord = a.wrist - a.shoulder;
    t.yaw_deg = DegFromRad(std::asin(std::min(1.0, std::abs(chord[2]) / capsule::Len(chord))));
    return t;
  }

  // The person (capsules in the camera frame) over `room`, 2x2 rays a pixel.
  void DrawPerson(const std::vector<Capsule>& caps, const capsule::Light& light,
                  cv::Mat* img) const {
    if (caps.empty()) return;
    cv::Rect box = caps[0].box;
    for (const Capsule& c : caps) box |= c.box;
    const cv::Vec3d light_cam = m.camera.ToCam(light.position);
    const double offs[4][2] = {{-0.125, -0.375}, {0.375, -0.125}, {0.125, 0.375}, {-0.375, 0.125}};
    for (int y = box.y; y < box.y + box.height; ++y) {
      cv::Vec3f* row = img->ptr<cv::Vec3f>(y);
      for (int x = box.x; x < box.x + box.width; ++x) {
        cv::Vec3f sum(0, 0, 0);
        int hits = 0;
        for (const auto& o : offs) {
          const cv::Vec3d d = m.camera.Ray(x + o[0], y + o[1]);
          double best = 1e18;
          const Capsule* hit = nullptr;
          for (const Capsule& c : caps) {
            if (!c.box.contains({x, y})) continue;
            const double t = capsule::IntersectCapsule({0, 0, 0}, d, c);
            if (t > 0 && t < best) best = t, hit = &c;
          }
          if (!hit) continue;
          sum += capsule::Shade(m.person, *hit, d * best, light_cam, light);
          ++hits;
        }
        if (hits > 0) row[x] = row[x] * (1.f - hits * 0.25f) + sum * 0.25f;
      }
    }
  }

  // The key light's shadow of the person on the room, softened; multiplies `img`.
  void DrawShadow(const std::vector<Capsule>& caps, const capsule::Light& light,
                  cv::Mat* img) const {
    const cv::Size size = img->size();
    const cv::Size half(size.width / 2, size.height / 2);
    const cv::Vec3d light_cam = m.camera.ToCam(light.position);
    const cv::Mat& points = room_a.point;
    const cv::Mat& normals = room_a.normal;
    cv::Mat mask(half, CV_32FC1, cv::Scalar(0));
    for (int y = 0; y < half.height; ++y) {
      for (int x = 0; x < half.width; ++x) {
        const cv::Vec3d p = points.at<cv::Vec3f>(2 * y, 2 * x);
        const cv::Vec3d n = normals.at<cv::Vec3f>(2 * y, 2 * x);
        const cv::Vec3d to = light_cam - p;
        const double dist = capsule::Len(to);
        const cv::Vec3d d = to * (1.0 / dist);
        if (capsule::Dot(n, d) <= 0) continue;
        const cv::Vec3d o = p + n * 1e-3;
        for (const Capsule& c : caps) {
          const double t = capsule::IntersectCapsule(o, d, c);
          if (t > 0 && t < dist) {
            mask.at<float>(y, x) = 1;
            break;
          }
        }
      }
    }
    cv::Mat full;
    cv::resize(mask, full, size, 0, 0, cv::INTER_LINEAR);
    const double sigma = 1.5 * size.width / 320.0;
    cv::GaussianBlur(full, full, cv::Size(0, 0), sigma);
    const float s = static_cast<float>(m.params.shadow_strength);
    for (int y = 0; y < size.height; ++y) {
      cv::Vec3f* row = img->ptr<cv::Vec3f>(y);
      const float* k = full.ptr<float>(y);
      for (int x = 0; x < size.width; ++x) row[x] *= 1.f - s * k[x];
    }
  }

  // The frame before noise, CV_32FC3.
  cv::Mat Compose(int frame, bool person, const ArmPose& pose,
                  const capsule::BodyPlacement& b) const {
    const double w = LightMix(frame);
    cv::Mat img;
    if (room_b.colour.empty()) {
      img = room_a.colour.clone();
    } else {
      cv::addWeighted(room_a.colour, 1 - w, room_b.colour, w, 0, img);
    }
    if (person) {
      const capsule::Light light = LightAt(frame);
      const std::vector<Capsule> caps =
          capsule::BuildPerson(m.person, b, pose, m.camera, options.size);
      if (m.params.shadow_strength > 0) DrawShadow(caps, light, &img);
      DrawPerson(caps, light, &img);
    }
    return img;
  }

  // Lighting drift (gain, flicker, colour cast), vignetting and sensor noise.
  cv::Mat Expose(const cv::Mat& img, int frame, uint64_t noise_salt) const {
    const double t = T01(frame);
    const double gain = 1 + m.params.drift * t +
                        m.params.flicker * std::sin(2 * kPi * frame / (m.params.fps * 3.1));
    const cv::Scalar g(gain * (1 + m.cast[0] * t), gain * (1 + m.cast[1] * t),
                       gain * (1 + m.cast[2] * t));
    cv::Mat out = img.mul(vignette);
    out = out.mul(cv::Mat(img.size(), CV_32FC3, g));
    cv::Mat noise(img.size(), CV_32FC3);
    cv::RNG rng(capsule::MixSeed(options.seed, noise_salt));
    rng.fill(noise, cv::RNG::NORMAL, 0, m.params.noise_sigma);
    out += noise;
    cv::Mat u8;
    out.convertTo(u8, CV_8UC3);
    return u8;
  }
};

CapsuleArmScene::CapsuleArmScene(const CapsuleArmSceneOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (Status st = options.Check(); !st.ok()) throw std::invalid_argument(st.message());
  Impl& s = *impl_;
  s.options = options;
  s.m = capsule::DrawScene(options);
  CapsuleSceneParams& q = s.m.params;
  s.total = q.background_frames + q.standstill_frames + q.motion_frames;
  const cv::Size size = options.size;
  // The motion keeps the elbow, wrist and hand in the frame as the person stands at rest.
  const double margin = 0.03 * size.width;
  auto in_frame = [&s, size, margin](const capsule::ArmPoints& a, bool keyframe) {
    for (const cv::Vec3d& p : {a.elbow, a.wrist, keyframe ? a.tip : a.wrist}) {
      const cv::Vec3d c = s.m.camera.ToCam(capsule::BodyToWorld(s.m.placement, p));
      if (c[2] < 0.2) return false;
      const cv::Point2d q = s.m.camera.Project(c);
      if (q.x < margin || q.y < margin || q.x > size.width - 1 - margin ||
          q.y > size.height - 1 - margin) {
        return false;
      }
    }
    return true;
  };
  capsule::Rng rng(capsule::MixSeed(options.seed, 0x407104));
  const capsule::MotionPlan plan =
      capsule::PlanMotion(s.m.person, s.m.placement.side, s.m.motion, in_frame, &rng);
  s.poses = plan.poses;
  q.hand_over_head = plan.over_head;
  q.beside_head = plan.beside_head;
  q.across_torso = plan.across_torso;
  q.yaw_move = plan.yaw;
  q.raised = plan.raised;
  // Room images at the light's two ends, and the vignette.
  s.room_a = capsule::RenderRoom(s.m.room, s.m.camera, s.m.light_a, size);
  if (q.light_move > 0) {
    s.room_b = capsule::RenderRoom(s.m.room, s.m.camera, s.m.light_b, size);
  }
  s.vignette.create(size, CV_32FC3);
  const double rmax = std::hypot(size.width / 2.0, size.height / 2.0);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const double r = std::hypot(x - s.m.camera.cx, y - s.m.camera.cy) / rmax;
      const float v = static_cast<float>(1 - q.vignetting * r * r);
      s.vignette.at<cv::Vec3f>(y, x) = {v, v, v};
    }
  }
  // The largest change of a projected direction between two frames, and the arm-length image's
  // segment lengths.
  for (int f = s.First() + 1; f < s.total; ++f) {
    const ArmTruth a = Truth(f - 1), b = Truth(f);
    q.max_step_deg = std::max({q.max_step_deg, std::abs(AngleDiff(b.upper_deg, a.upper_deg)),
                               std::abs(AngleDiff(b.fore_deg, a.fore_deg))});
  }
  ArmTruth al;
  ArmLengthImage(&al);
  q.upper_length_px = cv::norm(al.elbow_px - al.shoulder_px);
  q.fore_length_px = cv::norm(al.wrist_px - al.elbow_px);
}

CapsuleArmScene::~CapsuleArmScene() = default;

const CapsuleArmSceneOptions& CapsuleArmScene::options() const { return impl_->options; }
const CapsuleSceneParams& CapsuleArmScene::params() const { return impl_->m.params; }
cv::Size CapsuleArmScene::size() const { return impl_->options.size; }
double CapsuleArmScene::fps() const { return impl_->m.params.fps; }
int CapsuleArmScene::background_frames() const { return impl_->m.params.background_frames; }
int CapsuleArmScene::standstill_frames() const { return impl_->m.params.standstill_frames; }
int CapsuleArmScene::motion_frames() const { return impl_->m.params.motion_frames; }
double CapsuleArmScene::upper_length_px() const { return impl_->m.params.upper_length_px; }
double CapsuleArmScene::fore_length_px() const { return impl_->m.params.fore_length_px; }

ArmTruth CapsuleArmScene::Truth(int frame) const {
  if (frame < 0 || frame >= impl_->total) throw std::out_of_range("capsule scene frame");
  if (frame < impl_->m.params.background_frames) {
    ArmTruth t;
    t.frame = frame;
    t.time_s = frame / impl_->m.params.fps;
    return t;
  }
  return impl_->TruthOf(frame, impl_->PoseAt(frame), impl_->PlacementAt(frame));
}

cv::Mat CapsuleArmScene::Render(int frame, ArmTruth* truth) const {
  const ArmTruth t = Truth(frame);
  if (truth) *truth = t;
  const Impl& s = *impl_;
  const cv::Mat img = s.Compose(frame, t.person, s.PoseAt(frame), s.PlacementAt(frame));
  return s.Expose(img, frame, 0x10000 + static_cast<uint64_t>(frame));
}

cv::Mat CapsuleArmScene::ArmLengthImage(ArmTruth* truth) const {
  const Impl& s = *impl_;
  // The arm straight along the camera's x axis (world X): parallel to the image plane.
  const capsule::BodyPlacement b = s.m.placement;
  const double c = std::cos(-b.yaw_rad), sn = std::sin(-b.yaw_rad);
  const cv::Vec3d dir(c * b.side, 0, -sn * b.side);
  const ArmPose pose = capsule::PoseFromDirections(dir, dir, b.side);
  const int frame = s.m.params.background_frames;
  if (truth) *truth = s.TruthOf(frame, pose, b);
  return s.Expose(s.Compose(frame, true, pose, b), frame, 0xA4A4);
}

cv::Mat CapsuleArmScene::EmptyBackground() const {
  cv::Mat out = impl_->room_a.colour.mul(impl_->vignette);
  cv::Mat u8;
  out.convertTo(u8, CV_8UC3);
  return u8;
}

cv::Mat CapsuleArmScene::PartLabels(int frame) const {
  const Impl& s = *impl_;
  const cv::Size size = s.options.size;
  cv::Mat labels(size, CV_8UC1, cv::Scalar(kPartRoom));
  if (!Truth(frame).person) return labels;
  const std::vector<Capsule> caps =
      capsule::BuildPerson(s.m.person, s.PlacementAt(frame), s.PoseAt(frame), s.m.camera, size);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const cv::Vec3d d = s.m.camera.Ray(x, y);
      double best = 1e18;
      for (const Capsule& c : caps) {
        if (!c.box.contains({x, y})) continue;
        const double t = capsule::IntersectCapsule({0, 0, 0}, d, c);
        if (t > 0 && t < best) {
          best = t;
          labels.at<uint8_t>(y, x) = c.part;
        }
      }
    }
  }
  return labels;
}

CapsuleJoints3d CapsuleArmScene::Joints3d(int frame) const {
  const Impl& s = *impl_;
  const int f = std::max(frame, s.m.params.background_frames);
  const capsule::ArmPoints a = s.JointsWorld(s.PoseAt(f), s.PlacementAt(f));
  return {a.shoulder, a.elbow, a.wrist};
}

cv::Point2d CapsuleArmScene::Project(const cv::Vec3d& camera_point) const {
  return impl_->m.camera.Project(camera_point);
}

}  // namespace armmimic::synth
