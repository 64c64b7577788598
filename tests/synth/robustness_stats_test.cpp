// The robustness benchmark's arithmetic on hand-made truth and angle rows.
#include "armmimic/synth/robustness_stats.h"

#include <cmath>

#include <gtest/gtest.h>

namespace armmimic::synth {
namespace {

// Frames 0..9 with angles; the motion starts at frame 4.
TruthFile Truth() {
  TruthFile t;
  for (int f = 0; f < 10; ++f) {
    TruthRow r;
    r.frame = f;
    r.upper_deg = f < 4 ? -90 : -90 + 20 * (f - 4);
    r.fore_deg = r.upper_deg;
    r.bend_deg = 0;
    t.rows.push_back(r);
  }
  return t;
}

AngleRow Row(int frame, bool ok, double upper, double fore) {
  AngleRow a;
  a.frame = frame;
  a.status = ok ? RowStatus::kOk : RowStatus::kLost;
  a.upper_deg = ok ? upper : kNaN;
  a.fore_deg = ok ? fore : kNaN;
  return a;
}

TEST(RobustnessStats, ScoreMotionCountsOnlyMotionFramesAndMissingRowsAsNotOk) {
  const TruthFile truth = Truth();
  AngleFile angles;
  angles.rows.push_back(Row(2, true, 0, 0));  // a standstill frame: not scored
  // Frame 4: errors 2 and 4. Frame 5 lost. Frame 6: 20 and 0 (confidently wrong). Frame 7: 1, 1.
  // Frame 8: upper reversed (180), fore right. Frame 9: no row.
  angles.rows.push_back(Row(4, true, -88, -94));
  angles.rows.push_back(Row(5, false, 0, 0));
  angles.rows.push_back(Row(6, true, -30, -50));
  angles.rows.push_back(Row(7, true, -29, -31));
  angles.rows.push_back(Row(8, true, 170, -10));
  const MotionScore m = ScoreMotion(ScoreAngles(truth, angles), 4);
  EXPECT_EQ(m.motion_frames, 6);
  EXPECT_EQ(m.ok_frames, 4);
  EXPECT_DOUBLE_EQ(m.coverage(), 4.0 / 6.0);
  EXPECT_EQ(m.confidently_wrong_frames, 2);
  EXPECT_NEAR(m.mean_error_deg, (3 + 10 + 1 + 90) / 4.0, 1e-9);
  EXPECT_NEAR(m.worst_error_deg, 180, 1e-9);
}

TEST(RobustnessStats, AStaleOrEmptyRunHasZeroCoverageAndNoError) {
  const MotionScore m = ScoreMotion(ScoreAngles(Truth(), AngleFile{}), 4);
  EXPECT_EQ(m.motion_frames, 6);
  EXPECT_EQ(m.ok_frames, 0);
  EXPECT_DOUBLE_EQ(m.coverage(), 0);
  EXPECT_TRUE(std::isnan(m.mean_error_deg));
}

TEST(RobustnessStats, QuantilesInterpolateBetweenOrderStatistics) {
  EXPECT_TRUE(std::isnan(Quantile({}, 0.5)));
  EXPECT_DOUBLE_EQ(Quantile({7}, 0.9), 7);
  EXPECT_DOUBLE_EQ(Quantile({4, 1, 3, 2}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(Quantile({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, 0.9), 10);
  EXPECT_DOUBLE_EQ(Quantile({1, 2}, 0.9), 1.9);
  EXPECT_DOUBLE_EQ(Quantile({5, 1, 9}, 1.0), 9);
}

TEST(RobustnessStats, SummaryPoolsFramesAndKeepsTheWorstScene) {
  MotionScore a, b, c;
  a.motion_frames = 100, a.ok_frames = 100, a.mean_error_deg = 1, a.confidently_wrong_frames = 0;
  b.motion_frames = 50, b.ok_frames = 25, b.mean_error_deg = 9, b.confidently_wrong_frames = 5;
  c.motion_frames = 50, c.ok_frames = 0;
  const RobustnessSummary s = SummariseRobustness({a, b, c});
  EXPECT_EQ(s.scenes, 3);
  EXPECT_EQ(s.zero_coverage_scenes, 1);
  EXPECT_DOUBLE_EQ(s.coverage, 125.0 / 200.0);
  EXPECT_DOUBLE_EQ(s.worst_coverage, 0);
  EXPECT_DOUBLE_EQ(s.confidently_wrong_rate, 5.0 / 200.0);
  EXPECT_DOUBLE_EQ(s.median_deg, 5);  // of the two scenes with an error
  EXPECT_DOUBLE_EQ(s.max_deg, 9);
  EXPECT_NEAR(s.p90_deg, 8.2, 1e-12);
}

}  // namespace
}  // namespace armmimic::synth
