// The hybrid engine on the thesis protocol without clicks (the empty room, the standstill and the
// arm-length image), on scenes of both generators: the painted random figures and the ray-cast
// capsules. Each scene is rendered, its frames compressed as its video would be, and analysed as
// `analyze` would; the test asserts coverage, the mean error of the ok frames and the confidently
// wrong frames (ok, either segment more than 15 degrees off), pooled over the scenes. Seeds 8000+
// lie outside the tuning and held-out ranges (docs/accuracy.md); seed 1001 is a tuning scene.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "arm_errors.h"
#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/capsule_arm_scene.h"
#include "armmimic/synth/random_arm_scene.h"

namespace armmimic {
namespace {

struct ProtocolRun {
  int motion = 0;      // motion frames
  int ok = 0;          // of them ok
  int wrong = 0;       // ok and off by more than 15 degrees (either segment)
  double sum_err = 0;  // mean of |d upper| and |d fore|, summed over ok frames
  // Of the ok frames, those whose pose the tracker withheld as undecided and the background
  // difference decided (hybrid/agreement.h, DisagreementWithRival), their confidently wrong ones
  // and their largest error (either segment).
  int decided = 0, decided_wrong = 0;
  double decided_max_err = 0;
  int first_ok = -1;  // the first ok frame, counted from the first motion frame (-1: none)
  double coverage() const { return motion ? static_cast<double>(ok) / motion : 0; }
  double mae() const { return ok ? sum_err / ok : kNaN; }
  double wrong_share() const { return ok ? static_cast<double>(wrong) / ok : 0; }
  void Add(const ProtocolRun& r) {
    motion += r.motion;
    ok += r.ok;
    wrong += r.wrong;
    sum_err += r.sum_err;
    decided += r.decided;
    decided_wrong += r.decided_wrong;
    decided_max_err = std::max(decided_max_err, r.decided_max_err);
  }
};

// The engine `kind` on `scene`'s protocol as `synth arm` writes it and the operator gives it:
// the empty room's image, the arm-length image and the standstill, the video's frames
// JPEG-compressed at `quality`.
// With `clicked`, the joints of the start frame are given too (to whole pixels), as an operator
// would click them: the standstill's rows are then lost (the second opinion is still taking it),
// not setup.
ProtocolRun RunProtocol(const synth::ArmSceneSource& scene, int quality, EngineKind kind,
                        bool clicked = false) {
  const int k = scene.background_frames(), m = scene.standstill_frames();
  EngineContext ctx;
  ctx.frame_size = scene.size();
  ctx.fps = scene.fps();
  ctx.background = scene.EmptyBackground();
  ctx.arm_length = scene.ArmLengthImage();
  if (clicked) {
    const synth::ArmTruth t = scene.Truth(k);
    auto px = [](const cv::Point2d& p) { return cv::Point2d(std::round(p.x), std::round(p.y)); };
    ctx.shoulder_px = px(t.shoulder_px);
    ctx.elbow_px = px(t.elbow_px);
    ctx.wrist_px = px(t.wrist_px);
  }
  EngineOptions eo;
  eo.kind = kind;
  eo.bgsub.standstill_frames = m;
  eo.lk.standstill_frames = m;
  auto engine = Engine::Create(eo);
  const Status st = engine->Begin(ctx);
  EXPECT_TRUE(st.ok()) << st.message();
  ProtocolRun run;
  if (!st) return run;
  for (int i = k; i < scene.frame_count(); ++i) {
    Frame f;
    synth::ArmTruth t;
    f.image = synth::JpegRoundTrip(scene.Render(i, &t), quality);
    f.index = i;
    f.time_s = i / scene.fps();
    const ArmMeasurement a = engine->Process(f);
    if (i < k + m) {
      EXPECT_EQ(a.phase, clicked ? MeasurementPhase::kLost : MeasurementPhase::kSetup)
          << "frame " << i << " of the standstill";
      continue;
    }
    ++run.motion;
    if (a.phase != MeasurementPhase::kOk) continue;
    if (run.first_ok < 0) run.first_ok = run.motion - 1;
    ++run.ok;
    const test::SegmentErrors e = test::ErrorsAgainst(a, t);
    run.sum_err += e.mean();
    run.wrong += e.wrong();
    if (a.note.find("could not tell this pose from another alone") != std::string::npos) {
      ++run.decided;
      run.decided_wrong += e.wrong();
      run.decided_max_err = std::max({run.decided_max_err, e.upper, e.fore});
    }
  }
  return run;
}

ProtocolRun RandomScene(uint64_t seed, synth::SceneTier tier, EngineKind kind) {
  synth::RandomArmSceneOptions o;
  o.seed = seed;
  o.tier = tier;
  o.size = cv::Size(320, 240);
  const synth::RandomArmScene scene(o);
  return RunProtocol(scene, scene.params().jpeg_quality, kind);
}

ProtocolRun CapsuleScene(uint64_t seed, synth::SceneTier tier, EngineKind kind,
                         bool clicked = false) {
  synth::CapsuleArmSceneOptions o;
  o.seed = seed;
  o.tier = tier;
  o.size = cv::Size(320, 240);
  const synth::CapsuleArmScene scene(o);
  return RunProtocol(scene, scene.params().jpeg_quality, kind, clicked);
}

void Print(const char* what, const ProtocolRun& r) {
  std::printf(
      "%s: %d motion frames, %.1f %% ok, MAE %.2f deg, %d confidently wrong (%.1f %% of ok); %d "
      "ok rows decided by the background difference (%d confidently wrong, the worst %.1f deg "
      "off)\n",
      what, r.motion, 100 * r.coverage(), r.mae(), r.wrong, 100 * r.wrong_share(), r.decided,
      r.decided_wrong, r.decided_max_err);
}

// Pooled over four scenes, as they come: these bounds guard what the engine does today, short of
// the goals (docs/hybrid.md): measured 86.3 % ok, MAE 3.18 deg, 1 confidently wrong (15.2
// degrees off, one of the 5 rows the background difference decided for an undecided tracker).
// Before a tracker without a calibration was started on the first motion frame, 81.3 %, MAE
// 3.26 (21 rows decided); before the decided rows, 78.7 %, MAE 3.25, none wrong. Earlier 79.7 %
// (seeds 8001-8004: 75.5, 89.3, 97.5 and 52.2 % ok). Before the standstill calibration read a
// sleeve covered by the torso from its outer edge: 61.4 % ok, 36 of 505 ok frames confidently wrong
// (seed 8001 gave no row; on seed 8004 both opinions put the raised forearm's elbow short and
// agreed 16 degrees off).
TEST(HybridProtocol, RandomFiguresWithoutClicks) {
  ProtocolRun all;
  for (uint64_t seed = 8001; seed <= 8004; ++seed) {
    all.Add(RandomScene(seed, synth::SceneTier::kMedium, EngineKind::kHybrid));
  }
  Print("hybrid, random medium 8001-8004", all);
  ASSERT_GT(all.motion, 0);
  EXPECT_GE(all.coverage(), 0.75);
  EXPECT_LE(all.mae(), 3.8);
  EXPECT_LE(all.wrong_share(), 0.02);
}

// As above: measured 88.9 % ok, MAE 3.47 deg, none confidently wrong, 13 rows decided by the
// background difference for an undecided tracker (before a tracker without a calibration was
// started on the first motion frame 88.5 %, MAE 3.49; before the decided rows 87.1 %, MAE
// 3.52). Earlier
// 77.3 % ok, MAE 3.91 deg, 24 confidently wrong frames of 731 ok, all on seed 8001, whose short
// sleeves are the wall's colour (the background difference places the upper arm 30-40 degrees off
// with full confidence, and the tracker, which cannot calibrate there, restarts from it). Before
// the straight arm was followed on over a wall of its colour (common/straight_arm.h): 76.4 %,
// MAE 3.15; that moved seed 8004's calibrated shoulder by a pixel (the truth's within 1 px either
// way), and the tracker took another path there (MAE 2.3 -> 4.5 deg, 92.0 -> 95.2 % ok): the
// tracker's sensitivity to its start (docs/hybrid.md).
TEST(HybridProtocol, CapsuleFiguresWithoutClicks) {
  ProtocolRun all;
  for (uint64_t seed = 8001; seed <= 8004; ++seed) {
    all.Add(CapsuleScene(seed, synth::SceneTier::kMedium, EngineKind::kHybrid));
  }
  Print("hybrid, capsule medium 8001-8004", all);
  ASSERT_GT(all.motion, 0);
  EXPECT_GE(all.coverage(), 0.7);
  EXPECT_LE(all.mae(), 4.2);
  EXPECT_LE(all.wrong_share(), 0.045);
}

// A tuning scene whose standstill the tracker cannot calibrate from (a sleeve in the room's
// colour): lk alone gives no ok row at all; the hybrid engine starts its tracker from the
// background difference's joints instead, and measures the scene. (Started at once, the tracker
// finds the arm hanging against a body in the wall's colour ambiguous, and restarts again:
// measured 92.8 % ok, MAE 1.79 deg, the first ok row at motion frame 11; before the tracker was
// started on the first motion frame, 96.7 %.)
TEST(HybridProtocol, ATrackerThatCannotCalibrateStartsFromTheBackgroundDifference) {
  const ProtocolRun lk = RandomScene(1001, synth::SceneTier::kMedium, EngineKind::kLk);
  const ProtocolRun hybrid = RandomScene(1001, synth::SceneTier::kMedium, EngineKind::kHybrid);
  Print("lk, random medium 1001", lk);
  Print("hybrid, random medium 1001", hybrid);
  EXPECT_EQ(lk.ok, 0);
  EXPECT_GE(hybrid.coverage(), 0.9);
  EXPECT_LE(hybrid.mae(), 4.5);
  EXPECT_EQ(hybrid.wrong, 0);
}

// A tuning scene (capsule medium 3000) whose hanging arm does not show against the empty room,
// so the tracker cannot calibrate: it is started on the first motion frame from the background
// difference's row, which that engine's gate checked against the standstill's pose, and the
// rows are measured from the second motion frame. Measured: 87.1 % ok, MAE 5.04 deg, 1 of 196
// ok rows confidently wrong (frame 268: the upper arm 15.4 deg off, the forearm 3.7), the first
// ok row at motion frame 1. Before the background difference measured where the elbow lies
// (bgsub/fit.h): 75.6 % ok, MAE 5.36 deg, none wrong; before that, the tracker waited for 5 rows
// of its own loss and 5 steady rows of the background difference: 73.8 %, the first at 5.
TEST(HybridProtocol, ATrackerWithoutACalibrationStartsOnTheFirstMotionFrame) {
  const ProtocolRun lk = CapsuleScene(3000, synth::SceneTier::kMedium, EngineKind::kLk);
  const ProtocolRun hybrid = CapsuleScene(3000, synth::SceneTier::kMedium, EngineKind::kHybrid);
  Print("lk, capsule medium 3000", lk);
  Print("hybrid, capsule medium 3000", hybrid);
  std::printf("hybrid: the first ok row at motion frame %d\n", hybrid.first_ok);
  EXPECT_EQ(lk.ok, 0);
  EXPECT_EQ(hybrid.first_ok, 1);
  EXPECT_GE(hybrid.coverage(), 0.7);
  EXPECT_LE(hybrid.mae(), 6);
  EXPECT_LE(hybrid.wrong_share(), 0.01);
}

// A tuning scene (capsule medium 3003) whose hanging forearm lies against a torso the tracker
// never saw without it: in the first motion frames another forearm direction explains the
// tracker's evidence about as well, so lk alone writes them lost though it tracks on. The
// background difference measures the forearm apart from the tracker; where it places both
// segments nearer the tracker's pose than halfway to the rival, the hybrid engine writes the row.
// Measured: lk alone 85.5 % ok, the hybrid 96.0 % (MAE 3.82 deg, none confidently wrong), 11 of
// its rows decided by the background difference, the worst 10.4 degrees off; without that rule
// those rows were lost.
TEST(HybridProtocol, TheBackgroundDifferenceDecidesAForearmTheTrackerCannotTell) {
  const ProtocolRun lk = CapsuleScene(3003, synth::SceneTier::kMedium, EngineKind::kLk);
  const ProtocolRun hybrid = CapsuleScene(3003, synth::SceneTier::kMedium, EngineKind::kHybrid);
  Print("lk, capsule medium 3003", lk);
  Print("hybrid, capsule medium 3003", hybrid);
  EXPECT_GE(hybrid.decided, 8);
  EXPECT_EQ(hybrid.decided_wrong, 0);
  EXPECT_LE(hybrid.decided_max_err, 12);
  EXPECT_GE(hybrid.coverage(), 0.94);
  EXPECT_LE(hybrid.mae(), 4.5);
  EXPECT_EQ(hybrid.wrong, 0);
}

// A thin arm that hangs a few degrees out from the body (tuning scene capsule hard 3013, its arm
// about 8 px wide): the line straight down from the shoulder left the standstill's person, so
// the background difference's support rule could not be calibrated and every row of both
// engines was lost. The standstill's arm is now looked for along the outward lean the person
// supports best.
TEST(HybridProtocol, AThinArmHangingALittleOutCalibratesTheSupportRule) {
  const ProtocolRun bgsub = CapsuleScene(3013, synth::SceneTier::kHard, EngineKind::kBgsub);
  const ProtocolRun hybrid = CapsuleScene(3013, synth::SceneTier::kHard, EngineKind::kHybrid);
  Print("bgsub, capsule hard 3013", bgsub);
  Print("hybrid, capsule hard 3013", hybrid);
  EXPECT_GE(bgsub.coverage(), 0.9);
  EXPECT_LE(bgsub.wrong_share(), 0.02);
  EXPECT_GE(hybrid.coverage(), 0.9);
  EXPECT_LE(hybrid.mae(), 3.0);
  EXPECT_EQ(hybrid.wrong, 0);
}

// Joints clicked on footage with no empty room and no pose model (a model folder without it):
// there is no second opinion, so the rows are the tracker's own, exactly as the lk engine gives
// them, and the first row says so. (With the model, the pose network is the second opinion:
// real_clip_test.cpp.)
TEST(HybridProtocol, WithoutABackgroundTheRowsAreTheTrackersAlone) {
  synth::RandomArmSceneOptions so;
  so.seed = 8002;
  so.tier = synth::SceneTier::kMedium;
  so.size = cv::Size(320, 240);
  const synth::RandomArmScene scene(so);
  const int first = scene.first_motion_frame();
  const synth::ArmTruth t = scene.Truth(first);
  EngineContext ctx;
  ctx.frame_size = scene.size();
  ctx.fps = scene.fps();
  ctx.shoulder_px = t.shoulder_px;
  ctx.elbow_px = t.elbow_px;
  ctx.wrist_px = t.wrist_px;
  ctx.model_dir = ::testing::TempDir() + "/no-pose-model-here";
  EngineOptions lk_options, hybrid_options;
  lk_options.kind = EngineKind::kLk;
  hybrid_options.kind = EngineKind::kHybrid;
  auto lk = Engine::Create(lk_options);
  auto hybrid = Engine::Create(hybrid_options);
  ASSERT_TRUE(lk->Begin(ctx).ok());
  ASSERT_TRUE(hybrid->Begin(ctx).ok());
  int ok = 0;
  for (int i = first; i < first + 40; ++i) {
    Frame f;
    f.image = synth::JpegRoundTrip(scene.Render(i), scene.params().jpeg_quality);
    f.index = i;
    f.time_s = i / scene.fps();
    const ArmMeasurement a = lk->Process(f), b = hybrid->Process(f);
    ASSERT_EQ(a.phase, b.phase) << "frame " << i;
    if (i == first) {
      EXPECT_NE(b.estimate.find("no second opinion"), std::string::npos) << b.estimate;
    }
    if (a.phase != MeasurementPhase::kOk) continue;
    ++ok;
    EXPECT_EQ(a.upper_deg, b.upper_deg) << "frame " << i;
    EXPECT_EQ(a.fore_deg, b.fore_deg) << "frame " << i;
  }
  EXPECT_GT(ok, 30);
}

// The protocol with the joints clicked in its first standstill frame (or dragged in the GUI): the
// tracker starts from them, the background difference still calibrates itself from the
// standstill (apart from the clicks), and nearly every motion frame is measured (measured 99.6 %,
// MAE 3.57 deg: the mean of the tracker's 2.7 and the background difference's 4-7 on this scene).
TEST(HybridProtocol, ClickedJointsStartTheTrackerAndTheSecondOpinionStaysApart) {
  const ProtocolRun r = CapsuleScene(8004, synth::SceneTier::kMedium, EngineKind::kHybrid, true);
  Print("hybrid, joints clicked, capsule medium 8004", r);
  EXPECT_GE(r.coverage(), 0.95);
  EXPECT_LE(r.mae(), 4.5);
  EXPECT_EQ(r.wrong, 0);
}

// The arm-length image and a standstill compressed as video differ a little over the floor and
// the legs too; on this unit scene that region was larger than the straight arm, and both
// calibrations took it for the arm (the shoulder at the frame's bottom edge: every row lost). A
// shoulder lies in the upper half of a standing body, and the arm held out from it is found there.
TEST(HybridProtocol, TheStraightArmIsHeldOutFromTheShoulderNotLyingOnTheFloor) {
  const ProtocolRun bgsub = CapsuleScene(8002, synth::SceneTier::kMedium, EngineKind::kBgsub);
  const ProtocolRun hybrid = CapsuleScene(8002, synth::SceneTier::kMedium, EngineKind::kHybrid);
  Print("bgsub, capsule medium 8002", bgsub);
  Print("hybrid, capsule medium 8002", hybrid);
  EXPECT_GE(bgsub.coverage(), 0.9);
  EXPECT_GE(hybrid.coverage(), 0.9);
  EXPECT_EQ(hybrid.wrong, 0);
}

}  // namespace
}  // namespace armmimic
