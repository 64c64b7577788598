// The hybrid engine with no empty room and the pose network as its second opinion
// (hybrid/pose_opinion.h), on the generated person the network sees (synth arm's default
// scene, the moving arm on screen right: the person's own left), joints clicked from the truth
// at the first motion frame: the network follows the arm at the clicked shoulder, and the rows
// are the two measurements' mean where they agree. A shoulder clicked where the network sees
// none gives no row that leans on it. Compiled in only with the pose model.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "arm_errors.h"
#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/arm_scene.h"

#ifdef ARMMIMIC_HAVE_POSE_MODEL

namespace armmimic {
namespace {

struct HybridRun {
  int rows = 0, ok = 0, wrong = 0;
  double sum = 0;  // mean of |d upper| and |d fore| over ok rows
  std::string second_opinion, estimates, notes;
};

// Every 2nd of the first 60 motion frames; `shift` moves the clicked joints.
HybridRun RunHybrid(const cv::Point2d& shift) {
  synth::ArmSceneOptions o;
  synth::ArmSceneRenderer scene(o);
  const int first = o.first_motion_frame();
  synth::ArmTruth t;
  scene.Render(first, &t);
  EngineContext ctx;
  ctx.frame_size = o.size;
  ctx.fps = o.fps;
  ctx.shoulder_px = t.shoulder_px + shift;
  ctx.elbow_px = t.elbow_px + shift;
  ctx.wrist_px = t.wrist_px + shift;
  EngineOptions eo;
  eo.kind = EngineKind::kHybrid;
  auto engine = Engine::Create(eo);
  HybridRun run;
  const Status st = engine->Begin(ctx);
  EXPECT_TRUE(st.ok()) << st.message();
  if (!st) return run;
  for (const auto& [key, value] : engine->Describe()) {
    if (key == "second_opinion") run.second_opinion = value;
  }
  for (int i = first; i < first + 60 && i < o.frame_count(); i += 2) {
    Frame f;
    f.index = i;
    f.time_s = i / o.fps;
    synth::ArmTruth truth;
    f.image = scene.Render(i, &truth);
    const ArmMeasurement m = engine->Process(f);
    run.estimates += m.estimate;
    run.notes += m.note + "\n";
    if (!m.row()) continue;
    ++run.rows;
    if (m.phase != MeasurementPhase::kOk) continue;
    ++run.ok;
    const test::SegmentErrors e = test::ErrorsAgainst(m, truth);
    run.sum += e.mean();
    run.wrong += e.wrong();
  }
  return run;
}

TEST(HybridPoseOpinion, FollowsTheArmAtTheClickedShoulder) {
  const HybridRun r = RunHybrid({0, 0});
  std::printf(
      "hybrid, pose network as the second opinion: %d of %d rows ok, MAE %.2f deg, %d "
      "wrong\n",
      r.ok, r.rows, r.ok ? r.sum / r.ok : kNaN, r.wrong);
  EXPECT_EQ(r.second_opinion, "pose");
  EXPECT_NE(r.estimates.find("follows the person's left arm"), std::string::npos) << r.estimates;
  EXPECT_GE(r.ok, r.rows * 8 / 10);
  ASSERT_GT(r.ok, 0);
  EXPECT_LE(r.sum / r.ok, 5.0);
  EXPECT_EQ(r.wrong, 0);
}

TEST(HybridPoseOpinion, AShoulderClickedWhereTheNetworkSeesNoneGivesNoRow) {
  // The joints clicked 80 px to the side of the person, on the room's wall.
  const HybridRun r = RunHybrid({80, 0});
  EXPECT_EQ(r.second_opinion, "pose");
  EXPECT_EQ(r.ok, 0);
  EXPECT_EQ(r.estimates.find("follows the person's"), std::string::npos) << r.estimates;
}

}  // namespace
}  // namespace armmimic

#endif
