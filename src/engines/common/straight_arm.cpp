#include "common/straight_arm.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "common/order_statistic.h"

namespace armmimic {
namespace {

constexpr double kThickQuantile = 0.8;
constexpr double kFullShare = 0.75;
constexpr double kBandShare = 0.3;
// ContinueStraightArm: the columns whose colour is the arm's, the columns not the arm's that end
// it, and the rows' distance above and below the axis (in thicknesses) where the light's change
// is measured.
constexpr int kColourColumns = 8;
constexpr int kEndColumns = 3;
constexpr double kLightRowsOff = 1.5;

// Each channel's median ratio of `a` over `b` over the pixels of `rows` (y values) in columns
// [x0, x1]: the light's change from `b` to `a` there (1 where too dark to tell).
std::array<double, 3> LightRatio(const cv::Mat& a, const cv::Mat& b, const std::vector<int>& rows,
                                 int x0, int x1) {
  std::array<std::vector<double>, 3> ratios;
  for (int y : rows) {
    if (y < 0 || y >= a.rows) continue;
    for (int x = std::max(0, x0); x <= std::min(a.cols - 1, x1); ++x) {
      const cv::Vec3b& pa = a.at<cv::Vec3b>(y, x);
      const cv::Vec3b& pb = b.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c) {
        if (pb[c] >= 16) ratios[static_cast<std::size_t>(c)].push_back(double(pa[c]) / pb[c]);
      }
    }
  }
  std::array<double, 3> gain{1, 1, 1};
  for (int c = 0; c < 3; ++c) {
    const double q = arm::NearestRankQuantile(ratios[static_cast<std::size_t>(c)], 0.5);
    if (std::isfinite(q)) gain[static_cast<std::size_t>(c)] = q;
  }
  return gain;
}

// The largest channel difference of two colours.
double MaxChannel(const cv::Vec3d& a, const cv::Vec3d& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace

bool InTheBodysColumns(const cv::Rect& torso, const cv::Rect& part) {
  return part.x < torso.x + torso.width && torso.x < part.x + part.width;
}

bool CentredHighEnoughForAShoulder(const cv::Rect& region, const cv::Rect& body_box) {
  return region.y + 0.5 * region.height <= body_box.y + 0.5 * body_box.height;
}

cv::Rect HorizontalBand(const cv::Mat& arm, const cv::Rect& box) {
  std::vector<int> counts(static_cast<std::size_t>(box.height));
  for (int y = 0; y < box.height; ++y) {
    counts[static_cast<std::size_t>(y)] =
        cv::countNonZero(arm(cv::Rect(box.x, box.y + y, box.width, 1)));
  }
  const auto full = std::max_element(counts.begin(), counts.end());
  const int floor = static_cast<int>(std::ceil(kBandShare * *full));
  int top = static_cast<int>(full - counts.begin()), bottom = top;
  while (top > 0 && counts[static_cast<std::size_t>(top - 1)] >= floor) --top;
  while (bottom + 1 < box.height && counts[static_cast<std::size_t>(bottom + 1)] >= floor) ++bottom;
  return cv::Rect(box.x, box.y + top, box.width, bottom - top + 1);
}

StraightArmColumns MeasureStraightArm(const cv::Mat& arm, const cv::Rect& band, int side) {
  struct Column {
    int x, count, top, bottom;
  };
  std::vector<Column> cols;
  for (int x = band.x; x < band.x + band.width; ++x) {
    Column c{x, 0, band.y + band.height, band.y - 1};
    for (int y = band.y; y < band.y + band.height; ++y) {
      if (!arm.at<uchar>(y, x)) continue;
      ++c.count;
      c.top = std::min(c.top, y);
      c.bottom = std::max(c.bottom, y);
    }
    if (c.count > 0) cols.push_back(c);
  }
  StraightArmColumns out;
  if (cols.size() < 4) return out;
  if (side < 0) std::reverse(cols.begin(), cols.end());
  std::vector<double> heights, mids;
  for (const Column& c : cols) heights.push_back(c.count);
  out.thick_px = arm::NearestRankQuantile(heights, kThickQuantile);
  for (const Column& c : cols) {
    if (c.count >= kFullShare * out.thick_px) mids.push_back(0.5 * (c.top + c.bottom));
  }
  out.axis_y = arm::NearestRankQuantile(mids, 0.5);
  out.inner_x = cols.front().x;
  out.outer_x = cols.back().x;
  out.ok = true;
  return out;
}

int ContinueStraightArm(const cv::Mat& arm_length, const cv::Mat& standstill,
                        const StraightArmColumns& cols, int side) {
  if (!cols.ok || arm_length.empty() || arm_length.size() != standstill.size() ||
      arm_length.type() != CV_8UC3 || standstill.type() != CV_8UC3) {
    return cols.outer_x;
  }
  const int half = std::max(1, static_cast<int>(std::floor(cols.thick_px / 4)));
  const int axis = static_cast<int>(std::lround(cols.axis_y));
  std::vector<int> rows;
  for (int y = axis - half; y <= axis + half; ++y) {
    if (y >= 0 && y < arm_length.rows) rows.push_back(y);
  }
  const int length = side * (cols.outer_x - cols.inner_x) + 1;
  const int k = std::min(kColourColumns, length / 4);
  if (rows.empty() || k < 2) return cols.outer_x;
  // The arm's colour in each middle row: its last k columns found.
  std::vector<cv::Vec3d> colour(rows.size(), cv::Vec3d(0, 0, 0));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (int j = 0; j < k; ++j) {
      const cv::Vec3b& p = arm_length.at<cv::Vec3b>(rows[i], cols.outer_x - side * j);
      colour[i] += cv::Vec3d(p[0], p[1], p[2]);
    }
    colour[i] /= k;
  }
  // The light's change from the standstill to the arm-length image, where both show the room:
  // rows a thickness and a half above and below the axis, beyond the arm's end.
  const int off = static_cast<int>(std::lround(kLightRowsOff * cols.thick_px));
  const int x_far = side > 0 ? arm_length.cols - 1 : 0;
  const int x0 = std::min(cols.outer_x + side, x_far), x1 = std::max(cols.outer_x + side, x_far);
  const std::array<double, 3> gain =
      LightRatio(arm_length, standstill, {axis - off, axis + off}, x0, x1);
  int outer = cols.outer_x, misses = 0;
  for (int x = cols.outer_x + side; x >= 0 && x < arm_length.cols; x += side) {
    double to_arm = 0, to_room = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const cv::Vec3b& a = arm_length.at<cv::Vec3b>(rows[i], x);
      const cv::Vec3b& s = standstill.at<cv::Vec3b>(rows[i], x);
      const cv::Vec3d pixel(a[0], a[1], a[2]);
      to_arm += MaxChannel(pixel, colour[i]);
      to_room += MaxChannel(pixel, cv::Vec3d(gain[0] * s[0], gain[1] * s[1], gain[2] * s[2]));
    }
    if (to_arm < to_room) {
      outer = x;
      misses = 0;
    } else if (++misses >= kEndColumns) {
      break;
    }
  }
  return outer;
}

}  // namespace armmimic
