// MoveNet as a second opinion on BlazePose's arm (docs/pose.md, "BlazePose: a second opinion").
// BlazePose's own scores (person flag, visibility, presence) do not say when it has misread a
// figure unlike its training people: on generated figures its 2-D arm was biased by 15-20 degrees
// with every score high. Two networks trained apart seldom err alike, so a BlazePose row is `ok`
// only where MoveNet's looks at the same frame put the same arm in the same place.
#pragma once

#include <array>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/engines/pose.h"
#include "armmimic/engines/pose_options.h"
#include "pose/looks.h"

namespace armmimic::internal {

// Empty when MoveNet's looks bear out BlazePose's `side` arm `blaze` (keypoints in MoveNet's
// order, the same pixels as the looks'); otherwise why not, for the row's note:
//  - MoveNet does not see one of the arm's joints (body look score below min_score);
//  - MoveNet's own looks disagree (each closer look against the body look, by the measure below
//    with max_disagreement_deg): the second opinion is itself unsure;
//  - the shoulder, or the far end of a segment, is farther from MoveNet's than
//    sin(max_network_disagreement_deg) times the segment's length: for a segment seen at full
//    length, directions that differ by more than about that bound. The length is at least the
//    segment's anthropometric floor in torso lengths, so a segment foreshortened towards the
//    camera is compared by its joints' places rather than by a direction it does not have.
//  - a segment's 3-D direction (`world`: shoulder, elbow, wrist in BlazePose's world frame)
//    turns from MoveNet's segment in the image plane by more than that bound, weighted
//    by how much of the segment lies in that plane: BlazePose's world landmarks come from another
//    head of the network than its image landmarks, and can be wrong where those are right.
//    BlazePose's world frame has no perspective; `frame` (the whole frame's size, the principal
//    point at its centre) lets the check project the segment through any camera from a 90 degree
//    field of view to an orthographic one, and take the one that turns it least far.
std::string SecondOpinion(const PoseLooks& movenet, const PoseKeypoints& blaze,
                          const std::array<cv::Vec3d, 3>& world, const cv::Size& frame,
                          PoseSide side, const PoseOptions& options);

}  // namespace armmimic::internal
