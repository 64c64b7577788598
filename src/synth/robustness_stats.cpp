#include "armmimic/synth/robustness_stats.h"

#include <algorithm>
#include <cmath>

namespace armmimic::synth {

MotionScore ScoreMotion(const ScoreReport& report, int first_motion_frame) {
  MotionScore s;
  double sum = 0;
  for (const ScoreRow& r : report.rows) {
    if (r.frame < first_motion_frame) continue;
    ++s.motion_frames;
    if (!r.ok) continue;
    ++s.ok_frames;
    // A segment the engine left nan on an ok row counts as fully wrong.
    const double upper = std::isfinite(r.err_upper) ? r.err_upper : 180.0;
    const double fore = std::isfinite(r.err_fore) ? r.err_fore : 180.0;
    const double worst = std::max(upper, fore);
    sum += 0.5 * (upper + fore);
    if (worst > kConfidentlyWrongDeg) ++s.confidently_wrong_frames;
    s.worst_error_deg =
        std::isfinite(s.worst_error_deg) ? std::max(s.worst_error_deg, worst) : worst;
  }
  if (s.ok_frames > 0) s.mean_error_deg = sum / s.ok_frames;
  return s;
}

double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return kNaN;
  std::sort(values.begin(), values.end());
  const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const std::size_t i = static_cast<std::size_t>(std::floor(pos));
  if (i + 1 >= values.size()) return values.back();
  return values[i] + (pos - static_cast<double>(i)) * (values[i + 1] - values[i]);
}

RobustnessSummary SummariseRobustness(const std::vector<MotionScore>& scenes) {
  RobustnessSummary s;
  std::vector<double> errors;
  for (const MotionScore& m : scenes) {
    ++s.scenes;
    s.motion_frames += m.motion_frames;
    s.ok_frames += m.ok_frames;
    s.confidently_wrong_frames += m.confidently_wrong_frames;
    if (m.ok_frames == 0) ++s.zero_coverage_scenes;
    if (std::isfinite(m.mean_error_deg)) errors.push_back(m.mean_error_deg);
    s.worst_coverage =
        std::isfinite(s.worst_coverage) ? std::min(s.worst_coverage, m.coverage()) : m.coverage();
  }
  s.median_deg = Quantile(errors, 0.5);
  s.p90_deg = Quantile(errors, 0.9);
  s.max_deg = Quantile(errors, 1.0);
  if (s.motion_frames > 0) {
    s.coverage = static_cast<double>(s.ok_frames) / s.motion_frames;
    s.confidently_wrong_rate = static_cast<double>(s.confidently_wrong_frames) / s.motion_frames;
  }
  return s;
}

}  // namespace armmimic::synth
