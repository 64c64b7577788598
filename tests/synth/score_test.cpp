#include "armmimic/synth/score.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace armmimic::synth {
namespace {

TruthRow ArmTruthRow(int frame, double upper, double fore) {
  TruthRow t;
  t.frame = frame;
  t.time_s = frame / 30.0;
  t.upper_deg = upper;
  t.fore_deg = fore;
  t.yaw_deg = 0;
  t.bend_deg = AngleDiff(fore, upper);
  return t;
}

AngleRow Ok(int frame, double upper, double fore, double yaw = kNaN, double bend = kNaN) {
  AngleRow a;
  a.frame = frame;
  a.status = RowStatus::kOk;
  a.upper_deg = upper;
  a.fore_deg = fore;
  a.yaw_deg = yaw;
  a.bend_deg = bend;
  return a;
}

AngleRow Lost(int frame) {
  AngleRow a;
  a.frame = frame;
  return a;
}

// Truth: two background frames without angles, then frames 2..11 with known directions.
TruthFile MakeTruth() {
  TruthFile t;
  for (int f = 0; f < 2; ++f) {
    TruthRow r;
    r.frame = f;
    t.rows.push_back(r);
  }
  for (int f = 2; f < 12; ++f) t.rows.push_back(ArmTruthRow(f, -90 + 10 * f, -70 + 10 * f));
  t.rows.back().upper_deg = 179;  // frame 11: a direction next to the wrap-around
  t.rows.back().fore_deg = 170;
  return t;
}

TEST(Score, KnownErrorsGiveKnownSummary) {
  const TruthFile truth = MakeTruth();
  AngleFile angles;
  // Frames 2 and 3 have no row; frame 6 is lost; frame 9's upper arm points the opposite way
  // (direction error 176, axis error 4); frame 11 crosses +-180 (error 2); frame 40 is extra.
  for (int f = 4; f < 11; ++f) {
    const TruthRow& t = *truth.Find(f);
    if (f == 6) {
      angles.rows.push_back(Lost(f));
    } else if (f == 9) {
      angles.rows.push_back(Ok(f, t.upper_deg + 184, t.fore_deg - 6));
    } else {
      angles.rows.push_back(Ok(f, t.upper_deg + 4, t.fore_deg - 6));
    }
  }
  angles.rows.push_back(Ok(11, -179, 176));
  angles.rows.push_back(Ok(40, 0, 0));
  const ScoreReport rep = ScoreAngles(truth, angles);
  const ScoreSummary& s = rep.summary;
  EXPECT_EQ(s.truth_frames, 10);
  EXPECT_EQ(s.matched_frames, 8);
  EXPECT_EQ(s.ok_frames, 7);
  EXPECT_EQ(s.lost_frames, 1);
  EXPECT_EQ(s.missing_frames, 2);
  EXPECT_EQ(s.unmatched_rows, 1);
  EXPECT_DOUBLE_EQ(s.coverage, 7.0 / 8.0);
  // Only frame 9 (upper arm reversed) is ok and off by more than 15 degrees.
  EXPECT_EQ(s.confidently_wrong_frames, 1);
  EXPECT_DOUBLE_EQ(s.confidently_wrong_rate, 1.0 / 8.0);
  EXPECT_NE(FormatScoreSummary(rep).find("coverage: 87.5% (7/8 rows ok); confidently wrong: 12.5% "
                                         "(1/8 rows ok with an error over 15 degrees)"),
            std::string::npos)
      << FormatScoreSummary(rep);
  EXPECT_TRUE(s.has_directions);
  // Upper: 4,4,4,4,176,4 (frames 4,5,7,8,9,10) and 2 (frame 11).
  EXPECT_EQ(s.upper.count, 7);
  EXPECT_NEAR(s.upper.mae, (5 * 4 + 176 + 2) / 7.0, 1e-9);
  EXPECT_NEAR(s.upper.max, 176, 1e-9);
  EXPECT_EQ(s.upper.max_frame, 9);
  EXPECT_NEAR(s.upper_axis.mae, (6 * 4 + 2) / 7.0, 1e-9);
  // Fore: 6 everywhere but frame 11 (176 vs 170: 6).
  EXPECT_NEAR(s.fore.mae, 6.0, 1e-9);
  EXPECT_NEAR(s.fore.rmse, 6.0, 1e-9);
  EXPECT_NEAR(s.overall.mae, (5 * 4 + 176 + 2 + 7 * 6) / 14.0, 1e-9);
  EXPECT_NEAR(s.overall_axis.mae, (6 * 4 + 2 + 7 * 6) / 14.0, 1e-9);
  // Yaw and bend are nan in these rows: nothing to compare.
  EXPECT_EQ(s.yaw.count, 0);
  EXPECT_EQ(s.bend.count, 0);
  // Per-frame rows: every truth frame with angles, in order.
  ASSERT_EQ(rep.rows.size(), 10u);
  EXPECT_EQ(rep.rows[0].frame, 2);
  EXPECT_FALSE(rep.rows[0].has_row);
  EXPECT_TRUE(rep.rows[4].has_row);
  EXPECT_FALSE(rep.rows[4].ok);
  EXPECT_TRUE(std::isnan(rep.rows[4].err_upper));
  EXPECT_NEAR(rep.rows[7].err_upper, 176, 1e-9);
  EXPECT_NEAR(rep.rows[7].axis_err_upper, 4, 1e-9);
  EXPECT_NEAR(rep.rows[9].err_upper, 2, 1e-9);
}

TEST(Score, YawAndBendCountOnlyWhereBothSidesHaveValues) {
  TruthFile truth;
  for (int f = 0; f < 4; ++f) {
    TruthRow r;
    r.frame = f;
    r.yaw_deg = 10.0 * f;
    r.bend_deg = f == 3 ? kNaN : -20.0 * f;
    truth.rows.push_back(r);
  }
  AngleFile angles;
  angles.has_file_column = true;
  angles.rows.push_back(Ok(0, kNaN, kNaN, 1, 3));       // yaw 1, bend 3
  angles.rows.push_back(Ok(1, kNaN, kNaN, 13, -20));    // yaw 3, bend 0
  angles.rows.push_back(Ok(2, kNaN, kNaN, kNaN, 178));  // bend: -40 vs 178 -> 142 (wrapped)
  angles.rows.push_back(Ok(3, kNaN, kNaN, 35, 0));      // yaw 5; bend truth nan
  const ScoreReport rep = ScoreAngles(truth, angles);
  const ScoreSummary& s = rep.summary;
  EXPECT_FALSE(s.has_directions);
  EXPECT_TRUE(s.has_yaw_bend);
  EXPECT_EQ(s.yaw.count, 3);
  EXPECT_NEAR(s.yaw.mae, (1 + 3 + 5) / 3.0, 1e-9);
  EXPECT_EQ(s.bend.count, 3);
  EXPECT_NEAR(s.bend.mae, (3 + 0 + 142) / 3.0, 1e-9);
  EXPECT_EQ(s.upper.count, 0);
  EXPECT_DOUBLE_EQ(s.coverage, 1.0);
  EXPECT_EQ(s.confidently_wrong_frames, 1);  // frame 2's bend
  const std::string table = FormatScoreTable(rep);
  EXPECT_NE(table.find("t_yaw"), std::string::npos);
  EXPECT_EQ(table.find("t_upper"), std::string::npos);
  const std::string summary = FormatScoreSummary(rep);
  EXPECT_NE(summary.find("yaw    : MAE 3.00"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("direction error"), std::string::npos);
}

TEST(Score, ConfidentlyWrongCountsOkRowsWhoseWorseSegmentIsOffByMoreThan15Degrees) {
  const TruthFile truth = MakeTruth();  // frames 2..11 have angles
  AngleFile angles;
  const double upper_off[] = {15, 15.5, 0, -20, 0, 0};
  const double fore_off[] = {0, 0, 16, 0, 14.9, 0};
  for (int i = 0; i < 6; ++i) {
    const TruthRow& t = *truth.Find(2 + i);
    angles.rows.push_back(Ok(t.frame, t.upper_deg + upper_off[i], t.fore_deg + fore_off[i]));
  }
  angles.rows.push_back(Lost(8));  // a lost frame is never confidently wrong
  const ScoreSummary s = ScoreAngles(truth, angles).summary;
  EXPECT_EQ(s.matched_frames, 7);
  EXPECT_EQ(s.confidently_wrong_frames, 3);  // 15.5 upper, 16 fore, 20 upper
  EXPECT_DOUBLE_EQ(s.confidently_wrong_rate, 3.0 / 7.0);
}

TEST(Score, NoMatchingRowsLeavesCoverageUnknown) {
  const TruthFile truth = MakeTruth();
  AngleFile angles;
  angles.rows.push_back(Ok(500, 0, 0));
  const ScoreReport rep = ScoreAngles(truth, angles);
  EXPECT_EQ(rep.summary.matched_frames, 0);
  EXPECT_TRUE(std::isnan(rep.summary.coverage));
  EXPECT_EQ(rep.summary.unmatched_rows, 1);
  EXPECT_NE(FormatScoreSummary(rep).find("no truth frame has a row"), std::string::npos);
}

TEST(Score, TableListsRowsWithStatusAndErrors) {
  const TruthFile truth = MakeTruth();
  AngleFile angles;
  angles.rows = {Ok(4, -46, -26), Lost(5)};
  const ScoreReport rep = ScoreAngles(truth, angles);
  const std::string table = FormatScoreTable(rep);
  // Header plus two rows: frames without a row are only counted.
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 3);
  EXPECT_NE(table.find("lost"), std::string::npos);
  // Frame 4: truth -50/-30, calculated -46/-26 -> errors 4.00 and 4.00.
  EXPECT_NE(table.find("-50.00   -30.00   -46.00   -26.00     4.00     4.00"), std::string::npos)
      << table;
}

TEST(Score, PlotDrawsOneLinePerSegmentAndMarksLostFrames) {
  const TruthFile truth = MakeTruth();
  AngleFile angles;
  for (int f = 2; f < 12; ++f) {
    const TruthRow& t = *truth.Find(f);
    angles.rows.push_back(f == 6 ? Lost(f) : Ok(f, t.upper_deg + f, t.fore_deg - 2));
  }
  const cv::Mat plot = PlotScore(ScoreAngles(truth, angles), {640, 320});
  ASSERT_EQ(plot.size(), cv::Size(640, 320));
  ASSERT_EQ(plot.type(), CV_8UC3);
  auto count = [&](cv::Vec3b c) {
    int n = 0;
    for (int y = 0; y < plot.rows; ++y) {
      for (int x = 0; x < plot.cols; ++x) n += plot.at<cv::Vec3b>(y, x) == c;
    }
    return n;
  };
  EXPECT_GT(count({200, 90, 20}), 50);  // upper arm line
  EXPECT_GT(count({30, 40, 210}), 50);  // forearm line
  EXPECT_GT(count({0, 0, 220}), 5);     // lost-frame mark
}

}  // namespace
}  // namespace armmimic::synth
