// The planner's options and the steps PlanTrajectory (plan_trajectory.cpp) ends with: keyframe
// selection, the speed limits, the mapping for the file's kind, and the plan's description.
#include "armmimic/robot/planner.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "armmimic/core/text.h"
#include "armmimic/robot/option_tables.h"

namespace armmimic::robot {
namespace {

std::string Num(double v, int decimals = 2) { return FormatNumber(v, decimals); }

std::string JointName(int j) { return "J" + std::to_string(j + 1); }

}  // namespace

Status PlannerOptions::Check() const {
  Status s = mapping.Check();
  if (!s.ok()) return s;
  s = limits.Check();
  if (!s.ok()) return s;
  // Every range and the relation min interval <= max interval, from the planner's table.
  return CheckOptionFields(PlannerOptionFields(), "planner", *this);
}

std::vector<int> SelectKeyframes(const std::vector<double>& times_s,
                                 const std::vector<JointArray>& joints_deg,
                                 const PlannerOptions& options) {
  std::vector<int> keys;
  const int n = static_cast<int>(times_s.size());
  if (n == 0) return keys;
  keys.push_back(0);
  for (int i = 1; i < n; ++i) {
    const int last = keys.back();
    const double dt = times_s[i] - times_s[last];
    double moved = 0;
    for (int j = 0; j < kJoints; ++j) {
      moved = std::max(moved, std::abs(joints_deg[i][j] - joints_deg[last][j]));
    }
    const bool by_motion = moved > options.deadband_deg && dt >= options.min_interval_s - 1e-9;
    const bool by_time = dt >= options.max_interval_s - 1e-9;
    if (by_motion || by_time) keys.push_back(i);
  }
  if (keys.back() != n - 1) {
    // The final pose always ends the plan; it replaces a keyframe that would come too soon
    // before it when the two are within the deadband.
    const int last = keys.back();
    double moved = 0;
    for (int j = 0; j < kJoints; ++j) {
      moved = std::max(moved, std::abs(joints_deg[n - 1][j] - joints_deg[last][j]));
    }
    if (keys.size() > 1 && moved <= options.deadband_deg &&
        times_s[n - 1] - times_s[last] < options.min_interval_s) {
      keys.back() = n - 1;
    } else {
      keys.push_back(n - 1);
    }
  }
  return keys;
}

Status EnforceSpeedLimits(Trajectory* trajectory, const JointLimits& limits, SpeedPolicy policy,
                          double* stretch_s, int* stretched_steps) {
  double added = 0;
  int steps = 0;
  auto& kf = trajectory->keyframes;
  for (std::size_t k = 1; k < kf.size(); ++k) {
    kf[k].time_s += added;
    const double dt = kf[k].time_s - kf[k - 1].time_s;
    double need = 0;
    int worst = 0;
    for (int j = 0; j < kJoints; ++j) {
      const double t =
          std::abs(kf[k].joint_deg[j] - kf[k - 1].joint_deg[j]) / limits.max_speed_deg_s[j];
      if (t > need) {
        need = t;
        worst = j;
      }
    }
    if (need > dt + 1e-9) {
      if (policy == SpeedPolicy::kRefuse) {
        const double delta = std::abs(kf[k].joint_deg[worst] - kf[k - 1].joint_deg[worst]);
        return Status::Error(
            "frame " + std::to_string(kf[k].frame) + ": " + JointName(worst) + " would move " +
            Num(delta) + " deg in " + Num(dt, 3) + " s (" + Num(dt > 0 ? delta / dt : INFINITY, 1) +
            " deg/s), over its speed limit of " + Num(limits.max_speed_deg_s[worst], 1) + " deg/s");
      }
      added += need - dt;
      kf[k].time_s += need - dt;
      ++steps;
    }
  }
  if (stretch_s) *stretch_s = added;
  if (stretched_steps) *stretched_steps = steps;
  return Status::Ok();
}

Status MappingForSource(const MappingOptions& mapping, SourceKind source_kind, MappingOptions* out,
                        bool* adapted) {
  *out = mapping;
  if (adapted) *adapted = false;
  if (!mapping.follow_file_kind || source_kind == mapping.kind) return Status::Ok();
  const MappingOptions d = MappingOptions::Default(mapping.kind);
  const bool untouched = mapping.j1.sign == d.j1.sign && mapping.j1.offset_deg == d.j1.offset_deg &&
                         mapping.j2.sign == d.j2.sign && mapping.j2.offset_deg == d.j2.offset_deg &&
                         mapping.j3.sign == d.j3.sign && mapping.j3.offset_deg == d.j3.offset_deg &&
                         mapping.j2_elevation && mapping.j3_flexion;
  if (!untouched) {
    return Status::Error(std::string("the angle file comes from the ") +
                         (source_kind == SourceKind::kMarker ? "marker engine" : "arm engines") +
                         " but the mapping was set up for the " + SourceKindName(mapping.kind) +
                         (mapping.kind == SourceKind::kMarker ? " engine" : " engines"));
  }
  *out = MappingOptions::Default(source_kind);
  out->mirror = mapping.mirror;
  out->hold_deg = mapping.hold_deg;
  if (adapted) *adapted = true;
  return Status::Ok();
}

std::vector<std::string> DescribePlan(const std::string& source, const AngleFile& angles,
                                      const PlannerOptions& o, const PlanReport& report,
                                      const Trajectory& trajectory) {
  return {
      "source=" + PercentEncode(source) + " engine=" + PercentEncode(angles.Meta("engine", "?")) +
          " rows=" + std::to_string(report.rows) + " fps=" + Num(report.sample_rate_hz, 3),
      "mapping=" + report.mapping,
      "filter cutoff_hz=" + Num(report.filter_cutoff_hz, 3) +
          " gap=" + (o.gap == GapMode::kHold ? "hold" : "interpolate") +
          " max_gap_s=" + Num(o.max_gap_s, 3) + " max_jump_deg_s=" + Num(o.max_jump_deg_s, 1),
      "keyframes deadband_deg=" + Num(o.deadband_deg, 3) +
          " min_interval_s=" + Num(o.min_interval_s, 3) +
          " max_interval_s=" + Num(o.max_interval_s, 3) + " clamp=" + (o.clamp ? "yes" : "no") +
          " on_speed=" + (o.speed == SpeedPolicy::kRefuse ? "refuse" : "stretch"),
      "plan duration_s=" + Num(trajectory.duration_s(), 3) + " stretch_s=" +
          Num(report.stretch_s, 3) + " filled_rows=" + std::to_string(report.filled_rows) +
          " flagged_jumps=" + std::to_string(report.flagged_jumps) +
          " clamped_rows=" + std::to_string(report.clamped_rows),
      DescribePlannerSettings(o),
  };
}

}  // namespace armmimic::robot
