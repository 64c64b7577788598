// The LK engine on randomised scenes (synth arm --random), one or two fixed scenes per failure
// class of docs/accuracy.md: short sleeves, camouflage, the hand above the head, the forearm
// across the torso (also in the shirt's cloth), fast swings, a swaying body, a passing shadow and
// drifting light. Each run gets the joints clicked on the first motion frame (the benchmark's
// `joints` mode) and is scored over the motion frames: the error of its ok frames, its coverage
// and its confidently wrong frames (ok, worse segment > 15 deg off). The seeds lie outside the
// tuning and held-out ranges; the frames are small and JPEG-compressed as the scene's video would
// hold them.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "armmimic/engines/analysis.h"
#include "armmimic/synth/random_arm_scene.h"
#include "armmimic/synth/robustness_stats.h"
#include "armmimic/synth/score.h"
#include "armmimic/synth/truth_file.h"

namespace armmimic {
namespace {

// A scene at 240x180, its frames JPEG-compressed at the scene's quality; frames in [hide_from,
// hide_to) show the empty room instead (the arm, and the person, gone).
struct Scene {
  synth::RandomArmSceneOptions options;
  std::unique_ptr<synth::RandomArmScene> scene;
  std::shared_ptr<std::vector<cv::Mat>> frames = std::make_shared<std::vector<cv::Mat>>();
  synth::TruthFile truth;

  Scene(uint64_t seed, synth::SceneTier tier, int hide_from = -1, int hide_to = -1) {
    options.seed = seed;
    options.tier = tier;
    options.size = {240, 180};
    scene = std::make_unique<synth::RandomArmScene>(options);
    const int quality = scene->params().jpeg_quality;
    const int first = scene->first_motion_frame();
    const cv::Mat empty = synth::JpegRoundTrip(scene->EmptyBackground(), quality);
    for (int f = 0; f < scene->frame_count(); ++f) {
      // Frames before the start are never analysed: a blank stands in for them.
      if (f < first) {
        frames->push_back(cv::Mat(scene->size(), CV_8UC3, cv::Scalar::all(0)));
      } else if (f >= hide_from && f < hide_to) {
        frames->push_back(empty);
      } else {
        frames->push_back(synth::JpegRoundTrip(scene->Render(f), quality));
      }
      truth.rows.push_back(scene->Truth(f).ToRow());
    }
  }

  // The lk engine with the joints clicked (to whole pixels) on the first motion frame.
  synth::ScoreReport RunLk() const {
    const synth::ArmTruth t = scene->Truth(scene->first_motion_frame());
    auto px = [](const cv::Point2d& p) { return cv::Point2d(std::round(p.x), std::round(p.y)); };
    AnalysisOptions o;
    o.engine.kind = EngineKind::kLk;
    o.start = scene->first_motion_frame();
    o.shoulder_px = px(t.shoulder_px);
    o.elbow_px = px(t.elbow_px);
    o.wrist_px = px(t.wrist_px);
    o.inputs = {"scene"};
    auto held = frames;
    const double fps = scene->fps();
    o.open_source = [held, fps](Status* status) {
      return VideoSource::FromFrames(held, fps, "scene", status);
    };
    AngleFile angles;
    AnalysisCallbacks cb;
    cb.on_measurement = [&angles](const Frame&, const ArmMeasurement& m) {
      if (m.row()) angles.rows.push_back(m.ToRow());
    };
    AnalysisSummary summary;
    const Status st = RunAnalysis(o, cb, &summary);
    EXPECT_TRUE(st.ok()) << st.message();
    return synth::ScoreAngles(truth, angles);
  }
};

// The score of the frames in [from, to).
synth::MotionScore ScoreOf(const synth::ScoreReport& report, int from, int to) {
  synth::ScoreReport part;
  for (const synth::ScoreRow& r : report.rows) {
    if (r.frame >= from && r.frame < to) part.rows.push_back(r);
  }
  return synth::ScoreMotion(part, from);
}

// The motion's error, coverage and confidently wrong frames within bounds.
void ExpectWithin(uint64_t seed, synth::SceneTier tier, double max_error_deg, double min_coverage,
                  int max_wrong) {
  const Scene s(seed, tier);
  const synth::MotionScore m =
      ScoreOf(s.RunLk(), s.scene->first_motion_frame(), s.scene->frame_count());
  ASSERT_GT(m.motion_frames, 0);
  EXPECT_LE(m.mean_error_deg, max_error_deg);
  EXPECT_GE(m.coverage(), min_coverage);
  EXPECT_LE(m.confidently_wrong_frames, max_wrong)
      << "of " << m.motion_frames << " motion frames, " << m.ok_frames << " ok";
}

using synth::SceneTier;

TEST(LkRandomScene, ShortSleeves) { ExpectWithin(7002, SceneTier::kMedium, 6, 0.95, 2); }
TEST(LkRandomScene, ShortSleevesPastAnObjectInTheirColour) {
  ExpectWithin(7015, SceneTier::kMedium, 4, 0.95, 2);
}
// The sleeve in the shirt's cloth: where the arm hung at the start, the torso behind it is the
// arm's colour and becomes the scene only once it has held still (docs/lk.md), so the first frames
// after the start are lost rather than guessed (coverage 0.89; 0.93 when it was taken at once).
TEST(LkRandomScene, CamouflageAgainstAnObject) {
  ExpectWithin(7017, SceneTier::kMedium, 6, 0.85, 2);
}
TEST(LkRandomScene, HandAboveTheHead) { ExpectWithin(7001, SceneTier::kMedium, 5, 0.95, 3); }
TEST(LkRandomScene, BareHandAboveTheHead) { ExpectWithin(7022, SceneTier::kMedium, 7, 0.95, 2); }
TEST(LkRandomScene, ForearmAcrossTheTorso) { ExpectWithin(7005, SceneTier::kMedium, 4, 0.95, 2); }
TEST(LkRandomScene, FastSwingsOfASwayingBody) { ExpectWithin(7004, SceneTier::kHard, 6, 0.85, 4); }
TEST(LkRandomScene, SleeveInTheShirtsClothAcrossIt) {
  ExpectWithin(7002, SceneTier::kHard, 5, 0.85, 2);
}
// The forearm across the torso in the shirt's cloth, under drifting light: there its evidence
// does not say which way it points, and those frames must be lost rather than guessed (each scene
// had one confidently wrong frame before the forearm's own margin was checked).
TEST(LkRandomScene, ForearmAcrossTheTorsoInTheShirtsCloth) {
  ExpectWithin(7034, SceneTier::kHard, 5, 0.85, 0);
  ExpectWithin(7017, SceneTier::kHard, 6, 0.85, 0);
}

// A sleeve close to the wall's colour, the light drifting by a third and a shadow passing: the
// learnt background must not take in the arm where the pose lagged it (a ghost arm that then
// holds the fit on a wrong pose), and the light must not read as change or as another colour.
TEST(LkRandomScene, SleeveLikeTheWallUnderAPassingShadow) {
  ExpectWithin(7010, SceneTier::kHard, 5, 0.85, 2);
  ExpectWithin(7050, SceneTier::kHard, 5, 0.85, 2);
}
TEST(LkRandomScene, SleeveInTheShirtsClothUnderAStrongShadow) {
  ExpectWithin(7059, SceneTier::kHard, 5, 0.85, 2);
}

// The arm hanging in the shirt's cloth beside the torso, raised quickly at 12 fps: where it hung
// at the start the scene has never been seen without it, and the torso's edge in the same cloth
// (with a cabinet in the skin's colour below) scores there like the arm. Once the arm has been seen
// elsewhere, a lock there must be lost rather than written (22 of 28 ok frames were confidently
// wrong, whole stretches 100-170 deg off, before; 4 remain, where the arm first rises).
TEST(LkRandomScene, NoLockWhereTheStartHidTheScene) {
  const Scene s(7108, SceneTier::kHard);
  const synth::MotionScore m =
      ScoreOf(s.RunLk(), s.scene->first_motion_frame(), s.scene->frame_count());
  ASSERT_GT(m.motion_frames, 0);
  EXPECT_GT(m.ok_frames, 0);
  EXPECT_LE(m.confidently_wrong_frames, 5)
      << "of " << m.motion_frames << " motion frames, " << m.ok_frames << " ok";
}

// The arm vanishes for a while (the empty room): whatever the engine locks onto then is wrong, so
// those frames must be lost; when the arm is back, the engine finds it again by itself.
TEST(LkRandomScene, AVanishedArmIsLostThenFoundAgain) {
  const uint64_t seed = 7005;
  const Scene probe(seed, SceneTier::kMedium);
  const int first = probe.scene->first_motion_frame();
  const int from = first + 40, to = first + 60, end = probe.scene->frame_count();
  const Scene s(seed, SceneTier::kMedium, from, to);
  const synth::ScoreReport report = s.RunLk();
  const synth::MotionScore gone = ScoreOf(report, from, to);
  const synth::MotionScore back = ScoreOf(report, to, end);
  ASSERT_EQ(gone.motion_frames, to - from);
  EXPECT_EQ(gone.ok_frames, 0) << "frames of the empty room written as ok";
  ASSERT_GT(back.motion_frames, 0);
  EXPECT_GE(back.coverage(), 0.8) << "the arm not found again";
  EXPECT_LE(back.mean_error_deg, 5);
  EXPECT_LE(back.confidently_wrong_frames, 2);
}

}  // namespace
}  // namespace armmimic
