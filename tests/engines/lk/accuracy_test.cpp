// LK engine accuracy on rendered scenes with known angles (thesis Table 6-1 protocol): the error
// against the truth is bounded, and it does not grow over a long scene.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/arm_scene.h"

namespace armmimic {
namespace {

struct LkRun {
  int rows = 0;
  int ok = 0;
  std::vector<double> error;  // per motion frame: mean of upper and forearm direction errors
  double Mae(std::size_t from, std::size_t to) const {
    double sum = 0;
    int n = 0;
    for (std::size_t i = from; i < to && i < error.size(); ++i) {
      if (std::isnan(error[i])) continue;
      sum += error[i];
      ++n;
    }
    return n ? sum / n : kNaN;
  }
  double Mae() const { return Mae(0, error.size()); }
  double OkFraction() const { return rows ? static_cast<double>(ok) / rows : 0; }
};

// Runs the LK engine over `scene`: with the background (mean of the empty frames) and the
// standstill when `given_shoulder` is false, else from the last standstill frame with --shoulder
// (the true shoulder moved by `click_error_px`, as an operator's click would be).
LkRun RunLk(const synth::ArmSceneOptions& scene, bool given_shoulder, bool thesis = false,
            cv::Point2d click_error_px = {0, 0}) {
  synth::ArmSceneRenderer renderer(scene);
  EngineOptions options;
  options.kind = EngineKind::kLk;
  options.lk.thesis_mode = thesis;
  std::unique_ptr<Engine> engine = Engine::Create(options);
  EngineContext context;
  context.frame_size = scene.size;
  context.fps = scene.fps;
  int first = scene.background_frames;
  if (given_shoulder) {
    context.shoulder_px = renderer.shoulder_px() + click_error_px;
    first = scene.first_motion_frame() - 1;
  } else {
    cv::Mat sum = cv::Mat::zeros(scene.size, CV_32FC3);
    for (int i = 0; i < scene.background_frames; ++i) cv::accumulate(renderer.Render(i), sum);
    sum.convertTo(context.background, CV_8UC3, 1.0 / scene.background_frames);
  }
  EXPECT_TRUE(engine->Begin(context).ok());
  LkRun run;
  for (int i = first; i < renderer.frame_count(); ++i) {
    synth::ArmTruth truth;
    Frame frame;
    frame.image = renderer.Render(i, &truth);
    frame.index = i;
    frame.time_s = i / scene.fps;
    const ArmMeasurement m = engine->Process(frame);
    if (!m.row() || i < scene.first_motion_frame()) continue;
    ++run.rows;
    if (m.phase != MeasurementPhase::kOk) {
      run.error.push_back(kNaN);
      continue;
    }
    ++run.ok;
    run.error.push_back(0.5 * (std::abs(AngleDiff(m.upper_deg, truth.upper_deg)) +
                               std::abs(AngleDiff(m.fore_deg, truth.fore_deg))));
  }
  return run;
}

synth::ArmSceneOptions Scene(uint64_t seed, synth::ArmMotion motion, synth::ArmSide side,
                             int motion_frames) {
  synth::ArmSceneOptions s;
  s.seed = seed;
  s.motion = motion;
  s.side = side;
  s.motion_frames = motion_frames;
  return s;
}

// Direction MAE bound in memory (measured 0.84-2.04 degrees on these scenes; the target
// is 4).
constexpr double kMaeBound = 2.5;

// The engine found the arm in >= 95 % of the motion frames (a frame whose pose jumps faster
// than an arm turns is honestly `lost`), within `mae_bound` on average, and no `ok` frame is
// confidently wrong (more than 15 degrees off) beyond `wrong_share` of the frames.
void ExpectAccurate(const LkRun& run, double mae_bound = kMaeBound, double wrong_share = 0) {
  EXPECT_GE(run.OkFraction(), 0.95);
  EXPECT_LE(run.Mae(), mae_bound) << "MAE " << run.Mae();
  int wrong = 0;
  for (double e : run.error) wrong += e > 15;
  EXPECT_LE(wrong, wrong_share * run.rows) << "ok frames more than 15 degrees off";
}

TEST(LkAccuracy, SwingWithGivenShoulder) {
  const LkRun run = RunLk(Scene(1, synth::ArmMotion::kSwing, synth::ArmSide::kRight, 200), true);
  ExpectAccurate(run);
}

TEST(LkAccuracy, MixedLeftWithGivenShoulder) {
  const LkRun run = RunLk(Scene(3, synth::ArmMotion::kMixed, synth::ArmSide::kLeft, 200), true);
  ExpectAccurate(run);
}

TEST(LkAccuracy, MixedWithBackgroundAndStandstill) {
  const LkRun run = RunLk(Scene(1, synth::ArmMotion::kMixed, synth::ArmSide::kRight, 200), false);
  ExpectAccurate(run);
}

TEST(LkAccuracy, SwingLeftWithBackgroundAndStandstill) {
  const LkRun run = RunLk(Scene(4, synth::ArmMotion::kSwing, synth::ArmSide::kLeft, 200), false);
  ExpectAccurate(run);
}

// A straight arm turned out of the picture up to 70 degrees: its forearm is searched on the
// shortened arm, not beyond the hand.
TEST(LkAccuracy, YawTurnedArmWithBackgroundAndStandstill) {
  const LkRun run = RunLk(Scene(7, synth::ArmMotion::kYaw, synth::ArmSide::kRight, 150), false);
  // Turned 70 degrees away, the arm is seen at a third of its length: its direction is the least
  // certain of all (measured: 2 of 150 frames over 15 degrees).
  ExpectAccurate(run, kMaeBound, 0.02);
}

TEST(LkAccuracy, YawTurnedLeftArmWithGivenShoulder) {
  const LkRun run = RunLk(Scene(8, synth::ArmMotion::kYaw, synth::ArmSide::kLeft, 150), true);
  ExpectAccurate(run, 4.0);
}

// A shirt close to the wall's colour and a shoulder clicked 3 px too low: the sleeve lines nudge
// the shoulder back, and a few misleading frames cannot pull the elbow away.
TEST(LkAccuracy, LowContrastShirtWithAnImpreciseShoulder) {
  synth::ArmSceneOptions scene = Scene(9, synth::ArmMotion::kMixed, synth::ArmSide::kRight, 150);
  scene.clothing_contrast = 0.3;
  const LkRun run = RunLk(scene, true, false, {1, 3});
  ExpectAccurate(run, 4.0);
}

// Error must not accumulate: the last 100 frames of a 1000-frame scene are no worse than the
// first 100 (up to a small tolerance for the different poses visited).
TEST(LkAccuracy, LongSceneDoesNotDrift) {
  const LkRun run = RunLk(Scene(5, synth::ArmMotion::kSwing, synth::ArmSide::kRight, 1000), true);
  ASSERT_EQ(run.error.size(), 1000u);
  const double first = run.Mae(0, 100), last = run.Mae(900, 1000);
  EXPECT_LE(last, first + 0.5) << "first 100: " << first << ", last 100: " << last;
  ExpectAccurate(run);
}

TEST(LkEngine, ThesisPathRunsAndGivesRows) {
  const LkRun run =
      RunLk(Scene(2, synth::ArmMotion::kSwing, synth::ArmSide::kRight, 60), true, true);
  EXPECT_EQ(run.rows, 60);
  EXPECT_EQ(run.ok, 60);
}

TEST(LkEngine, BeginNamesWhatIsMissingOrWrong) {
  EngineOptions options;
  options.kind = EngineKind::kLk;
  std::unique_ptr<Engine> engine = Engine::Create(options);
  EngineContext context;
  context.frame_size = {320, 240};
  Status st = engine->Begin(context);
  EXPECT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "analysis.shoulder") << st.message();
  EXPECT_NE(st.message().find("shoulder"), std::string::npos) << st.message();

  context.background = cv::Mat(100, 100, CV_8UC3, cv::Scalar::all(0));
  st = engine->Begin(context);
  EXPECT_FALSE(st.ok());
  EXPECT_NE(st.message().find("background"), std::string::npos) << st.message();

  context.background.release();
  context.shoulder_px = cv::Point2d(500, 10);
  st = engine->Begin(context);
  EXPECT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "analysis.shoulder") << st.message();

  context.shoulder_px = cv::Point2d(100, 100);
  context.roi = cv::Rect(300, 200, 100, 100);
  st = engine->Begin(context);
  EXPECT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "analysis.roi") << st.message();
}

TEST(LkEngine, WrongFrameSizeIsLostNotACrash) {
  EngineOptions options;
  options.kind = EngineKind::kLk;
  std::unique_ptr<Engine> engine = Engine::Create(options);
  EngineContext context;
  context.frame_size = {320, 240};
  context.shoulder_px = cv::Point2d(160, 100);
  ASSERT_TRUE(engine->Begin(context).ok());
  Frame frame;
  frame.image = cv::Mat(120, 160, CV_8UC3, cv::Scalar::all(80));
  const ArmMeasurement m = engine->Process(frame);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost);
}

TEST(LkOptions, CheckNamesTheOption) {
  LkOptions o;
  EXPECT_TRUE(o.Check().ok());
  o.window_px = 14;
  EXPECT_EQ(o.Check().key(), "lk.window_px");
  EXPECT_EQ(o.Check().message(), "LK window is 14; it must be odd");
  o = LkOptions();
  o.quality_level = 0;
  EXPECT_EQ(o.Check().key(), "lk.quality_level");
  EXPECT_EQ(o.Check().message(), "corner quality is 0; it must be in [0.0001, 1]");
}

}  // namespace
}  // namespace armmimic
