// Scoring an angle file against the truth: per-frame errors, their statistics and the tables.
// Length: ScoreAngles is one pass over the truth rows, filling every accumulator from the same row.
#include "armmimic/synth/score.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace armmimic::synth {
namespace {

class Accumulator {
 public:
  void Add(double err, int frame) {
    if (!std::isfinite(err)) return;
    ++n_;
    sum_ += err;
    sum2_ += err * err;
    if (err > max_) {
      max_ = err;
      max_frame_ = frame;
    }
  }
  ErrorStats Stats() const {
    ErrorStats s;
    s.count = n_;
    if (n_ == 0) return s;
    s.mae = sum_ / n_;
    s.rmse = std::sqrt(sum2_ / n_);
    s.max = max_;
    s.max_frame = max_frame_;
    return s;
  }

 private:
  int n_ = 0;
  double sum_ = 0, sum2_ = 0, max_ = -1;
  int max_frame_ = -1;
};

bool Both(double a, double b) { return std::isfinite(a) && std::isfinite(b); }

// An error that was not measured counts as none.
double Finite(double err) { return std::isfinite(err) ? err : 0.0; }

std::string Fmt(double v, int decimals = 2) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

std::string Pad(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

std::string StatsLine(const char* name, const ErrorStats& s) {
  if (s.count == 0) return std::string("  ") + name + ": no values\n";
  return std::string("  ") + name + ": MAE " + Fmt(s.mae) + "  RMSE " + Fmt(s.rmse) + "  max " +
         Fmt(s.max) + " (frame " + std::to_string(s.max_frame) + ")  n=" + std::to_string(s.count) +
         "\n";
}

}  // namespace

ScoreReport ScoreAngles(const TruthFile& truth, const AngleFile& angles) {
  ScoreReport report;
  ScoreSummary& sum = report.summary;
  std::unordered_map<int, const AngleRow*> by_frame;
  for (const AngleRow& r : angles.rows) by_frame.emplace(r.frame, &r);  // first row wins
  Accumulator upper, fore, overall, upper_axis, fore_axis, overall_axis, yaw, bend;
  std::unordered_map<int, bool> truth_frames;
  for (const TruthRow& t : truth.rows) {
    if (!t.HasAngles()) continue;
    truth_frames[t.frame] = true;
    if (std::isfinite(t.upper_deg) || std::isfinite(t.fore_deg)) sum.has_directions = true;
    if (std::isfinite(t.yaw_deg) || std::isfinite(t.bend_deg)) sum.has_yaw_bend = true;
    ScoreRow row;
    row.frame = t.frame;
    row.truth_upper = t.upper_deg;
    row.truth_fore = t.fore_deg;
    row.truth_yaw = t.yaw_deg;
    row.truth_bend = t.bend_deg;
    ++sum.truth_frames;
    const auto it = by_frame.find(t.frame);
    if (it == by_frame.end()) {
      ++sum.missing_frames;
      report.rows.push_back(row);
      continue;
    }
    row.has_row = true;
    ++sum.matched_frames;
    const AngleRow& a = *it->second;
    row.ok = a.ok();
    if (!row.ok) {
      ++sum.lost_frames;
      report.rows.push_back(row);
      continue;
    }
    ++sum.ok_frames;
    row.calc_upper = a.upper_deg;
    row.calc_fore = a.fore_deg;
    row.calc_yaw = a.yaw_deg;
    row.calc_bend = a.bend_deg;
    if (Both(row.truth_upper, row.calc_upper)) {
      row.err_upper = std::fabs(AngleDiff(row.calc_upper, row.truth_upper));
      row.axis_err_upper = AxisDiff(row.calc_upper, row.truth_upper);
    }
    if (Both(row.truth_fore, row.calc_fore)) {
      row.err_fore = std::fabs(AngleDiff(row.calc_fore, row.truth_fore));
      row.axis_err_fore = AxisDiff(row.calc_fore, row.truth_fore);
    }
    if (Both(row.truth_yaw, row.calc_yaw)) row.err_yaw = std::fabs(row.calc_yaw - row.truth_yaw);
    if (Both(row.truth_bend, row.calc_bend)) {
      row.err_bend = std::fabs(AngleDiff(row.calc_bend, row.truth_bend));
    }
    upper.Add(row.err_upper, row.frame);
    fore.Add(row.err_fore, row.frame);
    overall.Add(row.err_upper, row.frame);
    overall.Add(row.err_fore, row.frame);
    upper_axis.Add(row.axis_err_upper, row.frame);
    fore_axis.Add(row.axis_err_fore, row.frame);
    overall_axis.Add(row.axis_err_upper, row.frame);
    overall_axis.Add(row.axis_err_fore, row.frame);
    yaw.Add(row.err_yaw, row.frame);
    bend.Add(row.err_bend, row.frame);
    report.rows.push_back(row);
  }
  for (const AngleRow& r : angles.rows) {
    if (!truth_frames.count(r.frame)) ++sum.unmatched_rows;
  }
  for (const ScoreRow& r : report.rows) {
    if (!r.ok) continue;
    const double worst = sum.has_directions ? std::max(Finite(r.err_upper), Finite(r.err_fore))
                                            : std::max(Finite(r.err_yaw), Finite(r.err_bend));
    if (worst > kConfidentlyWrongDeg) ++sum.confidently_wrong_frames;
  }
  sum.coverage =
      sum.matched_frames > 0 ? static_cast<double>(sum.ok_frames) / sum.matched_frames : kNaN;
  sum.confidently_wrong_rate =
      sum.matched_frames > 0
          ? static_cast<double>(sum.confidently_wrong_frames) / sum.matched_frames
          : kNaN;
  sum.upper = upper.Stats();
  sum.fore = fore.Stats();
  sum.overall = overall.Stats();
  sum.upper_axis = upper_axis.Stats();
  sum.fore_axis = fore_axis.Stats();
  sum.overall_axis = overall_axis.Stats();
  sum.yaw = yaw.Stats();
  sum.bend = bend.Stats();
  return report;
}

std::string FormatScoreTable(const ScoreReport& report) {
  const ScoreSummary& s = report.summary;
  std::string out;
  const std::size_t w = 9;
  std::vector<std::string> head{"frame", "status"};
  if (s.has_directions) {
    for (const char* h : {"t_upper", "t_fore", "c_upper", "c_fore", "e_upper", "e_fore"}) {
      head.push_back(h);
    }
  }
  if (s.has_yaw_bend) {
    for (const char* h : {"t_yaw", "t_bend", "c_yaw", "c_bend", "e_yaw", "e_bend"}) {
      head.push_back(h);
    }
  }
  for (const auto& h : head) out += Pad(h, w);
  out += "\n";
  for (const ScoreRow& r : report.rows) {
    if (!r.has_row) continue;  // frames without a row are counted in the summary
    out += Pad(std::to_string(r.frame), w) + Pad(r.ok ? "ok" : "lost", w);
    if (s.has_directions) {
      for (double v :
           {r.truth_upper, r.truth_fore, r.calc_upper, r.calc_fore, r.err_upper, r.err_fore}) {
        out += Pad(Fmt(v), w);
      }
    }
    if (s.has_yaw_bend) {
      for (double v : {r.truth_yaw, r.truth_bend, r.calc_yaw, r.calc_bend, r.err_yaw, r.err_bend}) {
        out += Pad(Fmt(v), w);
      }
    }
    out += "\n";
  }
  return out;
}

std::string FormatScoreSummary(const ScoreReport& report) {
  const ScoreSummary& s = report.summary;
  std::string out = "summary (degrees)\n";
  out += "  truth frames with angles: " + std::to_string(s.truth_frames) +
         "; with a row: " + std::to_string(s.matched_frames) + " (ok " +
         std::to_string(s.ok_frames) + ", lost " + std::to_string(s.lost_frames) +
         "); without a row: " + std::to_string(s.missing_frames) +
         "; rows matching no truth frame: " + std::to_string(s.unmatched_rows) + "\n";
  out += "  coverage: " +
         (std::isfinite(s.coverage)
              ? Fmt(100.0 * s.coverage, 1) + "% (" + std::to_string(s.ok_frames) + "/" +
                    std::to_string(s.matched_frames) +
                    " rows ok); confidently wrong: " + Fmt(100.0 * s.confidently_wrong_rate, 1) +
                    "% (" + std::to_string(s.confidently_wrong_frames) + "/" +
                    std::to_string(s.matched_frames) + " rows ok with an error over " +
                    Fmt(kConfidentlyWrongDeg, 0) + " degrees)"
              : std::string("- (no truth frame has a row)")) +
         "\n";
  if (s.has_directions) {
    out += "direction error (wrapped difference)\n";
    out += StatsLine("upper  ", s.upper);
    out += StatsLine("fore   ", s.fore);
    out += StatsLine("overall", s.overall);
    out += "axis error (difference mod 180, as the thesis' orientation)\n";
    out += StatsLine("upper  ", s.upper_axis);
    out += StatsLine("fore   ", s.fore_axis);
    out += StatsLine("overall", s.overall_axis);
  }
  if (s.has_yaw_bend) {
    out += "yaw and bend error (where both files have values)\n";
    out += StatsLine("yaw    ", s.yaw);
    out += StatsLine("bend   ", s.bend);
  }
  return out;
}

}  // namespace armmimic::synth
