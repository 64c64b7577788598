#include "bgsub/calib.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/geometry.h"
#include "bgsub/masks.h"
#include "common/order_statistic.h"
#include "common/straight_arm.h"

namespace armmimic::bgsub {
namespace {

// A region of the standstill's difference this many times smaller than the torso is a speck.
constexpr int kBodyPartShare = 25;

// The standing body: the largest region of the standstill's difference from the empty room.
void FindBody(const PixelModel& pixels, ArmCalibration* cal) {
  cv::Mat person, labels;
  pixels.StandstillPerson(&person);
  // Thin lines are no body: an edge of the room drawn a little differently (the floor's edge
  // under a drift of the light, a compression's ringing) would join the whole width of the room
  // to the person and move the body's centre.
  cv::morphologyEx(person, person, cv::MORPH_OPEN, cv::Mat::ones(3, 3, CV_8UC1));
  const std::vector<Component> parts = MaskComponents(person, &labels);
  const int largest = LargestComponent(parts);
  if (largest < 0) return;
  const Component& c = parts[static_cast<std::size_t>(largest)];
  ComponentMask(labels, c, &cal->body);
  // The head, and a hanging arm a gap of wall away from the torso, are the body too: every
  // sizeable region of the standstill's difference (not specks of noise) joins the mask.
  // The body's box also takes the parts above and below the largest one (InTheBodysColumns).
  cv::Mat one;
  cv::Rect box = c.box;
  for (const Component& part : parts) {
    if (part.label == c.label || part.area_px < std::max(16, c.area_px / kBodyPartShare)) continue;
    ComponentMask(labels, part, &one);
    cal->body |= one;
    if (InTheBodysColumns(c.box, part.box)) box |= part.box;
  }
  Close(&cal->body, cv::Rect(cv::Point(), cal->body.size()), 5);
  cal->body_box = box;
}

// The straight arm of the arm-length image: the largest region outside the standing body that
// differs from both the empty room and the standstill, with the regions lying in its band of rows
// (an arm broken where it crosses something of its own colour), centred high enough in the
// standing body's box for a shoulder (CentredHighEnoughForAShoulder).
bool FindStraightArm(const PixelModel& pixels, const cv::Mat& arm_length, const cv::Mat& body,
                     const std::optional<cv::Rect>& body_box, cv::Mat* arm, cv::Rect* band) {
  cv::Mat person, moved, both, labels;
  pixels.Differ(arm_length, pixels.background(), &person);
  pixels.Differ(arm_length, pixels.standstill(), &moved);
  cv::bitwise_and(person, moved, both);
  // Outside the standing body: where the hanging arm left the torso's side is not the arm.
  if (!body.empty()) both.setTo(0, body);
  // Thin lines (edges drawn a little differently) are no arm.
  cv::morphologyEx(both, both, cv::MORPH_OPEN, cv::Mat::ones(3, 3, CV_8UC1));
  const std::vector<Component> parts = MaskComponents(both, &labels);
  int largest = -1;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const cv::Rect& r = parts[i].box;
    if (body_box && !CentredHighEnoughForAShoulder(r, *body_box)) continue;
    if (largest < 0 || parts[i].area_px > parts[static_cast<std::size_t>(largest)].area_px) {
      largest = static_cast<int>(i);
    }
  }
  if (largest < 0) return false;
  const Component& main = parts[static_cast<std::size_t>(largest)];
  ComponentMask(labels, main, arm);
  const cv::Rect box = HorizontalBand(*arm, main.box);
  *band = box;
  // Pieces of the same arm: sizeable, no taller than it, centred in its rows and in line with it
  // (at most half its length away).
  cv::Mat one;
  for (const Component& c : parts) {
    const double cy = c.box.y + 0.5 * c.box.height;
    const int gap = std::max(c.box.x - (band->x + band->width), band->x - (c.box.x + c.box.width));
    if (c.label == main.label || c.area_px < std::max(8, main.area_px / 20) || cy < box.y ||
        cy > box.y + box.height || c.box.height > 1.5 * box.height + 2 || gap > band->width / 2) {
      continue;
    }
    ComponentMask(labels, c, &one);
    *arm |= one;
    *band |= cv::Rect(c.box.x, box.y, c.box.width, box.height);
  }
  return true;
}

// Where the hanging arm shows both its edges, its axis is read between them. Its outer edge alone
// tilts alike for an arm that leans out from the body and for one that tapers, and is read below
// the shoulder: under a lean it lies several pixels out there. A row shows both edges when the
// body, from its outer edge inwards, runs for one to three arm radii (an arm's width, not the
// torso's) and the room shows again before the body's centre (the arm hangs clear of the torso).
// Used when at least kBothEdgesShare of the rows with an edge, and kBothEdgesMinRows, do; the
// axis is then a line through the rows' middles (Theil-Sen over rows kLineMinRows apart, at most
// kMaxLean from straight down) read at the shoulder's row.
constexpr double kBothEdgesShare = 0.5;
constexpr std::size_t kBothEdgesMinRows = 5;
constexpr double kMinWidthRadii = 1, kMaxWidthRadii = 3;
constexpr double kLineMinRows = 4;
constexpr double kMaxLean = 0.7;  // dx/dy, about 35 degrees: as the standstill calibration

// The axis of the standstill's hanging arm, the shoulder's x, over the rows of the upper arm (from
// two radii below the shoulder to a quarter of the arm's length further): between its two edges
// where they show (above), or else the body's outer edge on the arm's side, one arm radius in.
// `inner_x` is the straight arm's inner end; the edge is looked for from three radii outside it
// inwards to the body's centre. NaN when too few rows have an edge.
double HangingArmAxis(const ArmCalibration& cal, int inner_x, double length) {
  if (cal.body.empty() || !cal.body_box) return kNaN;
  const double r = cal.half_width_px;
  const int centre = cal.body_box->x + cal.body_box->width / 2;
  const int outer = inner_x + cal.side * static_cast<int>(std::lround(3 * r + 2));
  const int y0 = static_cast<int>(std::lround(cal.shoulder_px.y + 2 * r));
  const int last = std::min(cal.body.rows - 1, y0 + static_cast<int>(std::max(4 * r, length / 4)));
  // On the arm's side of the body's centre only: a straight arm whose inner end lies past the
  // centre gives no edge (the walk must not run on past the centre).
  auto on_arm_side = [&](int x) { return cal.side * (x - centre) > 0; };
  std::vector<double> edges;
  std::vector<cv::Point2d> middles;
  for (int y = std::max(0, y0); y <= last; ++y) {
    const uchar* row = cal.body.ptr<uchar>(y);
    auto body = [&](int x) { return x >= 0 && x < cal.body.cols && row[x] != 0; };
    int x = std::clamp(outer, -1, cal.body.cols);
    while (on_arm_side(x) && !body(x)) x -= cal.side;
    if (!on_arm_side(x)) continue;
    const int edge = x;
    edges.push_back(edge);
    while (on_arm_side(x) && body(x)) x -= cal.side;
    const int width = cal.side * (edge - x);
    if (on_arm_side(x) && width >= kMinWidthRadii * r && width <= kMaxWidthRadii * r) {
      middles.emplace_back(0.5 * (edge + x + cal.side), y);
    }
  }
  if (edges.size() < 3) return kNaN;
  if (middles.size() >= kBothEdgesMinRows &&
      static_cast<double>(middles.size()) >= kBothEdgesShare * static_cast<double>(edges.size())) {
    double lean = arm::TheilSenSlope(middles, kLineMinRows);
    lean = std::isfinite(lean) ? std::clamp(lean, -kMaxLean, kMaxLean) : 0.0;
    return arm::MedianIntercept(middles, cal.shoulder_px.y, lean);
  }
  return arm::NearestRankQuantile(edges, 0.5) - cal.side * r;
}

}  // namespace

ArmCalibration Calibrate(const PixelModel& pixels, const cv::Mat& arm_length,
                         const std::optional<cv::Point2d>& fixed_shoulder) {
  ArmCalibration cal;
  FindBody(pixels, &cal);
  if (!cal.body_box && !fixed_shoulder) {
    cal.note = "no body in the standstill frames (check the background)";
    return cal;
  }
  cv::Mat arm;
  cv::Rect band;
  if (!FindStraightArm(pixels, arm_length, cal.body, cal.body_box, &arm, &band)) {
    cal.note = "arm-length image: no arm differs from the standstill";
    return cal;
  }
  const RegionMoments m = ComputeMoments(arm, band);
  const double centre_x =
      fixed_shoulder ? fixed_shoulder->x : cal.body_box->x + 0.5 * cal.body_box->width;
  cal.side = m.cx >= centre_x ? 1 : -1;
  const StraightArmColumns cols = MeasureStraightArm(arm, band, cal.side);
  if (!cols.ok) {
    cal.note = "arm-length image: the straight arm is too small";
    return cal;
  }
  const double length = std::abs(cols.outer_x - cols.inner_x) + 1;
  const double thick = cols.thick_px;
  cal.half_width_px = std::max(1.0, 0.5 * thick);
  cal.shoulder_px = cv::Point2d(cols.inner_x, cols.axis_y);
  if (fixed_shoulder) {
    cal.shoulder_px = *fixed_shoulder;
  } else if (const double axis = HangingArmAxis(cal, cols.inner_x, length); std::isfinite(axis)) {
    cal.shoulder_px.x = axis;
  } else {
    // Where the straight arm leaves the hanging one: one arm radius outside the shoulder.
    cal.shoulder_px.x -= cal.side * cal.half_width_px;
  }
  cal.reach_px = cal.side * (cols.outer_x - cal.shoulder_px.x) + 0.5;
  if (!(cal.reach_px > 4 * cal.half_width_px)) {
    cal.note = "arm-length image: the straight arm is shorter than it is thick";
    return cal;
  }
  cal.ok = true;
  return cal;
}

}  // namespace armmimic::bgsub
