#include "armmimic/robot/planner.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "armmimic/core/angles.h"
#include "armmimic/core/text.h"
#include "armmimic/robot/filter.h"

namespace armmimic::robot {
namespace {

constexpr int kListed = 5;  // offending frames listed in a message before "... and N more"

std::string Num(double v, int decimals = 2) { return FormatNumber(v, decimals); }

std::string JointName(int j) { return "J" + std::to_string(j + 1); }

double ParseFps(const std::string& text) {
  double v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !(v > 0) || !std::isfinite(v)) {
    return 0;
  }
  return v;
}

// "a, b, c (first 5 of 12)"
std::string ListItems(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t i = 0; i < items.size() && i < kListed; ++i) {
    if (i) s += ", ";
    s += items[i];
  }
  if (items.size() > kListed) s += " ... and " + std::to_string(items.size() - kListed) + " more";
  return s;
}

void Warn(PlanReport* r, int frame, const std::string& text) {
  if (r->warnings.size() < 20) r->warnings.push_back({frame, text});
}

}  // namespace

Status PlannerOptions::Check() const {
  Status s = mapping.Check();
  if (!s.ok()) return s;
  s = limits.Check();
  if (!s.ok()) return s;
  if (!(cutoff_hz >= 0) || !std::isfinite(cutoff_hz))
    return Status::Error("planner.cutoff_hz", "cutoff must be >= 0 Hz");
  if (!(max_gap_s >= 0) || !std::isfinite(max_gap_s))
    return Status::Error("planner.max_gap_s", "max gap must be >= 0 s");
  if (!(max_jump_deg_s > 0))
    return Status::Error("planner.max_jump_deg_s", "max jump speed must be > 0 deg/s");
  if (!(deadband_deg >= 0) || !std::isfinite(deadband_deg)) {
    return Status::Error("planner.deadband_deg", "deadband must be >= 0 deg");
  }
  if (!(min_interval_s >= 0) || !std::isfinite(min_interval_s)) {
    return Status::Error("planner.min_interval_s", "min interval must be >= 0 s");
  }
  if (!(max_interval_s > 0) || !std::isfinite(max_interval_s) || max_interval_s < min_interval_s) {
    return Status::Error("planner.max_interval_s",
                         "max interval must be > 0 s and not below the min interval");
  }
  if (!(fallback_fps > 0) || !std::isfinite(fallback_fps)) {
    return Status::Error("planner.fallback_fps", "fallback fps must be > 0");
  }
  return Status::Ok();
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

Status PlanTrajectory(const AngleFile& angles, const PlannerOptions& options, Trajectory* out,
                      PlanReport* report_out) {
  Status s = options.Check();
  if (!s.ok()) return s;
  PlanReport report;
  const auto& rows = angles.rows;
  const int n = static_cast<int>(rows.size());
  report.rows = n;
  if (n == 0) return Status::Error("the angle file has no rows");
  // A mapping left at its kind's defaults follows the file's engine kind (so plain defaults
  // plan marker and arm files alike); a customised mapping for the other kind is refused.
  MappingOptions mapping;
  {
    bool adapted = false;
    const Status ms =
        MappingForSource(options.mapping, DetectSourceKind(angles), &mapping, &adapted);
    if (!ms.ok()) return ms;
    if (adapted) {
      Warn(&report, rows.empty() ? 0 : rows[0].frame,
           std::string("default ") + SourceKindName(mapping.kind) + " mapping used for this " +
               SourceKindName(mapping.kind) + " file: " + mapping.Describe());
    }
  }
  const bool marker = mapping.kind == SourceKind::kMarker;
  report.mapping = mapping.Describe();

  // Times: the file's, or frame counts at fallback_fps when they do not increase.
  std::vector<double> t(n);
  bool increasing = true;
  for (int i = 0; i < n; ++i) {
    t[i] = rows[i].time_s;
    if (!std::isfinite(t[i]) || (i > 0 && !(t[i] > t[i - 1]))) increasing = false;
  }
  double fs = ParseFps(angles.Meta("fps"));
  // Still images (no frame rate) are spaced by a made-up rate; a low-pass filter over them would
  // mean nothing, and the default cutoff is not even below half of 1 fps.
  const bool still_images = !(fs > 0) && n > 1;
  double cutoff_hz = options.cutoff_hz;
  if (cutoff_hz > 0 && still_images) {
    cutoff_hz = 0;
    Warn(&report, rows[0].frame,
         "no frame rate (still images): planned without the low-pass filter");
  }
  report.filter_cutoff_hz = cutoff_hz;
  if (!increasing) {
    fs = options.fallback_fps;
    for (int i = 0; i < n; ++i) t[i] = i / fs;
    if (n > 1) {
      Warn(&report, rows[0].frame,
           "times do not increase; taking " + Num(fs, 3) + " rows per second");
    }
  } else if (fs <= 0) {
    std::vector<double> dts;
    for (int i = 1; i < n; ++i) dts.push_back(t[i] - t[i - 1]);
    if (dts.empty()) {
      fs = options.fallback_fps;
    } else {
      std::nth_element(dts.begin(), dts.begin() + dts.size() / 2, dts.end());
      fs = 1.0 / dts[dts.size() / 2];
    }
  }
  report.sample_rate_hz = fs;
  if (cutoff_hz > 0 && !(cutoff_hz < 0.5 * fs)) {
    return Status::Error("planner.cutoff_hz", "cutoff " + Num(cutoff_hz) +
                                                  " Hz must be below half the frame rate (" +
                                                  Num(fs, 3) + " fps)");
  }

  // 1. Unwrap from the first measured posture and flag impossible jumps.
  std::vector<double> upper(n, kNaN), bend(n, kNaN), yaw(n, kNaN);
  std::vector<char> good(n, 0), flagged(n, 0);
  int prev = -1;
  double ref_t = 0;
  for (int i = 0; i < n; ++i) {
    const AngleRow& r = rows[i];
    if (!r.ok()) continue;
    double u = marker ? 0.0 : r.upper_deg;
    double b = r.bend_deg;
    if (!std::isfinite(u) || !std::isfinite(b)) continue;
    const double y = std::isfinite(r.turn_yaw_deg()) ? r.turn_yaw_deg() : kNaN;
    if (prev >= 0) {
      u -= 360.0 * std::round((u - upper[prev]) / 360.0);
      b -= 360.0 * std::round((b - bend[prev]) / 360.0);
      // Time spent in flagged frames earns no allowance: a flip that persists stays flagged
      // (and refuses the plan once longer than the max gap) instead of being accepted later.
      const double allowed = options.max_jump_deg_s * (t[i] - ref_t);
      double jump = std::max(std::abs(u - upper[prev]), std::abs(b - bend[prev]));
      std::string what = std::abs(u - upper[prev]) >= std::abs(b - bend[prev]) ? "upper" : "bend";
      if (!std::isnan(y) && !std::isnan(yaw[prev]) && std::abs(y - yaw[prev]) > jump) {
        jump = std::abs(y - yaw[prev]);
        what = "yaw";
      }
      if (jump > allowed) {
        ref_t += t[i] - t[i - 1];
        flagged[i] = 1;
        ++report.flagged_jumps;
        Warn(&report, r.frame,
             what + " changes " + Num(jump, 1) + " deg in " + Num(t[i] - ref_t, 3) +
                 " s: impossible for an arm; frame treated as lost");
        continue;
      }
    }
    upper[i] = u;
    bend[i] = b;
    yaw[i] = y;
    good[i] = 1;
    prev = i;
    ref_t = t[i];
  }
  int first = -1, last = -1;
  for (int i = 0; i < n; ++i) {
    if (good[i]) {
      if (first < 0) first = i;
      last = i;
    }
  }
  if (first < 0) return Status::Error("no measured frames: every row is lost");
  // Flagged frames after the last good one are a gap too (a persistent flip must not vanish).
  int end = last;
  for (int i = last + 1; i < n; ++i) {
    if (flagged[i]) end = i;
  }

  // 2. Gaps.
  std::vector<std::string> long_gaps;
  for (int i = first; i <= end;) {
    if (good[i]) {
      ++i;
      continue;
    }
    int j = i;
    while (j <= end && !good[j]) ++j;  // rows [i, j) missing
    const double gap_s = t[j - 1] - t[i] + 1.0 / fs;
    bool has_flag = false;
    for (int k = i; k < j; ++k) has_flag = has_flag || flagged[k];
    const std::string range = "frames " + std::to_string(rows[i].frame) + "-" +
                              std::to_string(rows[j - 1].frame) + " (" + Num(gap_s, 3) + " s" +
                              (has_flag ? ", impossible jump" : "") + ")";
    // Still images are separate poses, not samples of one motion: an unreadable view holds the
    // last readable pose however long the made-up time between views.
    if ((gap_s > options.max_gap_s + 1e-9 && !still_images) || j > last) {
      long_gaps.push_back(range);
    } else {
      const int a = i - 1, b = j;  // good neighbours
      const bool interpolate = options.gap == GapMode::kInterpolate && !still_images;
      for (int k = i; k < j; ++k) {
        const double w = interpolate ? (t[k] - t[a]) / (t[b] - t[a]) : 0.0;
        upper[k] = upper[a] + w * (upper[b] - upper[a]);
        bend[k] = bend[a] + w * (bend[b] - bend[a]);
        yaw[k] =
            (std::isnan(yaw[a]) || std::isnan(yaw[b])) ? yaw[a] : yaw[a] + w * (yaw[b] - yaw[a]);
        ++report.filled_rows;
      }
      Warn(&report, rows[i].frame, std::string(interpolate ? "interpolated " : "held ") + range);
    }
    i = j;
  }
  if (!long_gaps.empty()) {
    return Status::Error(std::to_string(long_gaps.size()) + " gap" +
                         (long_gaps.size() > 1 ? "s" : "") + " longer than the " +
                         Num(options.max_gap_s, 3) + " s allowed: " + ListItems(long_gaps) +
                         " (raise the max gap or re-analyse those frames)");
  }
  report.used_rows = last - first + 1;
  report.source_duration_s = t[last] - t[first];

  // 3. Map (yaw held while NaN; before the first yaw, the first one; none at all: 0).
  double held_yaw = kNaN;
  for (int i = first; i <= last && std::isnan(held_yaw); ++i) held_yaw = yaw[i];
  if (std::isnan(held_yaw)) held_yaw = 0;
  const int m = last - first + 1;
  std::vector<std::vector<double>> series(kJoints, std::vector<double>(m));
  for (int i = first; i <= last; ++i) {
    if (!std::isnan(yaw[i])) held_yaw = yaw[i];
    const JointArray q = mapping.Map(upper[i], bend[i], held_yaw);
    for (int j = 0; j < kJoints; ++j) series[j][i - first] = q[j];
  }

  // 4. Zero-phase low-pass.
  if (cutoff_hz > 0) {
    for (int j = 0; j < 3; ++j) series[j] = ZeroPhaseLowPass(series[j], fs, cutoff_hz);
  }

  // 5. Limits.
  std::vector<std::string> violations[kJoints];
  std::vector<JointArray> joints(m);
  std::vector<double> times(m);
  for (int i = 0; i < m; ++i) {
    bool clamped = false;
    times[i] = t[first + i] - t[first];
    for (int j = 0; j < kJoints; ++j) {
      double v = series[j][i];
      if (v < options.limits.min_deg[j] || v > options.limits.max_deg[j]) {
        if (options.clamp) {
          v = std::clamp(v, options.limits.min_deg[j], options.limits.max_deg[j]);
          clamped = true;
        } else {
          violations[j].push_back(std::to_string(rows[first + i].frame) + " (" + Num(v) + ")");
        }
      }
      joints[i][j] = v;
    }
    if (clamped) {
      ++report.clamped_rows;
      if (report.clamped_rows <= kListed) {
        Warn(&report, rows[first + i].frame, "clamped to the joint limits");
      }
    }
  }
  std::string refusal;
  for (int j = 0; j < kJoints; ++j) {
    if (violations[j].empty()) continue;
    if (!refusal.empty()) refusal += "; ";
    refusal += DescribeLimit(options.limits, j) + " exceeded in " +
               std::to_string(violations[j].size()) + " frame" +
               (violations[j].size() > 1 ? "s" : "") + ": " + ListItems(violations[j]);
  }
  if (!refusal.empty()) {
    return Status::Error("targets outside the joint limits: " + refusal +
                         " (clamp them, or change the mapping or the limits)");
  }

  // 6. Keyframes, 7. speed.
  Trajectory traj;
  for (int idx : SelectKeyframes(times, joints, options)) {
    Keyframe kf;
    kf.time_s = times[idx];
    kf.joint_deg = joints[idx];
    kf.frame = rows[first + idx].frame;
    traj.keyframes.push_back(kf);
  }
  s = EnforceSpeedLimits(&traj, options.limits, options.speed, &report.stretch_s,
                         &report.stretched_steps);
  if (!s.ok()) return s;
  for (int j = 0; j < kJoints; ++j) {
    report.min_deg[j] = INFINITY;
    report.max_deg[j] = -INFINITY;
    for (const Keyframe& kf : traj.keyframes) {
      report.min_deg[j] = std::min(report.min_deg[j], kf.joint_deg[j]);
      report.max_deg[j] = std::max(report.max_deg[j], kf.joint_deg[j]);
    }
  }
  *out = std::move(traj);
  if (report_out) *report_out = std::move(report);
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
  };
}

}  // namespace armmimic::robot
