// PlanTrajectory: an angle file to joint keyframes, in the steps docs/robot.md lists. The rows'
// times and rate, 1. unwrapping and impossible jumps, 2. gaps, 3. mapping, 4. the zero-phase
// low-pass, 5. the joint limits, 6. keyframes and 7. the speed limits (the last two, and the
// options' check, in planner.cpp).
// Length: one file for the steps in order, each its own function over the shared series; the
// 3-D sources' checks sit with the mapping step that reads them.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "armmimic/core/angles.h"
#include "armmimic/core/text.h"
#include "armmimic/robot/filter.h"
#include "armmimic/robot/planner.h"

namespace armmimic::robot {
namespace {

constexpr int kListed = 5;  // offending frames listed in a message before "... and N more"

std::string Num(double v, int decimals = 2) { return FormatNumber(v, decimals); }

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

// The rows' times and the rate they are sampled at.
struct Timing {
  std::vector<double> t;      // per row, increasing
  double fs = 0;              // rows per second
  bool still_images = false;  // no frame rate: separate poses, not one motion
  double cutoff_hz = 0;       // the low-pass filter's cutoff, 0: none
};

// The measured series, unwrapped, over the rows [first, last] (end: the last row of a trailing
// gap of flagged frames).
struct Series {
  std::vector<double> upper, bend, yaw;
  std::vector<char> good, flagged;
  int first = -1, last = -1, end = -1;
};

// Times: the file's, or frame counts at fallback_fps when they do not increase.
Status SampleTimes(const AngleFile& angles, const PlannerOptions& options, PlanReport* report,
                   Timing* out) {
  const auto& rows = angles.rows;
  const int n = static_cast<int>(rows.size());
  std::vector<double>& t = out->t;
  t.assign(n, 0.0);
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
    Warn(report, rows[0].frame,
         "no frame rate (still images): planned without the low-pass filter");
  }
  report->filter_cutoff_hz = cutoff_hz;
  if (!increasing) {
    fs = options.fallback_fps;
    for (int i = 0; i < n; ++i) t[i] = i / fs;
    if (n > 1) {
      Warn(report, rows[0].frame,
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
  report->sample_rate_hz = fs;
  out->fs = fs;
  out->still_images = still_images;
  out->cutoff_hz = cutoff_hz;
  if (cutoff_hz > 0 && !(cutoff_hz < 0.5 * fs)) {
    return Status::Error("planner.cutoff_hz", "cutoff " + Num(cutoff_hz) +
                                                  " Hz must be below half the frame rate (" +
                                                  Num(fs, 3) + " fps)");
  }
  return Status::Ok();
}

// 1. Unwrap from the first measured posture and flag impossible jumps. side_3d: the arm's image
// side when the rows' 3-D columns are the sources (SourcesFrom3d), 0 for the 2-D columns.
Status Unwrap(const std::vector<AngleRow>& rows, const std::vector<double>& t, bool marker,
              bool signed_column, int side_3d, const PlannerOptions& options, PlanReport* report,
              Series* out) {
  const int n = static_cast<int>(rows.size());
  std::vector<double>&upper = out->upper, &bend = out->bend, &yaw = out->yaw;
  std::vector<char>&good = out->good, &flagged = out->flagged;
  upper.assign(n, kNaN);
  bend.assign(n, kNaN);
  yaw.assign(n, kNaN);
  good.assign(n, 0);
  flagged.assign(n, 0);
  int prev = -1, unsigned_rows = 0, first_unsigned = 0;
  double ref_t = 0;
  for (int i = 0; i < n; ++i) {
    const AngleRow& r = rows[i];
    if (!r.ok()) continue;
    double u = marker ? 0.0 : r.upper_deg;
    double b = r.bend_deg;
    // A marker row whose yaw sign is unknown holds J1 (never turned by the unsigned yaw).
    double y = std::isfinite(r.turn_yaw_deg(signed_column)) ? r.turn_yaw_deg(signed_column) : kNaN;
    // From the 3-D columns, a row without them is not measured (J1 held while the azimuth is
    // blind).
    if (side_3d != 0 && !SourcesFrom3d(r, side_3d, &u, &b, &y)) continue;
    if (!std::isfinite(u) || !std::isfinite(b)) continue;
    if (signed_column && std::isnan(y) && std::isfinite(r.yaw_deg) && unsigned_rows++ == 0) {
      first_unsigned = r.frame;
    }
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
        ++report->flagged_jumps;
        Warn(report, r.frame,
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
  if (unsigned_rows > 0) {
    Warn(report, first_unsigned,
         std::to_string(unsigned_rows) + " row" + (unsigned_rows > 1 ? "s" : "") +
             " with a yaw whose sign could not be told (yaw_signed_deg nan): J1 held there");
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
  out->first = first;
  out->last = last;
  out->end = end;
  return Status::Ok();
}

// 2. Gaps: held or interpolated when short, refused when long.
Status FillGaps(const std::vector<AngleRow>& rows, const Timing& timing,
                const PlannerOptions& options, PlanReport* report, Series* s) {
  const std::vector<double>& t = timing.t;
  const double fs = timing.fs;
  const bool still_images = timing.still_images;
  std::vector<double>&upper = s->upper, &bend = s->bend, &yaw = s->yaw;
  const std::vector<char>&good = s->good, &flagged = s->flagged;
  const int first = s->first, last = s->last, end = s->end;
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
        ++report->filled_rows;
      }
      Warn(report, rows[i].frame, std::string(interpolate ? "interpolated " : "held ") + range);
    }
    i = j;
  }
  if (!long_gaps.empty()) {
    return Status::Error(std::to_string(long_gaps.size()) + " gap" +
                         (long_gaps.size() > 1 ? "s" : "") + " longer than the " +
                         Num(options.max_gap_s, 3) + " s allowed: " + ListItems(long_gaps) +
                         " (raise the max gap or re-analyse those frames)");
  }
  return Status::Ok();
}

// 3. Map (yaw held while NaN; before the first yaw, the first one; none at all: 0), and 4. the
// zero-phase low-pass. One series per joint over the rows [first, last].
std::vector<std::vector<double>> MapAndFilter(const Series& s, const MappingOptions& mapping,
                                              const Timing& timing) {
  const int first = s.first, last = s.last;
  double held_yaw = kNaN;
  for (int i = first; i <= last && std::isnan(held_yaw); ++i) held_yaw = s.yaw[i];
  if (std::isnan(held_yaw)) held_yaw = 0;
  const int m = last - first + 1;
  std::vector<std::vector<double>> series(kJoints, std::vector<double>(m));
  for (int i = first; i <= last; ++i) {
    if (!std::isnan(s.yaw[i])) held_yaw = s.yaw[i];
    const JointArray q = mapping.Map(s.upper[i], s.bend[i], held_yaw);
    for (int j = 0; j < kJoints; ++j) series[j][i - first] = q[j];
  }
  if (timing.cutoff_hz > 0) {
    for (int j = 0; j < 3; ++j)
      series[j] = ZeroPhaseLowPass(series[j], timing.fs, timing.cutoff_hz);
  }
  return series;
}

// 5. Limits: targets outside them are refused, listing the frames, or clamped. Fills the joints
// and their times (from the first used row).
Status ApplyLimits(const std::vector<AngleRow>& rows, const std::vector<double>& t, int first,
                   const std::vector<std::vector<double>>& series, const PlannerOptions& options,
                   PlanReport* report, std::vector<JointArray>* joints_out,
                   std::vector<double>* times_out) {
  const int m = static_cast<int>(series[0].size());
  std::vector<std::string> violations[kJoints];
  std::vector<JointArray>& joints = *joints_out;
  std::vector<double>& times = *times_out;
  joints.assign(m, JointArray{});
  times.assign(m, 0.0);
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
      ++report->clamped_rows;
      if (report->clamped_rows <= kListed) {
        Warn(report, rows[first + i].frame, "clamped to the joint limits");
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
  return Status::Ok();
}

// The range each joint uses over the keyframes.
void RecordRanges(const Trajectory& traj, PlanReport* report) {
  for (int j = 0; j < kJoints; ++j) {
    report->min_deg[j] = INFINITY;
    report->max_deg[j] = -INFINITY;
    for (const Keyframe& kf : traj.keyframes) {
      report->min_deg[j] = std::min(report->min_deg[j], kf.joint_deg[j]);
      report->max_deg[j] = std::max(report->max_deg[j], kf.joint_deg[j]);
    }
  }
}

}  // namespace

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
  int side_3d = 0;
  if (!marker && mapping.arm_3d && angles.has_3d_columns) {
    side_3d = ImageSideOf(angles);
    if (side_3d == 0) {
      return Status::Error("mapping.arm_3d",
                           "the angle file's 3-D columns need the arm's side (pose.side in its "
                           "header) to turn J1 from the azimuth; plan it from the 2-D columns "
                           "instead");
    }
    if (!mapping.j2_elevation || !mapping.j3_flexion) {
      return Status::Error("mapping.arm_3d",
                           "the 3-D columns turn J2 by the elevation and J3 by the flexion; the "
                           "signed sources (upper, bend) need the 2-D columns");
    }
    report.mapping +=
        " from the 3-D columns (J1 the upper arm's azimuth, J2 its elevation, J3 "
        "180 - elbow_deg)";
  }

  Timing timing;
  s = SampleTimes(angles, options, &report, &timing);
  if (!s.ok()) return s;
  Series series;
  s = Unwrap(rows, timing.t, marker, angles.has_signed_yaw_column, side_3d, options, &report,
             &series);
  if (!s.ok()) return s;
  s = FillGaps(rows, timing, options, &report, &series);
  if (!s.ok()) return s;
  report.used_rows = series.last - series.first + 1;
  report.source_duration_s = timing.t[series.last] - timing.t[series.first];
  std::vector<JointArray> joints;
  std::vector<double> times;
  s = ApplyLimits(rows, timing.t, series.first, MapAndFilter(series, mapping, timing), options,
                  &report, &joints, &times);
  if (!s.ok()) return s;

  // 6. Keyframes, 7. speed.
  Trajectory traj;
  for (int idx : SelectKeyframes(times, joints, options)) {
    Keyframe kf;
    kf.time_s = times[idx];
    kf.joint_deg = joints[idx];
    kf.frame = rows[series.first + idx].frame;
    traj.keyframes.push_back(kf);
  }
  s = EnforceSpeedLimits(&traj, options.limits, options.speed, &report.stretch_s,
                         &report.stretched_steps);
  if (!s.ok()) return s;
  RecordRanges(traj, &report);
  *out = std::move(traj);
  if (report_out) *report_out = std::move(report);
  return Status::Ok();
}

}  // namespace armmimic::robot
