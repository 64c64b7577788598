#include "common/arm_support.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angle_file.h"

namespace armmimic::arm {
namespace {

// The share a segment needs, of the standstill arm's share on the same cue.
constexpr double kShareOfRest = 0.5;
// A standstill arm its cue saw on fewer of its samples than this is taken as seen on this many
// (the rule then asks for a quarter of a segment: the cue still separates arm from room).
constexpr double kLowestRestShare = 0.5;
// The flanks: from this share of the half-width (at least kFlankMinGapPx) outside the segment,
// along its middle part (the ends touch the body at the shoulder and the other segment at the
// elbow).
constexpr double kFlankGap = 0.5, kFlankMinGapPx = 2, kFlankFrom = 0.25, kFlankTo = 0.8;

struct Counter {
  const cv::Mat& mask;
  cv::Point origin;
  int set = 0, n = 0;
  void At(const cv::Point2d& p) {
    ++n;
    const int x = cvRound(p.x) - origin.x, y = cvRound(p.y) - origin.y;
    if (x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<uchar>(y, x)) ++set;
  }
};

// Samples from `a` + t0 to `b` along the axis and half a half-width either side of it.
void SampleSegment(const cv::Point2d& a, const cv::Point2d& b, double t0, double half_width,
                   Counter* c) {
  const double len = cv::norm(b - a);
  if (!(len > 0)) return;
  const cv::Point2d d = (b - a) / len, n(-d.y, d.x);
  const double off = 0.5 * half_width;
  for (double t = std::min(t0, 0.5 * len); t <= len; t += 1.0) {
    const cv::Point2d p = a + d * t;
    c->At(p);
    if (off >= 1) {
      c->At(p + n * off);
      c->At(p - n * off);
    }
  }
}

double DistanceToSegment(const cv::Point2d& p, const cv::Point2d& a, const cv::Point2d& b) {
  const cv::Point2d ab = b - a;
  const double len2 = ab.dot(ab);
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return cv::norm(p - (a + ab * t));
}

// The clearer flank's share of a segment from `a` to `b` (0 when it has no samples). Flank
// samples on the pose's other segment (from `c` to `d`, of half-width `other_hw`) are the pose's
// own arm, not a wider region: they are left out.
double FlankShare(const cv::Mat& mask, const cv::Point& origin, const cv::Point2d& a,
                  const cv::Point2d& b, double half_width, const cv::Point2d& c,
                  const cv::Point2d& d, double other_hw) {
  const double len = cv::norm(b - a);
  if (!(len > 0)) return 0;
  const cv::Point2d dir = (b - a) / len, n(-dir.y, dir.x);
  const double gap = std::max(kFlankMinGapPx, kFlankGap * half_width);
  const double own = other_hw + std::max(kFlankMinGapPx, kFlankGap * other_hw);
  double clearer = 1;
  for (int side : {-1, 1}) {
    Counter count{mask, origin};
    for (double t = kFlankFrom * len; t <= kFlankTo * len; t += 1.0) {
      for (double across : {half_width + gap, 2 * half_width + gap}) {
        const cv::Point2d p = a + dir * t + n * (side * across);
        if (DistanceToSegment(p, c, d) > own) count.At(p);
      }
    }
    clearer = std::min(clearer, count.n > 0 ? static_cast<double>(count.set) / count.n : 0.0);
  }
  return clearer;
}

}  // namespace

PoseSupport MeasureSupport(const cv::Mat& shows_arm, const cv::Mat& flank_mask,
                           const cv::Point& origin, const ArmJoints& pose, const ArmShape& shape) {
  PoseSupport s;
  Counter upper{shows_arm, origin}, fore{shows_arm, origin};
  SampleSegment(pose.shoulder, pose.elbow, shape.upper_hw, shape.upper_hw, &upper);
  SampleSegment(pose.elbow, pose.wrist, 0, shape.fore_hw, &fore);
  if (!flank_mask.empty()) {
    s.flank = std::max(FlankShare(flank_mask, origin, pose.shoulder, pose.elbow, shape.upper_hw,
                                  pose.elbow, pose.wrist, shape.fore_hw),
                       FlankShare(flank_mask, origin, pose.elbow, pose.wrist, shape.fore_hw,
                                  pose.shoulder, pose.elbow, shape.upper_hw));
  }
  s.upper_samples = upper.n;
  s.fore_samples = fore.n;
  s.upper = upper.n > 0 ? static_cast<double>(upper.set) / upper.n : 0;
  s.fore = fore.n > 0 ? static_cast<double>(fore.set) / fore.n : 0;
  return s;
}

void SupportRule::Calibrate(const PoseSupport& rest) {
  rest_share_ = rest.weaker();
  // A standstill arm that fails the rule it sets (a segment of it off the person): the
  // calibration does not match the standstill, and no pose can be checked against it.
  required_ = kShareOfRest * std::max(rest_share_, kLowestRestShare);
  if (rest_share_ < required_) required_ = 0;
}

std::string SupportRule::Verdict(const PoseSupport& now, bool fresh) const {
  if (!fresh) return "the pose is held from an earlier frame, not measured in this one";
  if (!calibrated()) {
    return "the calibrated arm, hanging, does not lie on the standstill's person (support " +
           FormatNumber(rest_share_, 2) + "): the calibration is not checked";
  }
  if (now.weaker() < required_) {
    return std::string(now.upper < now.fore ? "the upper arm" : "the forearm") +
           " lies on pixels that show no arm now (support " + FormatNumber(now.weaker(), 2) +
           ", needs " + FormatNumber(required_, 2) + ")";
  }
  if (now.flank > flank_limit()) {
    return "a segment lies in a region wider than the arm (arm pixels on both flanks: " +
           FormatNumber(now.flank, 2) + ", at most " + FormatNumber(flank_limit(), 2) + ")";
  }
  return {};
}

}  // namespace armmimic::arm
