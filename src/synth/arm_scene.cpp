// The arm scene renderer: a textured room, a person facing the camera, one arm moving.
// Everything is drawn for an arm on the right of the image; the left side is the mirror image.
// Length: one renderer whose drawing steps share the person's layout and the room.
#include "armmimic/synth/arm_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "arm_motion.h"
#include "paint.h"

namespace armmimic::synth {

const char* ArmMotionName(ArmMotion m) {
  switch (m) {
    case ArmMotion::kSwing:
      return "swing";
    case ArmMotion::kBend:
      return "bend";
    case ArmMotion::kYaw:
      return "yaw";
    case ArmMotion::kMixed:
      return "mixed";
  }
  return "mixed";
}

bool ParseArmMotion(const std::string& name, ArmMotion* out) {
  for (ArmMotion m : {ArmMotion::kSwing, ArmMotion::kBend, ArmMotion::kYaw, ArmMotion::kMixed}) {
    if (name == ArmMotionName(m)) {
      *out = m;
      return true;
    }
  }
  return false;
}

const char* ArmSideName(ArmSide s) { return s == ArmSide::kLeft ? "left" : "right"; }

bool ParseArmSide(const std::string& name, ArmSide* out) {
  if (name == "right")
    *out = ArmSide::kRight;
  else if (name == "left")
    *out = ArmSide::kLeft;
  else
    return false;
  return true;
}

Status ArmSceneOptions::Check() const {
  auto err = [](const char* member, const std::string& m) {
    return Status::Error(std::string("arm_scene.") + member, m);
  };
  if (size.width < 160 || size.height < 120 || size.width > 4096 || size.height > 4096) {
    return err("size", "size " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                           " is out of range (160x120 to 4096x4096)");
  }
  if (!(fps > 0 && fps <= 240))
    return err("fps", "fps " + std::to_string(fps) + " is out of range (0, 240]");
  if (background_frames < 0 || background_frames > 100000) {
    return err("background_frames", "background frames " + std::to_string(background_frames) +
                                        " is out of range 0..100000");
  }
  if (standstill_frames < 0 || standstill_frames > 100000) {
    return err("standstill_frames", "standstill frames " + std::to_string(standstill_frames) +
                                        " is out of range 0..100000");
  }
  if (motion_frames < 1 || motion_frames > 100000) {
    return err("motion_frames",
               "motion frames " + std::to_string(motion_frames) + " is out of range 1..100000");
  }
  if (!(noise_sigma >= 0 && noise_sigma <= 50)) {
    return err("noise_sigma",
               "noise sigma " + std::to_string(noise_sigma) + " is out of range 0..50");
  }
  if (codec != "MJPG" && codec != "XVID" && codec != "H264") {
    return err("codec", "codec '" + codec + "' is not one of MJPG, XVID, H264");
  }
  if (jpeg_quality < 0 || jpeg_quality > 100) {
    return err("jpeg_quality",
               "quality " + std::to_string(jpeg_quality) + " is out of range 0..100");
  }
  if (!(clothing_contrast >= 0 && clothing_contrast <= 2)) {
    return err("clothing_contrast",
               "clothing contrast " + std::to_string(clothing_contrast) + " is out of range 0..2");
  }
  if (!(lighting_drift >= -0.9 && lighting_drift <= 2)) {
    return err("lighting_drift",
               "lighting drift " + std::to_string(lighting_drift) + " is out of range -0.9..2");
  }
  return Status::Ok();
}

TruthRow ArmTruth::ToRow() const {
  TruthRow r;
  r.frame = frame;
  r.time_s = time_s;
  r.upper_deg = upper_deg;
  r.fore_deg = fore_deg;
  r.yaw_deg = yaw_deg;
  r.bend_deg = bend_deg;
  r.shoulder_x = shoulder_px.x;
  r.shoulder_y = shoulder_px.y;
  r.elbow_x = elbow_px.x;
  r.elbow_y = elbow_px.y;
  r.wrist_x = wrist_px.x;
  r.wrist_y = wrist_px.y;
  return r;
}

struct ArmSceneRenderer::Impl {
  ArmSceneOptions opt;
  double s = 1;           // pixels per body unit (1 at 320x240)
  double cx = 0, y0 = 0;  // body origin: centre line and top of the 240-unit figure
  cv::Point2d shoulder;   // moving shoulder joint, canonical (right-side) image
  double upper_len = 0, fore_len = 0, hand_len = 0;
  cv::Mat background;  // CV_32FC3, canonical
  Layer body;          // torso, legs, the other arm, neck (premultiplied)
  cv::Vec3f shirt, skin, hair;
  Texture fabric, skin_tex;
  std::unique_ptr<ArmMotionPlan> plan;

  cv::Point2d P(double u, double v) const { return {cx + u * s, y0 + v * s}; }

  // Joint positions of a pose in the canonical image.
  void Joints(const ArmPose& pose, cv::Point2d* elbow, cv::Point2d* wrist, cv::Point2d* tip) const {
    const double k = std::cos(pose.yaw_deg * CV_PI / 180.0);
    *elbow = shoulder + DirectionVector(pose.upper_deg) * (upper_len * k);
    const double fore = pose.upper_deg + pose.bend_deg;
    *wrist = *elbow + DirectionVector(fore) * (fore_len * k);
    *tip = *wrist + DirectionVector(fore) * (hand_len * k);
  }

  bool Valid(const ArmPose& pose) const {
    const double fore = pose.upper_deg + pose.bend_deg;
    if (fore < -100 || fore > 150) return false;
    cv::Point2d e, w, t;
    Joints(pose, &e, &w, &t);
    const double m = 4 * s;
    for (const cv::Point2d& p : {e, w, t}) {
      if (p.x < m || p.y < m || p.x > opt.size.width - m || p.y > opt.size.height - m) return false;
    }
    // Keep the hand off the head and the chest.
    return w.x >= shoulder.x - 10 * s && t.x >= shoulder.x - 12 * s;
  }

  ArmPose PoseAt(int frame) const {
    const int i = frame - opt.first_motion_frame();
    if (i < 0) return ArmPose{};
    return plan->At(i);
  }

  cv::Point2d HeadOffset(int frame, double* tilt_deg) const {
    *tilt_deg = 0;
    const int i = frame - opt.first_motion_frame();
    if (!opt.head_motion || i <= 0) return {0, 0};
    const double r = std::min(1.0, i / 20.0);
    const double t = i / opt.fps;
    *tilt_deg = r * 6.0 * std::sin(2 * CV_PI * t / 2.9 + 0.3);
    return {r * 3.5 * s * std::sin(2 * CV_PI * t / 2.2),
            r * 1.8 * s * std::sin(2 * CV_PI * t / 1.3 + 0.7)};
  }

  void BuildBackground(cv::RNG& rng);
  void BuildBody();
  void PaintHead(Layer* canvas, int frame) const;
  void PaintArm(Layer* canvas, const ArmPose& pose) const;
  cv::Mat Compose(int frame, const ArmPose& pose, bool person, bool effects,
                  uint64_t noise_salt) const;
  ArmTruth MakeTruth(int frame, bool person, const ArmPose& pose) const;
};

void ArmSceneRenderer::Impl::BuildBackground(cv::RNG& rng) {
  const int W = opt.size.width, H = opt.size.height;
  const cv::Vec3f wall =
      Clamp255(cv::Vec3f(168, 190, 208) +
               cv::Vec3f(rng.uniform(-8.f, 8.f), rng.uniform(-8.f, 8.f), rng.uniform(-8.f, 8.f)));
  cv::Mat low(6, 8, CV_32FC1);
  rng.fill(low, cv::RNG::NORMAL, 0, 1);
  cv::resize(low, low, opt.size, 0, 0, cv::INTER_CUBIC);
  cv::Mat grain(opt.size, CV_32FC1);
  rng.fill(grain, cv::RNG::NORMAL, 0, 1);
  cv::GaussianBlur(grain, grain, cv::Size(), 0.8);
  background.create(opt.size, CV_32FC3);
  const double floor_y = y0 + 206 * s;
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const double gx = (x - 0.35 * W) / W;
      double k = (1.08 - 0.18 * y / H) * (1 - 0.1 * gx * gx) * (1 + 0.035 * low.at<float>(y, x));
      cv::Vec3f c = wall * static_cast<float>(k) + cv::Vec3f::all(3.0f * grain.at<float>(y, x));
      if (y >= floor_y) {
        // Wooden floor: planks with grain.
        const double plank = std::fmod((y - floor_y) / (9 * s), 1.0);
        const double seam = plank < 0.12 ? 0.8 : 1.0;
        c = cv::Vec3f(70, 105, 140) * static_cast<float>(seam * (1 + 0.06 * low.at<float>(y, x))) +
            cv::Vec3f::all(5.0f * grain.at<float>(y, x));
      } else if (y >= floor_y - 5 * s) {
        c = cv::Vec3f(212, 220, 228) + cv::Vec3f::all(2.0f * grain.at<float>(y, x));
      }
      background.at<cv::Vec3f>(y, x) = c;
    }
  }
  Layer bg{background, cv::Mat()};
  // A cabinet on the left with shelves and a knob.
  const double cab_x0 = 0.03 * W, cab_x1 = 0.22 * W, cab_y0 = y0 + 118 * s;
  const std::vector<cv::Point2d> cabinet{
      {cab_x0, cab_y0}, {cab_x1, cab_y0}, {cab_x1, floor_y}, {cab_x0, floor_y}};
  Texture wood = MakeTexture(rng, 0.08f, 0.6);
  PaintBody(&bg, cabinet, (cab_x0 + cab_x1) / 2, (cab_x1 - cab_x0), {45, 78, 118}, &wood);
  PaintBody(&bg,
            {{cab_x0 - 2 * s, cab_y0 - 3 * s},
             {cab_x1 + 2 * s, cab_y0 - 3 * s},
             {cab_x1 + 2 * s, cab_y0 + 2 * s},
             {cab_x0 - 2 * s, cab_y0 + 2 * s}},
            (cab_x0 + cab_x1) / 2, (cab_x1 - cab_x0), {70, 110, 150}, &wood);
  for (double f : {0.38, 0.7}) {
    const double yy = cab_y0 + f * (floor_y - cab_y0);
    PaintCapsule(&bg, {cab_x0 + 3 * s, yy}, {cab_x1 - 3 * s, yy}, 1.0 * s, 1.0 * s, {30, 50, 80},
                 nullptr);
  }
  PaintEllipse(&bg, {cab_x1 - 7 * s, cab_y0 + 0.2 * (floor_y - cab_y0)}, 1.8 * s, 1.8 * s, 0,
               {90, 170, 200}, nullptr);
  // A framed picture on the right of the wall.
  const double px0 = 0.74 * W, px1 = 0.93 * W, py0 = y0 + 30 * s, py1 = y0 + 78 * s;
  PaintBody(&bg, {{px0, py0}, {px1, py0}, {px1, py1}, {px0, py1}}, (px0 + px1) / 2, px1 - px0,
            {38, 40, 46}, nullptr);
  const cv::Rect inner(cvRound(px0 + 3 * s), cvRound(py0 + 3 * s), cvRound(px1 - px0 - 6 * s),
                       cvRound(py1 - py0 - 6 * s));
  if (inner.width > 2 && inner.height > 2) {
    cv::Mat art(inner.size(), CV_32FC3, cv::Scalar(150, 170, 120));
    for (int b = 0; b < 6; ++b) {
      const cv::Point c(rng.uniform(0, inner.width), rng.uniform(0, inner.height));
      cv::circle(art, c, rng.uniform(2, std::max(3, inner.height / 2)),
                 cv::Scalar(rng.uniform(40, 230), rng.uniform(40, 230), rng.uniform(40, 230)), -1);
    }
    cv::GaussianBlur(art, art, cv::Size(), 1.5 * s);
    art.copyTo(background(inner));
  }
  // Soft vignette.
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const double u = (x - W / 2.0) / W, v = (y - H / 2.0) / H;
      background.at<cv::Vec3f>(y, x) *= static_cast<float>(1 - 0.25 * (u * u + v * v));
    }
  }
}

void ArmSceneRenderer::Impl::BuildBody() {
  body.color = cv::Mat(opt.size, CV_32FC3, cv::Scalar::all(0));
  body.alpha = cv::Mat(opt.size, CV_32FC1, cv::Scalar(0));
  const cv::Vec3f trousers(58, 52, 48), belt(30, 45, 70);
  // Legs (cut by the frame's bottom edge), then the torso over them.
  for (double side : {-1.0, 1.0}) {
    PaintCapsule(&body, P(side * 12, 184), P(side * 14, 290), 12 * s, 11 * s, trousers, &fabric);
  }
  const std::vector<cv::Point2d> torso{P(-20, 85),  P(20, 85),   P(29, 89),  P(33, 97),
                                       P(31, 120),  P(25, 150),  P(24, 184), P(-24, 184),
                                       P(-25, 150), P(-31, 120), P(-33, 97), P(-29, 89)};
  PaintBody(&body, torso, cx, 34 * s, shirt, &fabric);
  PaintBody(&body, {P(-24.5, 178), P(24.5, 178), P(24.5, 186), P(-24.5, 186)}, cx, 30 * s, belt,
            nullptr);
  PaintCapsule(&body, P(0, 68), P(0, 90), 6.2 * s, 6.8 * s, skin, &skin_tex);
  // Collar over the neck's base.
  PaintEllipse(&body, P(0, 88), 9 * s, 3.5 * s, 0, shirt * 0.9f, &fabric);
  for (double side : {-1.0, 1.0})
    PaintEllipse(&body, P(side * 27, 99), 9 * s, 8.5 * s, 0, shirt, &fabric);
  // The other arm, hanging beside the body.
  const cv::Point2d os = P(-30, 100), oe = P(-32, 144), ow = P(-33, 182), oh = P(-33.5, 194);
  PaintCapsule(&body, os, oe, 7.5 * s, 5.8 * s, shirt, &fabric);
  PaintCapsule(&body, oe, ow, 5.6 * s, 4.3 * s, shirt, &fabric);
  PaintCapsule(&body, ow, oh, 4.6 * s, 3.6 * s, skin, &skin_tex);
}

void ArmSceneRenderer::Impl::PaintHead(Layer* canvas, int frame) const {
  double tilt = 0;
  const cv::Point2d off = HeadOffset(frame, &tilt);
  const cv::Point2d h = P(0, 58) + off;
  const double th = tilt * CV_PI / 180.0;
  auto rot = [&](double u, double v) {
    return h +
           cv::Point2d(u * std::cos(th) - v * std::sin(th), u * std::sin(th) + v * std::cos(th)) *
               s;
  };
  PaintEllipse(canvas, h, 13.5 * s, 16.5 * s, tilt, skin, &skin_tex);
  // Ears.
  for (double side : {-1.0, 1.0})
    PaintEllipse(canvas, rot(side * 13.5, 1), 2.2 * s, 3.5 * s, tilt, skin * 0.92f, nullptr);
  // Hair: a cap over the top of the head, the fringe line tilting with the head.
  PaintEllipse(canvas, rot(0, -5), 15 * s, 13.5 * s, tilt, hair, &fabric, {}, rot(0, -5).y + 2 * s);
  for (double side : {-1.0, 1.0}) {
    PaintEllipse(canvas, rot(side * 5, 0), 1.7 * s, 1.1 * s, tilt, {45, 40, 40}, nullptr);
    PaintCapsule(canvas, rot(side * 3, -4), rot(side * 7.5, -4.5), 0.7 * s, 0.6 * s, hair, nullptr);
  }
  PaintEllipse(canvas, rot(0, 9.5), 4 * s, 1.2 * s, tilt, {95, 95, 165}, nullptr);
}

void ArmSceneRenderer::Impl::PaintArm(Layer* canvas, const ArmPose& pose) const {
  cv::Point2d e, w, t;
  Joints(pose, &e, &w, &t);
  PaintCapsule(canvas, shoulder, e, 7.5 * s, 5.8 * s, shirt, &fabric);
  PaintCapsule(canvas, e, w, 5.6 * s, 4.3 * s, shirt, &fabric);
  // A darker cuff, then the hand.
  const cv::Point2d cuff = w + (e - w) * (2.0 * s / std::max(1.0, cv::norm(e - w)));
  PaintCapsule(canvas, cuff, w, 4.5 * s, 4.4 * s, shirt * 0.8f, &fabric);
  PaintCapsule(canvas, w, t, 4.6 * s, 3.6 * s, skin, &skin_tex);
}

cv::Mat ArmSceneRenderer::Impl::Compose(int frame, const ArmPose& pose, bool person, bool effects,
                                        uint64_t noise_salt) const {
  cv::Mat canvas = background.clone();
  const int i = frame - opt.first_motion_frame();
  if (effects && opt.shadow && i >= 0) {
    // A soft shadow drifting across the wall, as of someone passing a lamp.
    const double u = static_cast<double>(i) / std::max(1, opt.motion_frames);
    const double sx = 0.12 * opt.size.width, sy = 0.25 * opt.size.height;
    const double mx = (0.05 + 0.9 * u) * opt.size.width, my = 0.45 * opt.size.height;
    const cv::Rect roi =
        cv::Rect(cvFloor(mx - 3 * sx), cvFloor(my - 3 * sy), cvCeil(6 * sx), cvCeil(6 * sy)) &
        cv::Rect(0, 0, opt.size.width, opt.size.height);
    for (int y = roi.y; y < roi.y + roi.height; ++y) {
      for (int x = roi.x; x < roi.x + roi.width; ++x) {
        const double dx = (x - mx) / sx, dy = (y - my) / sy;
        canvas.at<cv::Vec3f>(y, x) *=
            static_cast<float>(1 - 0.32 * std::exp(-0.5 * (dx * dx + dy * dy)));
      }
    }
  }
  if (person) {
    Over(body, &canvas);
    Layer layer{canvas, cv::Mat()};
    PaintHead(&layer, effects ? frame : 0);
    PaintArm(&layer, pose);
  }
  if (effects && opt.lighting_drift != 0) {
    const int n = opt.frame_count();
    canvas *= 1.0 + opt.lighting_drift * (n > 1 ? static_cast<double>(frame) / (n - 1) : 0.0);
  }
  if (opt.noise_sigma > 0) {
    cv::RNG rng(Mix(opt.seed, noise_salt));
    cv::Mat noise(opt.size, CV_32FC3);
    rng.fill(noise, cv::RNG::NORMAL, 0, opt.noise_sigma);
    canvas += noise;
  }
  cv::Mat out;
  canvas.convertTo(out, CV_8UC3);
  if (opt.side == ArmSide::kLeft) cv::flip(out, out, 1);
  return out;
}

ArmTruth ArmSceneRenderer::Impl::MakeTruth(int frame, bool person, const ArmPose& pose) const {
  ArmTruth t;
  t.frame = frame;
  t.time_s = frame / opt.fps;
  t.person = person;
  if (!person) return t;
  cv::Point2d e, w, tip;
  Joints(pose, &e, &w, &tip);
  cv::Point2d sh = shoulder;
  double upper = pose.upper_deg, fore = pose.upper_deg + pose.bend_deg;
  if (opt.side == ArmSide::kLeft) {
    const double W1 = opt.size.width - 1;
    sh.x = W1 - sh.x, e.x = W1 - e.x, w.x = W1 - w.x;
    upper = 180 - upper, fore = 180 - fore;
  }
  t.upper_deg = Wrap180(upper);
  t.fore_deg = Wrap180(fore);
  t.bend_deg = AngleDiff(t.fore_deg, t.upper_deg);
  t.yaw_deg = pose.yaw_deg;
  t.shoulder_px = sh;
  t.elbow_px = e;
  t.wrist_px = w;
  return t;
}

ArmSceneRenderer::ArmSceneRenderer(const ArmSceneOptions& options)
    : impl_(std::make_unique<Impl>()) {
  const Status st = options.Check();
  if (!st.ok()) throw std::invalid_argument("ArmSceneOptions: " + st.message());
  Impl& m = *impl_;
  m.opt = options;
  const cv::Size sz = options.size;
  m.s = std::min(sz.width / 320.0, sz.height / 240.0);
  m.cx = sz.width / 2.0;
  m.y0 = sz.height - 240 * m.s;
  m.shoulder = m.P(30, 100);
  m.upper_len = 44 * m.s;
  m.fore_len = 38 * m.s;
  m.hand_len = 12 * m.s;
  cv::RNG rng(Mix(options.seed, 0xB6));
  m.BuildBackground(rng);
  m.fabric = MakeTexture(rng, 0.06f, 0.7);
  m.skin_tex = MakeTexture(rng, 0.025f, 1.2);
  const cv::Vec3f shirt_base = Clamp255(cv::Vec3f(122, 62, 36) + cv::Vec3f(rng.uniform(-12.f, 12.f),
                                                                           rng.uniform(-10.f, 10.f),
                                                                           rng.uniform(-8.f, 8.f)));
  m.skin = Clamp255(cv::Vec3f(118, 148, 198) * rng.uniform(0.85f, 1.05f));
  m.hair = Clamp255(cv::Vec3f(28, 38, 52) * rng.uniform(0.7f, 1.4f));
  // Clothing contrast: 1 keeps the shirt's own colour, 0 matches the wall where the arm moves.
  const cv::Rect arm_zone = cv::Rect(cvRound(m.shoulder.x - 10 * m.s), cvRound(m.y0 + 10 * m.s),
                                     cvRound(140 * m.s), cvRound(190 * m.s)) &
                            cv::Rect(0, 0, sz.width, sz.height);
  const cv::Scalar ref = cv::mean(m.background(arm_zone));
  const cv::Vec3f refv(static_cast<float>(ref[0]), static_cast<float>(ref[1]),
                       static_cast<float>(ref[2]));
  // The limbs' shading darkens their middle to about 0.86 of the colour: compensate, so that at
  // contrast 0 the lit sleeve matches the wall.
  const cv::Vec3f wall_like = refv / 0.86f;
  m.shirt = Clamp255(wall_like +
                     (shirt_base - wall_like) * static_cast<float>(options.clothing_contrast));
  m.BuildBody();
  m.plan = std::make_unique<ArmMotionPlan>(options.motion, options.motion_frames, options.seed,
                                           [&m](const ArmPose& p) { return m.Valid(p); });
}

ArmSceneRenderer::~ArmSceneRenderer() = default;

const ArmSceneOptions& ArmSceneRenderer::options() const { return impl_->opt; }
cv::Size ArmSceneRenderer::size() const { return impl_->opt.size; }
double ArmSceneRenderer::fps() const { return impl_->opt.fps; }
int ArmSceneRenderer::background_frames() const { return impl_->opt.background_frames; }
int ArmSceneRenderer::standstill_frames() const { return impl_->opt.standstill_frames; }
int ArmSceneRenderer::motion_frames() const { return impl_->opt.motion_frames; }

ArmTruth ArmSceneRenderer::Truth(int frame) const {
  const bool person = frame >= impl_->opt.background_frames;
  return impl_->MakeTruth(frame, person, impl_->PoseAt(frame));
}

cv::Mat ArmSceneRenderer::Render(int frame, ArmTruth* truth) const {
  if (frame < 0 || frame >= frame_count()) {
    throw std::out_of_range("ArmSceneRenderer::Render: frame " + std::to_string(frame) +
                            " outside 0.." + std::to_string(frame_count() - 1));
  }
  const bool person = frame >= impl_->opt.background_frames;
  const ArmPose pose = impl_->PoseAt(frame);
  if (truth) *truth = impl_->MakeTruth(frame, person, pose);
  return impl_->Compose(frame, pose, person, true, static_cast<uint64_t>(frame) + 1);
}

cv::Mat ArmSceneRenderer::ArmLengthImage(ArmTruth* truth) const {
  const ArmPose pose{0, 0, 0};
  if (truth) {
    *truth = impl_->MakeTruth(0, true, pose);
    truth->time_s = 0;
  }
  return impl_->Compose(0, pose, true, false, 0xA11E57ULL);
}

cv::Mat ArmSceneRenderer::EmptyBackground() const {
  cv::Mat out;
  impl_->background.convertTo(out, CV_8UC3);
  if (impl_->opt.side == ArmSide::kLeft) cv::flip(out, out, 1);
  return out;
}

cv::Point2d ArmSceneRenderer::shoulder_px() const {
  cv::Point2d p = impl_->shoulder;
  if (impl_->opt.side == ArmSide::kLeft) p.x = impl_->opt.size.width - 1 - p.x;
  return p;
}

double ArmSceneRenderer::upper_length_px() const { return impl_->upper_len; }
double ArmSceneRenderer::fore_length_px() const { return impl_->fore_len; }

}  // namespace armmimic::synth
