// Scoring an angle file against a truth file (thesis Tables 5-1 and 6-1, Fig. 5-10): rows are
// matched by frame index; direction errors are wrapped differences, the axis error is the
// difference modulo 180 (the thesis measured orientation, an axis).
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "armmimic/core/status.h"
#include "armmimic/synth/truth_file.h"

namespace armmimic::synth {

// An `ok` row whose worse segment is off by more than this many degrees is confidently wrong: a
// wrong answer that looks like a right one.
inline constexpr double kConfidentlyWrongDeg = 15;

// One truth frame that has angles.
struct ScoreRow {
  int frame = 0;
  bool has_row = false;  // the angle file has a row for this frame
  bool ok = false;       // ... and its status is ok
  double truth_upper = kNaN, truth_fore = kNaN, truth_yaw = kNaN, truth_bend = kNaN;
  double calc_upper = kNaN, calc_fore = kNaN, calc_yaw = kNaN, calc_bend = kNaN;
  // Absolute errors in degrees; nan where either side has no value.
  double err_upper = kNaN;  // |wrapped difference| of directions, [0, 180]
  double err_fore = kNaN;
  double axis_err_upper = kNaN;  // difference mod 180, [0, 90]
  double axis_err_fore = kNaN;
  double err_yaw = kNaN;
  double err_bend = kNaN;  // |wrapped difference|
};

struct ErrorStats {
  int count = 0;      // values that entered the statistics
  double mae = kNaN;  // mean absolute error
  double rmse = kNaN;
  double max = kNaN;
  int max_frame = -1;
};

struct ScoreSummary {
  int truth_frames = 0;    // truth rows with angles
  int matched_frames = 0;  // ... that the angle file has a row for
  int ok_frames = 0;       // ... whose row is ok
  int lost_frames = 0;     // ... whose row is lost
  int missing_frames = 0;  // truth rows with angles and no row in the angle file
  int unmatched_rows = 0;  // angle rows whose frame is not a truth frame with angles
  double coverage = kNaN;  // ok_frames / matched_frames
  // Ok rows whose worse error exceeds kConfidentlyWrongDeg: of the upper arm and forearm
  // directions where the truth has them (arm scenes), else of yaw and bend (marker scenes).
  int confidently_wrong_frames = 0;
  double confidently_wrong_rate = kNaN;            // confidently_wrong_frames / matched_frames
  ErrorStats upper, fore;                          // direction errors
  ErrorStats overall;                              // upper and fore together
  ErrorStats upper_axis, fore_axis, overall_axis;  // mod-180 errors
  ErrorStats yaw, bend;                            // where both sides have values
  bool has_directions = false;                     // the truth has upper/fore (arm scenes)
  bool has_yaw_bend = false;                       // the truth has yaw or bend values
};

struct ScoreReport {
  std::vector<ScoreRow> rows;  // truth frames with angles, in frame order
  ScoreSummary summary;
};

ScoreReport ScoreAngles(const TruthFile& truth, const AngleFile& angles);

// Per-frame table (thesis Table 5-1 layout) and the summary, as plain text.
std::string FormatScoreTable(const ScoreReport& report);
std::string FormatScoreSummary(const ScoreReport& report);

// Error-vs-frame plot like thesis Fig. 5-10: one line per segment (or yaw/bend), lost and
// missing frames marked along the axis. CV_8UC3, `size` pixels.
cv::Mat PlotScore(const ScoreReport& report, cv::Size size = {800, 400});

}  // namespace armmimic::synth
