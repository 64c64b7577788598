// Planner: an angle series (angle file v1) -> a timed joint trajectory for the PUMA (thesis
// appendix C). Steps, in order:
//   1. unwrap upper/bend so each is continuous with the previous frame, starting from the first
//      measured (initial) posture; a change faster than max_jump_deg_s is flagged as impossible
//      and the frame treated as lost;
//   2. lost frames: leading/trailing ones are dropped; inner gaps up to max_gap_s are held or
//      interpolated, a longer gap refuses the plan;
//   3. map to joints (mapping.h); yaw is held while NaN (bent arm);
//   4. zero-phase low-pass at cutoff_hz (0: off);
//   5. joint limits: refuse listing the offending frames, or clamp and report;
//   6. keyframes: a new one when any joint moved more than deadband_deg from the last keyframe
//      (but not sooner than min_interval_s) or max_interval_s passed; the last frame always;
//   7. speed: a step faster than a joint's speed limit stretches the time (or refuses).
#pragma once

#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/robot/limits.h"
#include "armmimic/robot/mapping.h"
#include "armmimic/robot/trajectory.h"

namespace armmimic::robot {

enum class GapMode { kHold, kInterpolate };
enum class SpeedPolicy { kStretch, kRefuse };

struct PlannerOptions {
  MappingOptions mapping;
  JointLimits limits;
  double cutoff_hz = 3.0;
  double max_gap_s = 0.5;
  GapMode gap = GapMode::kInterpolate;
  double max_jump_deg_s = 1000;  // faster than any human arm: a flipped or wrong measurement
  double deadband_deg = 2.0;
  double min_interval_s = 0.2;  // at most 5 moves a second, whatever the video's frame rate
  double max_interval_s = 1.0;
  bool clamp = false;
  SpeedPolicy speed = SpeedPolicy::kStretch;
  // Rows whose time_s does not increase (e.g. a folder of marker images) are taken as this many
  // frames per second instead.
  double fallback_fps = 1.0;

  // Every value sensible; the message names the option.
  Status Check() const;
};

struct PlanIssue {
  int frame = 0;
  std::string text;
};

struct PlanReport {
  int rows = 0;           // rows in the angle file
  int used_rows = 0;      // rows between the first and last measured frame
  int filled_rows = 0;    // lost (or flagged) rows filled by hold/interpolation
  int flagged_jumps = 0;  // rows whose change was impossibly fast
  int clamped_rows = 0;   // rows with a joint clamped to its limit
  int stretched_steps = 0;
  double source_duration_s = 0;  // first to last used row in the video
  double stretch_s = 0;          // time added by the speed limits
  double sample_rate_hz = 0;
  // The low-pass cutoff applied: options.cutoff_hz, or 0 for rows with no frame rate (still
  // images, such as the marker engine's views), which are planned unfiltered.
  double filter_cutoff_hz = 0;
  JointArray min_deg{};  // range of the keyframes, per joint
  JointArray max_deg{};
  std::string mapping;              // the mapping used (MappingOptions::Describe())
  std::vector<PlanIssue> warnings;  // flagged jumps, filled gaps, clamps (first few of each)
};

// The mapping used for a source of `source_kind`: `mapping` itself, or, when it follows the
// file's kind and was left at the defaults of the other kind, that kind's defaults (keeping
// mirror and holds; *adapted says so). A changed mapping for the other kind is refused.
Status MappingForSource(const MappingOptions& mapping, SourceKind source_kind, MappingOptions* out,
                        bool* adapted = nullptr);

// A mapping left at the defaults of its kind follows the file's kind (DetectSourceKind), keeping
// mirror and holds; a changed mapping for the other kind is refused.
Status PlanTrajectory(const AngleFile& angles, const PlannerOptions& options, Trajectory* out,
                      PlanReport* report);

// The "; key=value" lines that head a planned .val (FormatValProgram's header): the source, the
// mapping, the filter and keyframe settings and what the plan did. `source` is named as given.
std::vector<std::string> DescribePlan(const std::string& source, const AngleFile& angles,
                                      const PlannerOptions& options, const PlanReport& report,
                                      const Trajectory& trajectory);

// Step 6 and 7 on their own (used by the planner, exposed for tests). `times_s` ascending.
std::vector<int> SelectKeyframes(const std::vector<double>& times_s,
                                 const std::vector<JointArray>& joints_deg,
                                 const PlannerOptions& options);
// Stretches keyframe times so no step is faster than the speed limits. Returns the time added;
// with SpeedPolicy::kRefuse, fails naming the first too-fast step.
Status EnforceSpeedLimits(Trajectory* trajectory, const JointLimits& limits, SpeedPolicy policy,
                          double* stretch_s, int* stretched_steps);

}  // namespace armmimic::robot
