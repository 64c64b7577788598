#include "common/straight_arm.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace armmimic {
namespace {

constexpr double kThickQuantile = 0.8;
constexpr double kFullShare = 0.75;
constexpr double kBandShare = 0.3;

double Quantile(std::vector<double> v, double q) {
  if (v.empty()) return kNaN;
  auto at = v.begin() + static_cast<std::ptrdiff_t>(std::lround(q * (v.size() - 1)));
  std::nth_element(v.begin(), at, v.end());
  return *at;
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
  out.thick_px = Quantile(heights, kThickQuantile);
  for (const Column& c : cols) {
    if (c.count >= kFullShare * out.thick_px) mids.push_back(0.5 * (c.top + c.bottom));
  }
  out.axis_y = Quantile(mids, 0.5);
  out.inner_x = cols.front().x;
  out.outer_x = cols.back().x;
  out.ok = true;
  return out;
}

}  // namespace armmimic
