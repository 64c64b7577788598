// Where the upper arm turns (pose/shoulder_pivot.h), from hand-made elbows (no network): a sweep
// about a pivot below the keypoint gives the pivot, also while the person moves and leans in the
// image; too short an arc, or elbows that leave the circle (an arm moving out of the image
// plane), keep the keypoint.
#include "pose/shoulder_pivot.h"

#include <gtest/gtest.h>

#include <cmath>

namespace armmimic::internal {
namespace {

// The elbow `upper_px` from `pivot` at direction `deg` (image y down).
cv::Point2d Elbow(const cv::Point2d& pivot, double deg, double upper_px) {
  const double a = deg * M_PI / 180;
  return pivot + upper_px * cv::Point2d(std::cos(a), -std::sin(a));
}

// Turns `p` about `centre` by `deg` (image y down).
cv::Point2d Turn(const cv::Point2d& p, const cv::Point2d& centre, double deg) {
  const double a = -deg * M_PI / 180;
  const cv::Point2d d = p - centre;
  return centre +
         cv::Point2d(d.x * std::cos(a) - d.y * std::sin(a), d.x * std::sin(a) + d.y * std::cos(a));
}

TEST(ShoulderPivotTest, ASweepAboutAPivotBelowTheKeypointGivesThePivot) {
  ShoulderPivot pivot;
  const cv::Point2d keypoint(100, 90), truth(100, 100), hips(100, 200), shoulders(120, 90);
  cv::Point2d got;
  for (int i = 0; i <= 60; ++i) {
    got = pivot.Add(keypoint, Elbow(truth, -90 + 3 * i, 50), hips, shoulders);
  }
  EXPECT_LT(cv::norm(got - truth), 0.5) << got;
}

TEST(ShoulderPivotTest, ThePivotFollowsThePersonWhoMovesAndLeans) {
  ShoulderPivot pivot;
  cv::Point2d got, truth;
  for (int i = 0; i <= 60; ++i) {
    // The person walks 1 px a frame to the right and leans up to 15 degrees.
    const cv::Point2d shift(i, 0);
    const cv::Point2d hips = cv::Point2d(100, 200) + shift;
    const double lean = 15.0 * i / 60;
    const cv::Point2d keypoint = Turn(cv::Point2d(100, 90) + shift, hips, lean);
    const cv::Point2d shoulders = Turn(cv::Point2d(120, 90) + shift, hips, lean);
    truth = Turn(cv::Point2d(100, 100) + shift, hips, lean);
    got = pivot.Add(keypoint, Elbow(truth, -90 + 3 * i, 50), hips, shoulders);
  }
  EXPECT_LT(cv::norm(got - truth), 0.5) << got << " against " << truth;
}

TEST(ShoulderPivotTest, AShortArcKeepsTheKeypoint) {
  ShoulderPivot pivot;
  const cv::Point2d keypoint(100, 90), hips(100, 200), shoulders(120, 90);
  cv::Point2d got;
  for (int i = 0; i <= 60; ++i) {
    got = pivot.Add(keypoint, Elbow({100, 100}, -90 + 1.0 * i, 50), hips, shoulders);
  }
  EXPECT_EQ(got, keypoint);
}

TEST(ShoulderPivotTest, ElbowsThatLeaveTheCircleKeepTheKeypoint) {
  ShoulderPivot pivot;
  const cv::Point2d keypoint(100, 90), hips(100, 200), shoulders(120, 90);
  cv::Point2d got;
  for (int i = 0; i <= 60; ++i) {
    // The arm swings out of the image plane as it rises: its image length shrinks to a third.
    got = pivot.Add(keypoint, Elbow({100, 100}, -90 + 3 * i, 50 - 0.55 * i), hips, shoulders);
  }
  EXPECT_EQ(got, keypoint);
}

}  // namespace
}  // namespace armmimic::internal
