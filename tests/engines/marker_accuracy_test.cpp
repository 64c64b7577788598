// Accuracy of the marker-joint engine on rendered views with known poses (thesis chapter 4):
// the targets are yaw MAE <= 1.0 and bend MAE <= 1.5 degrees over readable views (the thesis
// reached 1.2 and 3.3, with maxima of 4.5 and 5.2), and every view past the visibility limit lost.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/marker_scene.h"

namespace armmimic {
namespace {

struct Tally {
  int views = 0;  // readable views
  int ok = 0;     // ... measured
  int unreadable = 0;
  int unreadable_ok = 0;  // must stay 0
  int gross = 0;          // ok views with yaw or bend off by more than 10 degrees
  double yaw_sum = 0, bend_sum = 0, yaw_max = 0, bend_max = 0;
  std::string log;  // the views behind the maxima and every unreadable view read
  double yaw_mae() const { return ok ? yaw_sum / ok : kNaN; }
  double bend_mae() const { return ok ? bend_sum / ok : kNaN; }
  double coverage() const { return views ? static_cast<double>(ok) / views : kNaN; }
};

// Renders `poses` views of the scene with yaw in [min_yaw, max_yaw] (either sign) and bend in
// [-max_bend, max_bend], runs the engine on them and tallies the errors.
void RunScene(const synth::MarkerSceneOptions& scene_options, int poses, double min_yaw,
              double max_yaw, double max_bend, bool thesis_mode, Tally* tally) {
  const synth::MarkerSceneRenderer scene(scene_options);
  EngineOptions options;
  options.kind = EngineKind::kMarker;
  options.marker.thesis_mode = thesis_mode;
  const std::unique_ptr<Engine> engine = Engine::Create(options);
  EngineContext context;
  context.reference = scene.Reference();
  context.frame_size = context.reference.size();
  const Status begun = engine->Begin(context);
  ASSERT_TRUE(begun.ok()) << begun.message() << " (seed " << scene_options.seed << ", "
                          << scene.background_kind() << "/" << scene.lighting_kind() << ")";
  cv::RNG rng(scene_options.seed * 31 + 5);
  for (int i = 0; i < poses; ++i) {
    synth::MarkerPose pose;
    pose.yaw_deg = rng.uniform(min_yaw, max_yaw) * (rng.uniform(0, 2) ? 1 : -1);
    pose.bend_deg = rng.uniform(-max_bend, max_bend);
    synth::MarkerTruth truth;
    Frame frame;
    frame.image = scene.RenderPose(pose, 100 + i, &truth);
    frame.index = i;
    frame.name = "view.png";
    const ArmMeasurement m = engine->Process(frame);
    const bool ok = m.phase == MeasurementPhase::kOk;
    if (!truth.readable) {
      ++tally->unreadable;
      if (ok) {
        ++tally->unreadable_ok;
        tally->log += "unreadable view read: seed " + std::to_string(scene_options.seed) + " yaw " +
                      std::to_string(pose.yaw_deg) + " bend " + std::to_string(pose.bend_deg) +
                      " -> " + m.note + "\n";
      }
      continue;
    }
    ++tally->views;
    if (!ok) continue;
    ++tally->ok;
    const double yaw_err = std::abs(m.yaw_deg - truth.yaw_deg);
    const double bend_err = std::abs(AngleDiff(m.bend_deg, truth.bend_deg));
    tally->yaw_sum += yaw_err;
    tally->bend_sum += bend_err;
    if (yaw_err > tally->yaw_max) {
      tally->log += "yaw max: seed " + std::to_string(scene_options.seed) + " yaw " +
                    std::to_string(pose.yaw_deg) + " bend " + std::to_string(pose.bend_deg) +
                    " measured " + std::to_string(m.yaw_deg) + "\n";
    }
    tally->yaw_max = std::max(tally->yaw_max, yaw_err);
    tally->bend_max = std::max(tally->bend_max, bend_err);
    if (yaw_err > 10 || bend_err > 10) ++tally->gross;
  }
}

synth::MarkerSceneOptions Scene(uint64_t seed, const std::string& lighting, int clutter) {
  synth::MarkerSceneOptions o;
  o.seed = seed;
  o.lighting = lighting;
  o.clutter = clutter;
  o.views = 1;
  return o;
}

TEST(MarkerAccuracy, NormalLightingMeetsTheTargets) {
  Tally t;
  for (uint64_t seed : {1, 2, 3}) {
    RunScene(Scene(seed, "normal", 0), 14, 0, 29, 60, false, &t);
  }
  EXPECT_GE(t.coverage(), 0.9) << t.ok << " of " << t.views;
  EXPECT_LE(t.yaw_mae(), 1.0);
  EXPECT_LE(t.bend_mae(), 1.5);
  // The targets are the MAEs; single views may stray further (the thesis' maxima were 4.5 and
  // 5.2), but never grossly.
  EXPECT_LE(t.yaw_max, 6.0) << t.log;
  EXPECT_LE(t.bend_max, 5.2);
  EXPECT_EQ(t.unreadable_ok, 0);
}

TEST(MarkerAccuracy, OtherIlluminationKeepsTheTargets) {
  Tally t;
  uint64_t seed = 4;
  for (const char* lighting : {"bright", "side", "shadow", "dim"}) {
    RunScene(Scene(seed++, lighting, 0), 10, 0, 29, 60, false, &t);
  }
  EXPECT_GE(t.coverage(), 0.5) << t.ok << " of " << t.views;
  EXPECT_LE(t.yaw_mae(), 1.0);
  EXPECT_LE(t.bend_mae(), 1.5);
  EXPECT_EQ(t.gross, 0);
  EXPECT_EQ(t.unreadable_ok, 0);
}

TEST(MarkerAccuracy, GeometryCheckRejectsClutterThatFoolsTheThreeLargest) {
  Tally ours, thesis;
  for (uint64_t seed : {1, 2}) {
    RunScene(Scene(seed, "normal", 6), 14, 0, 29, 60, false, &ours);
    RunScene(Scene(seed, "normal", 6), 14, 0, 29, 60, true, &thesis);
  }
  EXPECT_GE(ours.coverage(), 0.7) << ours.ok << " of " << ours.views;
  EXPECT_LE(ours.yaw_mae(), 1.0);
  EXPECT_LE(ours.bend_mae(), 1.5);
  EXPECT_EQ(ours.gross, 0);
  // The thesis' rule takes dark clutter for markers on the same images.
  EXPECT_GE(thesis.gross, 3);
}

TEST(MarkerAccuracy, ThesisPathReadsCleanViews) {
  Tally t;
  RunScene(Scene(2, "normal", 0), 14, 0, 29, 60, true, &t);
  EXPECT_GE(t.coverage(), 0.9);
  EXPECT_LE(t.yaw_mae(), 4.0);   // acos of bounding-box centres: coarse near zero yaw
  EXPECT_LE(t.bend_mae(), 3.3);  // the thesis' own figure
}

TEST(MarkerAccuracy, ViewsPastTheVisibilityLimitAreLost) {
  Tally t;
  RunScene(Scene(3, "normal", 0), 12, 36, 60, 60, false, &t);
  RunScene(Scene(5, "mixed", 3), 12, 36, 60, 60, false, &t);
  EXPECT_EQ(t.views, 0);  // past 35 degrees a lower marker is turned beyond 75
  EXPECT_EQ(t.unreadable, 24);
  EXPECT_EQ(t.unreadable_ok, 0) << t.log;
}

}  // namespace
}  // namespace armmimic
