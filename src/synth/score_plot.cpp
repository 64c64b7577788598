// Error-vs-frame plot (thesis Fig. 5-10) drawn with OpenCV.
// Length: PlotScore draws one figure whose axes, curves and legend share its scales.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "armmimic/synth/score.h"

namespace armmimic::synth {
namespace {

double NiceStep(double range, int target_ticks) {
  const double raw = range / std::max(1, target_ticks);
  const double mag = std::pow(10.0, std::floor(std::log10(std::max(raw, 1e-9))));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (raw <= m * mag) return m * mag;
  }
  return 10 * mag;
}

std::string Label(double v) {
  char buf[32];
  if (std::fabs(v - std::round(v)) < 1e-9)
    std::snprintf(buf, sizeof(buf), "%.0f", v);
  else
    std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

void Text(cv::Mat& img, const std::string& s, cv::Point at, double scale, const cv::Scalar& c,
          bool center = false, bool right = false) {
  int base = 0;
  const cv::Size ts = cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &base);
  if (center) at.x -= ts.width / 2;
  if (right) at.x -= ts.width;
  cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, c, 1, cv::LINE_AA);
}

struct Series {
  const char* name;
  cv::Scalar color;
  double ScoreRow::*field;
};

}  // namespace

cv::Mat PlotScore(const ScoreReport& report, cv::Size size) {
  size.width = std::max(size.width, 300);
  size.height = std::max(size.height, 200);
  cv::Mat img(size, CV_8UC3, cv::Scalar(255, 255, 255));
  const ScoreSummary& s = report.summary;
  std::vector<Series> series;
  if (s.has_directions) {
    series.push_back({"upper arm", {200, 90, 20}, &ScoreRow::err_upper});
    series.push_back({"forearm", {30, 40, 210}, &ScoreRow::err_fore});
  } else {
    series.push_back({"yaw", {40, 150, 40}, &ScoreRow::err_yaw});
    series.push_back({"bend", {170, 40, 170}, &ScoreRow::err_bend});
  }
  // Frame range: the frames the angle file covers, or every truth frame when it covers none.
  int f0 = 0, f1 = 1;
  bool any = false;
  for (const ScoreRow& r : report.rows) {
    if (!r.has_row && s.matched_frames > 0) continue;
    f0 = any ? std::min(f0, r.frame) : r.frame;
    f1 = any ? std::max(f1, r.frame) : r.frame;
    any = true;
  }
  if (f1 <= f0) f1 = f0 + 1;
  double emax = 0;
  for (const ScoreRow& r : report.rows) {
    for (const Series& se : series) {
      const double e = r.*(se.field);
      if (std::isfinite(e)) emax = std::max(emax, e);
    }
  }
  const double ystep = NiceStep(std::max(emax, 5.0), 5);
  const double ymax = std::max(ystep, std::ceil(std::max(emax, 5.0) / ystep) * ystep);
  const int left = 60, right = 20, top = 40, bottom = 55;
  const cv::Rect area(left, top, size.width - left - right, size.height - top - bottom);
  auto X = [&](double f) { return area.x + (f - f0) / (f1 - f0) * area.width; };
  auto Y = [&](double e) { return area.y + area.height - e / ymax * area.height; };
  const cv::Scalar grid(225, 225, 225), ink(40, 40, 40);
  // Grid, ticks and labels.
  for (double v = 0; v <= ymax + 1e-9; v += ystep) {
    const int y = cvRound(Y(v));
    cv::line(img, {area.x, y}, {area.x + area.width, y}, grid, 1);
    cv::line(img, {area.x - 4, y}, {area.x, y}, ink, 1);
    Text(img, Label(v), {area.x - 7, y + 4}, 0.4, ink, false, true);
  }
  const double xstep = NiceStep(f1 - f0, 8);
  for (double f = std::ceil(f0 / xstep) * xstep; f <= f1 + 1e-9; f += xstep) {
    const int x = cvRound(X(f));
    cv::line(img, {x, area.y}, {x, area.y + area.height}, grid, 1);
    cv::line(img, {x, area.y + area.height}, {x, area.y + area.height + 4}, ink, 1);
    Text(img, Label(f), {x, area.y + area.height + 17}, 0.4, ink, true);
  }
  cv::rectangle(img, area, ink, 1);
  Text(img, "frame", {area.x + area.width / 2, size.height - 10}, 0.45, ink, true);
  // Vertical axis label, drawn horizontally above the axis.
  Text(img, "error (deg)", {8, top - 12}, 0.45, ink);
  Text(img, "Angle error per frame", {area.x + area.width / 2, 20}, 0.55, ink, true);
  // Lost frames (row with status lost) and frames without a row, marked under the axis.
  int lost = 0, missing = 0;
  for (const ScoreRow& r : report.rows) {
    if (r.frame < f0 || r.frame > f1) continue;
    const int x = cvRound(X(r.frame));
    const int yb = area.y + area.height;
    if (r.has_row && !r.ok) {
      cv::line(img, {x, yb - 8}, {x, yb - 1}, {0, 0, 220}, 1);
      ++lost;
    } else if (!r.has_row) {
      cv::line(img, {x, yb - 4}, {x, yb - 1}, {160, 160, 160}, 1);
      ++missing;
    }
  }
  // One polyline per series, broken where a frame has no value.
  for (const Series& se : series) {
    std::vector<cv::Point> run;
    auto flush = [&]() {
      if (run.size() == 1) cv::circle(img, run[0], 1, se.color, -1, cv::LINE_AA);
      if (run.size() > 1) cv::polylines(img, run, false, se.color, 1, cv::LINE_AA);
      run.clear();
    };
    for (const ScoreRow& r : report.rows) {
      const double e = r.*(se.field);
      if (!std::isfinite(e) || r.frame < f0 || r.frame > f1) {
        flush();
        continue;
      }
      run.emplace_back(cvRound(X(r.frame)), cvRound(Y(e)));
    }
    flush();
  }
  // Legend.
  int lx = area.x + area.width - 150, ly = area.y + 14;
  for (const Series& se : series) {
    cv::line(img, {lx, ly - 4}, {lx + 20, ly - 4}, se.color, 2, cv::LINE_AA);
    Text(img, se.name, {lx + 26, ly}, 0.4, ink);
    ly += 16;
  }
  if (lost > 0) {
    cv::line(img, {lx + 10, ly - 9}, {lx + 10, ly}, {0, 0, 220}, 1);
    Text(img, "lost (" + std::to_string(lost) + ")", {lx + 26, ly}, 0.4, ink);
    ly += 16;
  }
  if (missing > 0) {
    cv::line(img, {lx + 10, ly - 5}, {lx + 10, ly}, {160, 160, 160}, 1);
    Text(img, "no row (" + std::to_string(missing) + ")", {lx + 26, ly}, 0.4, ink);
  }
  return img;
}

}  // namespace armmimic::synth
