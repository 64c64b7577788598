// The hybrid engine on real footage with no empty room (the real clip, joints clicked at frame 0
// from its reference keypoints): the pose network is the second opinion, so the tracker's rows
// are checked against it, and where the tracker has lost the arm (squats at 5 fps: the forearm
// turns 20-45 degrees and the shoulder moves 50 px between frames) the network's own row stands.
// Scored against the clip's reference keypoints, which any network misses by 4-7 degrees.
// Compiled in only with the pose model and the clip (tests/engines/CMakeLists.txt).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "../pose/reference_directions.h"
#include "armmimic/core/angles.h"
#include "armmimic/core/video_source.h"
#include "armmimic/engines/engine.h"

#if defined(ARMMIMIC_HAVE_POSE_MODEL) && defined(ARMMIMIC_REAL_DIR)

namespace armmimic {
namespace {

struct ArmRun {
  int rows = 0, ok = 0, over30 = 0;
  double upper_sum = 0, fore_sum = 0;
  std::string second_opinion;
};

// Each arm's joints at frame 0 (the reference's pixels, as an operator would click them).
ArmRun RunArm(cv::Point2d shoulder, cv::Point2d elbow, cv::Point2d wrist, int column) {
  const std::string dir = ARMMIMIC_REAL_DIR;
  const auto ref = test::ReadReferenceDirections(dir + "/pose_squats.keypoints.tsv");
  Status st;
  auto video = VideoSource::Open(dir + "/pose_squats.mp4", &st);
  EXPECT_TRUE(video) << st.message();
  ArmRun run;
  if (!video) return run;
  EngineOptions o;
  o.kind = EngineKind::kHybrid;
  auto engine = Engine::Create(o);
  EngineContext context;
  context.frame_size = video->info().size;
  context.fps = video->info().fps;
  context.shoulder_px = shoulder;
  context.elbow_px = elbow;
  context.wrist_px = wrist;
  const Status begun = engine->Begin(context);
  EXPECT_TRUE(begun.ok()) << begun.message();
  if (!begun) return run;
  for (const auto& [key, value] : engine->Describe()) {
    if (key == "second_opinion") run.second_opinion = value;
  }
  Frame f;
  while (video->Read(&f, &st)) {
    const ArmMeasurement m = engine->Process(f);
    if (!m.row()) continue;
    ++run.rows;
    if (m.phase != MeasurementPhase::kOk) continue;
    ++run.ok;
    const auto& r = ref.at(f.index);
    const double du = std::abs(AngleDiff(m.upper_deg, r[column]));
    const double df = std::abs(AngleDiff(m.fore_deg, r[column + 1]));
    run.upper_sum += du;
    run.fore_sum += df;
    if (std::max(du, df) > 30) ++run.over30;
  }
  EXPECT_TRUE(st.ok()) << st.message();
  return run;
}

// Measured: left arm 47 of 65 rows ok, upper 4.6 / forearm 4.6 degrees; right 60 of 65, 5.0 /
// 3.4; no row more than 30 degrees off. Before a tracker that disagrees with the network let the
// network's row stand (it had only counted as lost for the restart), 41 and 54 rows, 4.8 / 4.8
// and 4.8 / 3.0. The tracker alone (no second opinion) kept 2 and 3 rows, the right arm's 46 / 17
// degrees off with 2 rows more than 30 off.
TEST(HybridRealClip, ThePoseNetworkIsTheSecondOpinionWithoutAnEmptyRoom) {
  const ArmRun left = RunArm({411.96, 343.44}, {439.53, 466.98}, {484.4, 570.0}, 0);
  const ArmRun right = RunArm({266.74, 331.35}, {215.66, 452.39}, {196.93, 560.5}, 2);
  for (const ArmRun* r : {&left, &right}) {
    std::printf("%s arm: %d of %d rows ok, upper %.1f, forearm %.1f deg, %d over 30\n",
                r == &left ? "left" : "right", r->ok, r->rows, r->upper_sum / r->ok,
                r->fore_sum / r->ok, r->over30);
    EXPECT_EQ(r->second_opinion, "pose");
    EXPECT_EQ(r->rows, 65);
    EXPECT_EQ(r->over30, 0);
    ASSERT_GT(r->ok, 0);
    EXPECT_LE(r->upper_sum / r->ok, 6.5);
    EXPECT_LE(r->fore_sum / r->ok, 6.5);
  }
  EXPECT_GE(left.ok + right.ok, 100);  // 107 of 130 measured
}

}  // namespace
}  // namespace armmimic

#endif
