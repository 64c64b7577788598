#include "lk/arm_flow.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "common/order_statistic.h"

namespace armmimic::lk {
namespace {

constexpr double kMinLeverPx = 4;     // nearer its joint, a feature tells no turn
constexpr int kSeedInterval = 5;      // frames between seedings
constexpr int kMinPartFeatures = 8;   // fewer on a part: seed at once
constexpr int kMaxPartFeatures = 40;  // per arm part
constexpr int kMaxBodyFeatures = 30;
// The body's features: part of a ring around the shoulder (shares of the upper arm), below the
// shoulder's height, so clear of the sleeve's cap that rises with the arm and of the head (which
// nods on its own): the torso, which sways with the shoulder.
constexpr double kBodyInner = 0.3, kBodyOuter = 1.2;
constexpr double kBelowShoulder = 0.25;  // of the upper arm: the ring's top, below the shoulder
constexpr double kOffArmPx = 2;          // beyond the half-width: off the arm
constexpr int kMinBodyFeatures = 4;

// The hand's end: the forearm's features reach over the hand.
cv::Point2d HandEnd(const arm::ArmJoints& j, const arm::ArmShape& shape) {
  const double fl = cv::norm(j.wrist - j.elbow);
  return fl > 0 ? j.wrist + shape.hand_px / fl * (j.wrist - j.elbow) : j.wrist;
}

bool OnBody(const cv::Point2d& p, const cv::Point2d& shoulder, double upper_px) {
  const double r = cv::norm(p - shoulder);
  return r >= kBodyInner * upper_px && r <= kBodyOuter * upper_px &&
         p.y >= shoulder.y + kBelowShoulder * upper_px;
}

}  // namespace

void ArmFlow::Reset(const cv::Mat& gray) {
  flow_.Reset(gray);
  feats_.clear();
  since_seed_ = kSeedInterval;
}

FlowCue ArmFlow::Track(const cv::Mat& gray, const arm::ArmPose& pose, const arm::ArmShape& shape) {
  FlowCue cue;
  TrackFeatures(&flow_, gray, &feats_);
  ++since_seed_;
  // The body first: the shoulder moves with it.
  std::vector<double> dx, dy;
  for (const Feature& f : feats_) {
    if (f.part != 0) continue;
    dx.push_back(f.p.x - f.prev.x);
    dy.push_back(f.p.y - f.prev.y);
  }
  cue.body_count = static_cast<int>(dx.size());
  if (cue.body_count >= kMinBodyFeatures) {
    cue.shoulder_shift = {arm::NearestRankQuantile(dx, 0.5), arm::NearestRankQuantile(dy, 0.5)};
  }
  const arm::ArmJoints then = arm::JointsOf(pose, shape);
  const cv::Point2d shoulder_now = pose.shoulder + cue.shoulder_shift;
  std::vector<double> turns[2];
  for (const Feature& f : feats_) {
    if (f.part != 1) continue;
    const cv::Point2d a(f.prev), b(f.p);
    if (cv::norm(a - then.shoulder) < kMinLeverPx || cv::norm(b - shoulder_now) < kMinLeverPx) {
      continue;
    }
    turns[0].push_back(AngleDiff(DirectionDeg(shoulder_now, b), DirectionDeg(then.shoulder, a)));
  }
  cue.upper_count = static_cast<int>(turns[0].size());
  cue.upper_turn_deg = arm::NearestRankQuantile(turns[0], 0.5);
  const double upper_now =
      pose.upper_deg + (std::isfinite(cue.upper_turn_deg) ? cue.upper_turn_deg : 0.0);
  const cv::Point2d elbow_now = shoulder_now + shape.upper_px * DirectionVector(upper_now);
  for (const Feature& f : feats_) {
    if (f.part != 2) continue;
    const cv::Point2d a(f.prev), b(f.p);
    if (cv::norm(a - then.elbow) < kMinLeverPx || cv::norm(b - elbow_now) < kMinLeverPx) continue;
    turns[1].push_back(AngleDiff(DirectionDeg(elbow_now, b), DirectionDeg(then.elbow, a)));
  }
  cue.fore_count = static_cast<int>(turns[1].size());
  cue.fore_turn_deg = arm::NearestRankQuantile(turns[1], 0.5);
  return cue;
}

void ArmFlow::Refresh(const cv::Mat& gray, const arm::ArmPose& pose, const arm::ArmShape& shape) {
  const arm::ArmJoints j = arm::JointsOf(pose, shape);
  const cv::Point2d hand = HandEnd(j, shape);
  int count[3] = {0, 0, 0};
  std::size_t w = 0;
  for (Feature f : feats_) {
    const cv::Point2d p(f.p);
    const double du = arm::DistanceToSegment(p, j.shoulder, j.elbow);
    const double df = arm::DistanceToSegment(p, j.elbow, hand);
    if (f.part == 0) {
      // The body's features stay near the shoulder and off the arm.
      const bool on_arm = du < shape.upper_hw + kOffArmPx || df < shape.fore_hw + kOffArmPx;
      if (on_arm || !OnBody(p, j.shoulder, shape.upper_px)) continue;
    } else {
      if (du < shape.upper_hw + kOffArmPx && du <= df) {
        f.part = 1;
      } else if (df < shape.fore_hw + kOffArmPx) {
        f.part = 2;
      } else {
        continue;  // off the arm: background, or it slid along an edge
      }
    }
    ++count[f.part];
    feats_[w++] = f;
  }
  feats_.resize(w);
  const bool short_part =
      count[1] < kMinPartFeatures || count[2] < kMinPartFeatures || count[0] < kMinBodyFeatures;
  if (since_seed_ >= kSeedInterval || short_part) Seed(gray, pose, shape);
}

void ArmFlow::ForgetArm() {
  feats_.erase(
      std::remove_if(feats_.begin(), feats_.end(), [](const Feature& f) { return f.part != 0; }),
      feats_.end());
}

void ArmFlow::Seed(const cv::Mat& gray, const arm::ArmPose& pose, const arm::ArmShape& shape) {
  since_seed_ = 0;
  const arm::ArmJoints j = arm::JointsOf(pose, shape);
  const cv::Point2d hand = HandEnd(j, shape);
  auto pt = [](const cv::Point2d& p) { return cv::Point(cvRound(p.x), cvRound(p.y)); };
  const double reach = shape.upper_px + shape.fore_px + shape.hand_px;
  const cv::Rect area = cv::Rect(pt(j.shoulder - cv::Point2d(reach, reach)),
                                 cv::Size(cvRound(2 * reach) + 1, cvRound(2 * reach) + 1)) &
                        cv::Rect(0, 0, gray.cols, gray.rows);
  if (area.width < 8 || area.height < 8) return;
  const cv::Point2d o(area.tl());
  cv::Mat mask[3];
  for (cv::Mat& m : mask) m = cv::Mat::zeros(area.size(), CV_8U);
  // Arm parts: their strips, a pixel inside the edges (corners on the edge slide along it).
  const int tu = std::max(1, cvRound(2 * (shape.upper_hw - 1))),
            tf = std::max(1, cvRound(2 * (shape.fore_hw - 1)));
  cv::line(mask[1], pt(j.shoulder - o), pt(j.elbow - o), cv::Scalar(255), tu);
  cv::line(mask[2], pt(j.elbow - o), pt(hand - o), cv::Scalar(255), tf);
  // The body: a ring around the shoulder, clear of the arm.
  cv::circle(mask[0], pt(j.shoulder - o), cvRound(kBodyOuter * shape.upper_px), cv::Scalar(255),
             cv::FILLED);
  cv::circle(mask[0], pt(j.shoulder - o), cvRound(kBodyInner * shape.upper_px), cv::Scalar(0),
             cv::FILLED);
  const int top = cvRound(j.shoulder.y - o.y + kBelowShoulder * shape.upper_px);
  if (top > 0) mask[0].rowRange(0, std::min(top, mask[0].rows)).setTo(0);
  arm::ArmJoints local = j;
  local.shoulder -= o;
  local.elbow -= o;
  local.wrist -= o;
  arm::DrawArm(mask[0], local, shape, 4, 0);
  int count[3] = {0, 0, 0};
  std::vector<cv::Point2f> existing;
  for (const Feature& f : feats_) {
    ++count[f.part];
    existing.emplace_back(f.p.x - static_cast<float>(o.x), f.p.y - static_cast<float>(o.y));
  }
  const int limit[3] = {kMaxBodyFeatures, kMaxPartFeatures, kMaxPartFeatures};
  const cv::Mat roi = gray(area);
  for (int part = 0; part < 3; ++part) {
    const int room = limit[part] - count[part];
    if (room <= 0) continue;
    for (const cv::Point2f& c : DetectCorners(roi, mask[part], existing, room, o_)) {
      Feature f;
      f.p = f.prev = c + cv::Point2f(static_cast<float>(o.x), static_cast<float>(o.y));
      f.part = part;
      feats_.push_back(f);
      existing.push_back(c);
    }
  }
}

std::vector<cv::Point2f> ArmFlow::Points(int part) const {
  std::vector<cv::Point2f> out;
  for (const Feature& f : feats_) {
    if (f.part == part) out.push_back(f.p);
  }
  return out;
}

}  // namespace armmimic::lk
