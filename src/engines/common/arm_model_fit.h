// The two-segment arm model scored against the evidence map (arm_appearance.h): how well an arm
// of the learnt lengths and widths, in a given pose, explains a frame. A segment scores the mean
// evidence inside its strip minus the mean on its two flanks, so a strip inside a larger region
// of the arm's colour (or beside the body in the same cloth) scores less than one that is the
// arm. The searches find the best pose near a prediction, and the best pose anywhere the arm can
// reach, which tells whether a far-apart pose explains the frame about as well (ambiguity).
//
// Shared by the tracking engines (lk, and the hybrid engine). Qt-free.
#pragma once

#include <limits>
#include <vector>

#include "common/arm_appearance.h"
#include "common/segment_score.h"

namespace armmimic::arm {

struct ArmPose {
  cv::Point2d shoulder;
  double upper_deg = -90, fore_deg = -90;  // the contract's directions (CCW on screen from +x)
};

ArmJoints JointsOf(const ArmPose& pose, const ArmShape& shape);

// The distance from `p` to the segment `a`-`b`, pixels.
double DistanceToSegment(const cv::Point2d& p, const cv::Point2d& a, const cv::Point2d& b);

// The strip of half-width `hw_px` from `from_px` along `deg`, over [t0, t1] x `length_px`.
// Flank samples closer than `avoid_hw_px` to the segment `avoid_a`-`avoid_b` (the other part of
// the arm) are left out when `avoid_hw_px` > 0. `coarse` takes fewer samples (a wide search).
SegmentScore ScoreSegment(const EvidenceMap& evidence, const cv::Point2d& from_px, double deg,
                          double length_px, double hw_px, double t0, double t1, bool coarse = false,
                          const cv::Point2d& avoid_a = {}, const cv::Point2d& avoid_b = {},
                          double avoid_hw_px = 0);

struct PoseScore {
  SegmentScore upper, fore;
  double total = -2;  // upper.score + fore.score
};

PoseScore ScorePose(const EvidenceMap& evidence, const ArmPose& pose, const ArmShape& shape,
                    bool coarse = false);

// The forearm folded back onto the upper arm by more than this is not searched (its strip would
// lie on the upper arm's own sleeve), nor reported.
inline constexpr double kMaxBendDeg = 150;

struct LocalSearch {
  double upper_range_deg = 15;  // searched around the prediction, 1-degree steps
  double bend_range_deg = 15;
};

struct FitResult {
  ArmPose pose;
  PoseScore score;
};

// The best pose with the shoulder of `predicted`, within the ranges of its directions (the bend
// kept), refined between the 1-degree steps.
FitResult FitNear(const EvidenceMap& evidence, const ArmShape& shape, const ArmPose& predicted,
                  const LocalSearch& search);

// What one frame's search over every pose leaves for the next frame's, to save it work and never
// to change what it returns: the coarse score its `count`-th best pose reached.
struct WideSearchMemory {
  double last_floor = -std::numeric_limits<double>::infinity();
};

// The best poses over every direction of the upper arm and every bend the elbow allows (coarse
// steps, then refined), as local maxima of the upper arm's score, best first. `count` poses at
// most. With `memory`, a coarse pose that can no longer reach a little below the last frame's
// floor is given up; where fewer than `count` poses reach it, the given-up ones are scored in
// full. The result is the same, to the bit, with or without it.
std::vector<FitResult> FitAnywhere(const EvidenceMap& evidence, const ArmShape& shape,
                                   const cv::Point2d& shoulder, int count,
                                   WideSearchMemory* memory = nullptr);

// The best forearm score with the upper arm of `pose` kept and the bend at least `apart_deg` away
// from the pose's (3-degree steps over every bend the elbow allows): how well another forearm
// direction explains the image. A forearm lying on cloth of its own colour is seen about as well
// in many directions; its evidence then does not say where it is. The rivals are scored over the
// forearm alone, elbow to wrist (a region of the arm's colour that could hold the forearm but
// not the hand is still a place the forearm may be). -2 when no bend is apart enough.
double ForeRivalScore(const EvidenceMap& evidence, const ArmShape& shape, const ArmPose& pose,
                      double apart_deg);

// The largest turn of either segment between two poses, degrees.
double PoseDistanceDeg(const ArmPose& a, const ArmPose& b);

}  // namespace armmimic::arm
