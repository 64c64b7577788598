// The robustness benchmark's arithmetic (docs/accuracy.md): one engine run on one scene scored
// over the scene's motion frames, and many such scenes summarised.
#pragma once

#include <vector>

#include "armmimic/core/angles.h"
#include "armmimic/synth/score.h"

namespace armmimic::synth {

// One engine run on one scene, over the motion frames (the frames after the standstill).
struct MotionScore {
  int motion_frames = 0;             // truth frames with angles from the first motion frame on
  int ok_frames = 0;                 // ... with an ok row
  int confidently_wrong_frames = 0;  // ... whose worse segment is off by > kConfidentlyWrongDeg
  // The scene's error: the mean over its ok frames of the mean of |d upper| and |d fore|
  // (wrapped differences); nan without ok frames.
  double mean_error_deg = kNaN;
  double worst_error_deg = kNaN;  // the largest worse-segment error of an ok frame
  double coverage() const {
    return motion_frames > 0 ? static_cast<double>(ok_frames) / motion_frames : 0.0;
  }
};

// Scores `report` (ScoreAngles) from `first_motion_frame` on. A motion frame without a row in
// the angle file counts as not ok.
MotionScore ScoreMotion(const ScoreReport& report, int first_motion_frame);

// Many scenes of one engine, calibration mode and tier.
struct RobustnessSummary {
  int scenes = 0;
  int zero_coverage_scenes = 0;  // no ok frame at all
  // The distribution of the per-scene mean errors over the scenes with an ok frame.
  double median_deg = kNaN, p90_deg = kNaN, max_deg = kNaN;
  int motion_frames = 0, ok_frames = 0, confidently_wrong_frames = 0;  // pooled
  double coverage = kNaN;                                              // ok_frames / motion_frames
  double worst_coverage = kNaN;          // the lowest coverage of a scene
  double confidently_wrong_rate = kNaN;  // confidently_wrong_frames / motion_frames
};

RobustnessSummary SummariseRobustness(const std::vector<MotionScore>& scenes);

// The q-quantile (0..1) of `values` by linear interpolation between order statistics
// (position q * (n - 1)); nan for no values.
double Quantile(std::vector<double> values, double q);

}  // namespace armmimic::synth
