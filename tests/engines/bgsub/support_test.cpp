// The support rule in the bgsub engine (bgsub/support.h) on rendered scenes with known angles,
// edited so that the pixels stop showing the arm: the frames where the arm's whole reach looks like
// the empty room are lost, not guessed; and where the hanging arm leaves behind pixels that look
// like it (a sleeve in the shirt's colour, in the video and in the arm-length image), the
// standstill's pose is not reported while the arm is raised.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "arm_errors.h"
#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/arm_scene.h"
#include "common/arm_appearance.h"

namespace armmimic {
namespace {

struct Counts {
  int rows = 0, ok = 0, wrong = 0;  // wrong: ok with a segment more than 15 degrees off
  int edited = 0, edited_ok = 0;    // frames the edit changed, and those still ok
};

// Renders the scene, lets `edit` change a motion frame (true: it did), runs bgsub as the protocol
// does (background, standstill, arm-length image) and counts.
using Edit = std::function<bool(int frame, const synth::ArmTruth&, cv::Mat*)>;
Counts RunEdited(const synth::ArmSceneRenderer& scene, const cv::Mat& arm_length,
                 const Edit& edit) {
  const synth::ArmSceneOptions& so = scene.options();
  EngineContext ctx;
  ctx.frame_size = so.size;
  ctx.fps = so.fps;
  ctx.background = scene.EmptyBackground();
  ctx.arm_length = arm_length;
  EngineOptions eo;
  eo.kind = EngineKind::kBgsub;
  eo.bgsub.standstill_frames = so.standstill_frames;
  auto engine = Engine::Create(eo);
  EXPECT_TRUE(engine->Begin(ctx).ok());
  Counts c;
  for (int i = so.background_frames; i < scene.frame_count(); ++i) {
    Frame f;
    synth::ArmTruth t;
    f.image = scene.Render(i, &t);
    f.index = i;
    f.time_s = i / so.fps;
    const bool edited = i >= so.first_motion_frame() && edit(i, t, &f.image);
    const ArmMeasurement m = engine->Process(f);
    if (!m.row()) continue;
    ++c.rows;
    c.edited += edited;
    if (m.phase != MeasurementPhase::kOk) continue;
    ++c.ok;
    c.edited_ok += edited;
    c.wrong += test::ErrorsAgainst(m, t).wrong();
  }
  std::printf("  %d rows, %d ok, %d confidently wrong; %d edited, %d of them ok\n", c.rows, c.ok,
              c.wrong, c.edited, c.edited_ok);
  return c;
}

synth::ArmSceneOptions Scene(uint64_t seed) {
  synth::ArmSceneOptions so;
  so.seed = seed;
  so.motion = synth::ArmMotion::kMixed;
  so.motion_frames = 120;
  so.noise_sigma = 3;
  return so;
}

// The capsules of the arm at `t`, of radius `r` pixels, into a CV_8U mask of `size`.
cv::Mat ArmRegion(const synth::ArmTruth& t, double r, const cv::Size& size) {
  cv::Mat mask = cv::Mat::zeros(size, CV_8UC1);
  arm::ArmShape shape;
  shape.upper_hw = shape.fore_hw = r;
  shape.hand_px = r;
  arm::DrawArm(mask, {t.shoulder_px, t.elbow_px, t.wrist_px}, shape, 0);
  return mask;
}

// From the 30th motion frame on, everything the arm can reach looks like the empty room: no pose
// there may be `ok`.
TEST(BgsubSupport, AnArmThatLooksLikeTheEmptyRoomIsLost) {
  const synth::ArmSceneRenderer scene(Scene(3));
  const cv::Mat room = scene.EmptyBackground();
  const double reach = 1.5 * (scene.upper_length_px() + scene.fore_length_px());
  const int from = scene.options().first_motion_frame() + 30;
  const Counts c =
      RunEdited(scene, scene.ArmLengthImage(), [&](int i, const synth::ArmTruth& t, cv::Mat* img) {
        if (i < from) return false;
        cv::Mat disc = cv::Mat::zeros(img->size(), CV_8UC1);
        cv::circle(disc, t.shoulder_px, static_cast<int>(reach), cv::Scalar(255), cv::FILLED);
        room.copyTo(*img, disc);
        return true;
      });
  EXPECT_GT(c.edited, 60);
  EXPECT_EQ(c.edited_ok, 0);
  EXPECT_EQ(c.wrong, 0);
  EXPECT_GT(c.ok, 20);  // the frames before are measured
}

// What the hanging arm covers looks like the arm, and the raised arm is hard to see: in the
// arm-length image and in every motion frame the standstill's arm is pasted back where the arm
// was (a sleeve in the shirt's colour leaves that picture), and the moving arm itself wears the
// room's colour. The standstill's pose, on its unchanged pixels, must not be reported while the
// arm is raised.
TEST(BgsubSupport, TheStandstillsPoseIsNotRepeatedWhereTheArmLeftItsLook) {
  const synth::ArmSceneRenderer scene(Scene(3));
  const synth::ArmSceneOptions& so = scene.options();
  const cv::Mat room = scene.EmptyBackground();
  synth::ArmTruth rest;
  const cv::Mat standstill = scene.Render(so.first_motion_frame() - 1, &rest);
  const double r = 0.3 * scene.upper_length_px();
  const cv::Mat rest_region = ArmRegion(rest, r, so.size);
  // Below the arm-length image's horizontal arm.
  cv::Mat below = rest_region.clone();
  below(cv::Rect(0, 0, so.size.width, static_cast<int>(rest.shoulder_px.y + 2 * r))).setTo(0);
  cv::Mat arm_length = scene.ArmLengthImage();
  standstill.copyTo(arm_length, below);
  int raised = 0;
  const Counts c = RunEdited(scene, arm_length, [&](int, const synth::ArmTruth& t, cv::Mat* img) {
    const cv::Mat now = ArmRegion(t, r, so.size);
    room.copyTo(*img, now & ~rest_region);
    standstill.copyTo(*img, rest_region & ~now);
    const bool away = std::fabs(AngleDiff(t.upper_deg, -90)) > 45;
    raised += away;
    return away;
  });
  EXPECT_GT(raised, 20);
  EXPECT_EQ(c.edited_ok, 0);
  EXPECT_EQ(c.wrong, 0);
}

}  // namespace
}  // namespace armmimic
