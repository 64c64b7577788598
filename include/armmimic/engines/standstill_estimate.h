// The joints a tracking engine (lk, hybrid) calibrates itself from in the thesis protocol,
// estimated before the run: the standstill's mean over frames [start, start + N) against the
// background (an image or the mean of the first K frames) and the arm-length image, through the
// same calibration and parameters the engine uses (lk.body_threshold, lk.side,
// lk.upper_fraction, lk.standstill_frames). The shells show them on the last standstill frame,
// for the operator to accept or correct.
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/core/status.h"
#include "armmimic/engines/analysis.h"

namespace armmimic {

struct StandstillJoints {
  int frame = -1;  // the last standstill frame, start + N - 1, the run's starting posture
  cv::Point2d shoulder_px{kNaN, kNaN}, elbow_px{kNaN, kNaN}, wrist_px{kNaN, kNaN};  // full image
  std::string description;  // every estimate in one line, as the run logs it
};

// Opens options' input (open_source or inputs), averages the standstill and calibrates. The
// engine must be lk or hybrid, with a background, an arm-length image and a standstill inside
// the input. Errors are keyed by the setting they are about ("analysis.arm_length"); a scene
// the images do not support is refused with the calibration's reason.
Status EstimateStandstillJoints(const AnalysisOptions& options, StandstillJoints* out);

}  // namespace armmimic
