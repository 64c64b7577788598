// The arm's joints from the standstill and the arm-length image (common/standstill_calibration.h).
// Length: CalibrateFromStandstill is the calibration's steps in order (body, straight arm, side,
// width, shoulder, hanging direction, joints), each a few lines over the same masks.
#include "common/standstill_calibration.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angle_file.h"
#include "common/colour_difference.h"
#include "common/order_statistic.h"
#include "common/straight_arm.h"

namespace armmimic {
namespace {

// Anthropometric segment lengths as shares of body height: upper arm, forearm, hand. Only their
// ratio is used: shoulder to wrist over shoulder to fingertip.
constexpr double kUpperShare = 0.186, kForeShare = 0.146, kHandShare = 0.108;
constexpr double kWristOfReach =
    (kUpperShare + kForeShare) / (kUpperShare + kForeShare + kHandShare);
// A region of the standstill's difference this many times smaller than the torso is a speck.
constexpr int kBodyPartShare = 25;
// A hanging arm fitted further than this from straight down is not believed (the protocol asks
// for the arm to hang); the search for its edge leans out as far.
constexpr double kMaxHangFromDownDeg = 35;
constexpr int kMinHangingRows = 5;
constexpr double kHangingShare = 0.5;

struct Part {
  int label = 0, area = 0;
  cv::Rect box;
};

std::vector<Part> Parts(const cv::Mat& mask, cv::Mat* labels) {
  cv::Mat stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, *labels, stats, centroids, 8, CV_32S);
  std::vector<Part> parts;
  for (int i = 1; i < n; ++i) {
    parts.push_back(
        {i, stats.at<int>(i, cv::CC_STAT_AREA),
         cv::Rect(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                  stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT))});
  }
  return parts;
}

const Part* Largest(const std::vector<Part>& parts) {
  const Part* best = nullptr;
  for (const Part& p : parts) {
    if (!best || p.area > best->area) best = &p;
  }
  return best;
}

void Open3(cv::Mat* mask) {
  cv::morphologyEx(*mask, *mask, cv::MORPH_OPEN, cv::Mat::ones(3, 3, CV_8UC1));
}

// Where the three images differ from each other (ColourDifferenceMask), each taken once.
struct Differences {
  cv::Mat standstill_room;        // the standstill against the empty room: the standing person
  cv::Mat arm_length_room;        // the arm-length image against the empty room
  cv::Mat arm_length_standstill;  // the arm-length image against the standstill
};

// The standing body: the largest region of the standstill's difference from the empty room, with
// every sizeable region beside it (the head, a hanging arm a gap of wall away).
bool FindBody(const Differences& d, cv::Mat* body, cv::Rect* box) {
  cv::Mat person = d.standstill_room.clone(), labels;
  Open3(&person);
  const std::vector<Part> parts = Parts(person, &labels);
  const Part* main = Largest(parts);
  if (!main || main->area < 0.005 * static_cast<double>(person.total())) return false;
  *body = cv::Mat::zeros(person.size(), CV_8UC1);
  // The box also takes the parts above and below the largest one (InTheBodysColumns).
  *box = main->box;
  for (const Part& p : parts) {
    if (p.label == main->label || p.area >= std::max(16, main->area / kBodyPartShare)) {
      body->setTo(255, labels == p.label);
      if (InTheBodysColumns(main->box, p.box)) *box |= p.box;
    }
  }
  cv::morphologyEx(*body, *body, cv::MORPH_CLOSE, cv::Mat::ones(5, 5, CV_8UC1));
  return true;
}

// The straight arm of the arm-length image: the largest region outside the standing body that
// differs from both the empty room and the standstill, with the pieces in line with it (an arm
// broken where it crosses something of its own colour), centred high enough in the body's box
// `body_box` for a shoulder (CentredHighEnoughForAShoulder). `band`: its rows, around the fullest.
bool FindStraightArm(const Differences& d, const cv::Mat& body, const cv::Rect& body_box,
                     cv::Mat* arm, cv::Rect* band) {
  cv::Mat both = d.arm_length_room & d.arm_length_standstill, labels;
  both.setTo(0, body);
  Open3(&both);
  const std::vector<Part> parts = Parts(both, &labels);
  std::vector<Part> high;
  for (const Part& p : parts) {
    if (CentredHighEnoughForAShoulder(p.box, body_box)) high.push_back(p);
  }
  const Part* main = Largest(high);
  if (!main) return false;
  *arm = labels == main->label;
  const cv::Rect rows = HorizontalBand(*arm, main->box);
  *band = rows;
  for (const Part& p : parts) {
    const double cy = p.box.y + 0.5 * p.box.height;
    const int gap = std::max(p.box.x - (band->x + band->width), band->x - (p.box.x + p.box.width));
    if (p.label == main->label || p.area < std::max(8, main->area / 20) || cy < rows.y ||
        cy > rows.y + rows.height || p.box.height > 1.5 * rows.height + 2 ||
        gap > band->width / 2) {
      continue;
    }
    arm->setTo(255, labels == p.label);
    *band |= cv::Rect(p.box.x, rows.y, p.box.width, rows.height);
  }
  return true;
}

// x = a + b (y - y0) through `points`: b the median of the pairwise slopes, a the median
// intercept (Theil-Sen: a row that meets something else moves neither).
void FitAxis(const std::vector<cv::Point2d>& points, double y0, double* a, double* b) {
  *b = arm::TheilSenSlope(points, 0);
  *a = arm::MedianIntercept(points, y0, *b);
}

}  // namespace

std::string StandstillCalibration::Describe(const cv::Point2d& offset) const {
  auto xy = [&offset](const cv::Point2d& p) {
    return FormatNumber(p.x + offset.x, 0) + "," + FormatNumber(p.y + offset.y, 0);
  };
  return std::string(
             "calibrated from the standstill and the arm-length image: the arm on the "
             "image's ") +
         (side > 0 ? "right" : "left") + ", shoulder " + xy(shoulder) + ", elbow " + xy(elbow) +
         ", wrist " + xy(wrist) + "; hanging at " + FormatNumber(hanging_deg, 0) + " deg (" +
         (hanging_rows > 0 ? "fitted on " + std::to_string(hanging_rows) + " rows"
                           : std::string("straight down assumed")) +
         "), reach " + FormatNumber(reach_px, 0) + " px, width " +
         FormatNumber(2 * half_width_px, 0) + " px";
}

StandstillCalibration CalibrateFromStandstill(const cv::Mat& background, const cv::Mat& standstill,
                                              const cv::Mat& arm_length, int threshold, int side,
                                              double upper_fraction) {
  StandstillCalibration cal;
  if (background.empty() || standstill.empty() || arm_length.empty() ||
      background.size() != standstill.size() || arm_length.size() != standstill.size()) {
    cal.note = "needs the background, the standstill and the arm-length image, of one size";
    return cal;
  }
  const Differences d{ColourDifferenceMask(standstill, background, threshold),
                      ColourDifferenceMask(arm_length, background, threshold),
                      ColourDifferenceMask(arm_length, standstill, threshold)};
  cv::Mat body, arm;
  cv::Rect body_box, band;
  if (!FindBody(d, &body, &body_box)) {
    cal.note = "no person in the standstill: it does not differ from the background";
    return cal;
  }
  if (!FindStraightArm(d, body, body_box, &arm, &band)) {
    cal.note = "the arm-length image: no arm differs from the standstill";
    return cal;
  }
  const cv::Moments mo = cv::moments(arm(band), true);
  const double arm_cx = band.x + (mo.m00 > 0 ? mo.m10 / mo.m00 : 0.5 * band.width);
  const int centre = body_box.x + body_box.width / 2;
  cal.side = arm_cx >= centre ? 1 : -1;
  if (side != 0 && side != cal.side) {
    cal.note = std::string("the arm-length image's straight arm is on the image's ") +
               (cal.side > 0 ? "right" : "left") + ", not on the side named";
    return cal;
  }
  StraightArmColumns cols = MeasureStraightArm(arm, band, cal.side);
  if (!cols.ok) {
    cal.note = "the arm-length image: the straight arm is too small";
    return cal;
  }
  // The fixed threshold loses an arm held out over a wall of nearly its colour.
  cols.outer_x = ContinueStraightArm(arm_length, standstill, cols, cal.side);
  const double thick = cols.thick_px;
  const double r = std::max(1.0, 0.5 * thick);
  cal.half_width_px = r;
  const double shoulder_y = cols.axis_y;
  const int inner = cols.inner_x;
  const double first_reach = cal.side * (cols.outer_x - inner) + 1;
  // The hanging upper arm: where the standstill shows the person but the arm-length image shows
  // the empty room again (the arm has left), from two radii below the shoulder down to the
  // elbow's expected height. Its axis in each row is the middle of that region near the straight
  // arm's inner end (the search leans out as far as an arm may hang); a row where less than an
  // arm radius of it shows (the arm in front of something of its own colour) gives none.
  const cv::Mat left_empty = d.standstill_room & d.arm_length_standstill & ~d.arm_length_room;
  const double lean = std::tan(kMaxHangFromDownDeg * M_PI / 180);
  const int y0 = static_cast<int>(std::lround(shoulder_y + 2 * r));
  const int y1 = static_cast<int>(
      std::lround(shoulder_y + upper_fraction * kWristOfReach * (first_reach + r)));
  std::vector<cv::Point2d> axis;
  for (int y = std::max(0, y0); y <= std::min(left_empty.rows - 1, y1); ++y) {
    const double reach_out = lean * (y - shoulder_y);
    const int from = static_cast<int>(std::lround(inner - cal.side * (4 * r + reach_out)));
    const int to = static_cast<int>(std::lround(inner + cal.side * (2 * r + reach_out)));
    int lo = left_empty.cols, hi = -1, count = 0;
    for (int x = std::max(0, std::min(from, to));
         x <= std::min(left_empty.cols - 1, std::max(from, to)); ++x) {
      if (!left_empty.at<uchar>(y, x)) continue;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
      ++count;
    }
    if (count < r) continue;
    // A row narrower than the arm whose inner side meets the person of the arm-length image shows
    // only the arm's part clear of the torso (a sleeve that hung over the body's side, in the
    // shirt's colour, is no change where the body stays): its outer edge, against the room, is
    // the arm's, and the axis lies a radius in from it.
    const int beside = cal.side > 0 ? lo - 1 : hi + 1;
    const bool covered = hi - lo + 1 < 2 * r && beside >= 0 && beside < left_empty.cols &&
                         d.arm_length_room.at<uchar>(y, beside) != 0;
    const double outer_edge = cal.side > 0 ? hi + 0.5 : lo - 0.5;
    axis.emplace_back(covered ? outer_edge - cal.side * r : 0.5 * (lo + hi), y);
  }
  // Without it in at least kHangingShare of those rows (the arm in front of something of its own
  // colour, a sleeve in the room's), where the arm hangs is not shown: no calibration rather than
  // a guessed start, which the tracker would follow confidently.
  const int searched = std::min(left_empty.rows - 1, y1) - std::max(0, y0) + 1;
  if (static_cast<int>(axis.size()) <
      std::max(kMinHangingRows, static_cast<int>(std::ceil(kHangingShare * searched)))) {
    cal.note = "the hanging arm does not show against the empty room (" +
               std::to_string(axis.size()) + " of " + std::to_string(std::max(searched, 0)) +
               " rows of the upper arm)";
    return cal;
  }
  // Where the straight arm leaves the hanging one: one arm radius inside its inner end.
  double shoulder_x = inner - cal.side * r;
  cal.hanging_deg = -90;
  if (static_cast<int>(axis.size()) >= kMinHangingRows) {
    double a = 0, b = 0;
    FitAxis(axis, shoulder_y, &a, &b);
    const double deg = DirectionDeg(cv::Point2d(0, 0), cv::Point2d(b, 1));
    if (std::abs(deg + 90) <= kMaxHangFromDownDeg) {
      cal.hanging_deg = deg;
      cal.hanging_rows = static_cast<int>(axis.size());
      shoulder_x = a;
    }
    // The two images must agree on the shoulder: the hanging arm's axis meets the shoulder's row
    // where the straight arm leaves the body. When they do not, one of them saw only part of the
    // arm (a sleeve in the room's colour ends the straight arm early), and neither is believed.
    const double straight_x = inner - cal.side * r;
    if (std::abs(a - straight_x) > 2 * r + 2) {
      cal.note = "the hanging arm and the straight arm disagree on the shoulder (" +
                 FormatNumber(std::abs(a - straight_x), 0) + " px apart)";
      return cal;
    }
  }
  cal.shoulder = cv::Point2d(shoulder_x, shoulder_y);
  cal.reach_px = cal.side * (cols.outer_x - shoulder_x) + 0.5;
  if (!(cal.reach_px > 4 * r)) {
    cal.note = "the arm-length image: the straight arm is shorter than it is thick";
    return cal;
  }
  const double a = cal.hanging_deg * M_PI / 180;
  const cv::Point2d dir(std::cos(a), -std::sin(a));
  const double to_wrist = kWristOfReach * cal.reach_px;
  cal.elbow = cal.shoulder + upper_fraction * to_wrist * dir;
  cal.wrist = cal.shoulder + to_wrist * dir;
  const cv::Rect2d image(0, 0, standstill.cols, standstill.rows);
  if (!image.contains(cal.shoulder) || !image.contains(cal.elbow) || !image.contains(cal.wrist)) {
    cal.note = "the estimated hanging arm leaves the image";
    return cal;
  }
  cal.ok = true;
  return cal;
}

StandstillCalibration CalibrateFromStandstill(const cv::Mat& background, const cv::Mat& standstill,
                                              const cv::Mat& arm_length, const LkOptions& lk) {
  const int side = lk.side == LkArmSide::kLeft ? -1 : lk.side == LkArmSide::kRight ? 1 : 0;
  return CalibrateFromStandstill(background, standstill, arm_length, lk.body_threshold, side,
                                 lk.upper_fraction);
}

}  // namespace armmimic
