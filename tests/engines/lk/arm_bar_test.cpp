// The LK engine's sleeve measurements (lk/arm_bar.h) on drawn bars of known direction and width:
// the sleeve's axis is found from its edges whatever the joint's position, a width read too
// narrow no longer tilts it, and a sleeve's length and width are read as drawn.
#include "lk/arm_bar.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"

namespace armmimic::lk {
namespace {

const cv::Scalar kWall(200, 210, 215);
const cv::Vec3f kSleeve(120, 50, 25);

// A wall with a sleeve from `from_px` along `deg`, `length_px` long and 2 * `half_width_px` wide.
cv::Mat DrawSleeve(const cv::Point2d& from_px, double deg, double length_px, double half_width_px) {
  cv::Mat image(240, 320, CV_8UC3, kWall);
  const cv::Point2d to = from_px + length_px * DirectionVector(deg);
  const cv::Point2d n(-DirectionVector(deg).y, DirectionVector(deg).x);
  const cv::Point2d d = half_width_px * n;
  const std::vector<cv::Point> quad = {
      cv::Point(cvRound((from_px + d).x * 16), cvRound((from_px + d).y * 16)),
      cv::Point(cvRound((to + d).x * 16), cvRound((to + d).y * 16)),
      cv::Point(cvRound((to - d).x * 16), cvRound((to - d).y * 16)),
      cv::Point(cvRound((from_px - d).x * 16), cvRound((from_px - d).y * 16))};
  cv::fillConvexPoly(image, quad, cv::Scalar(kSleeve[0], kSleeve[1], kSleeve[2]), cv::LINE_AA, 4);
  return image;
}

ArmBar Bar(double half_width_px, bool measured) {
  ArmBar bar;
  bar.valid = true;
  bar.colour = kSleeve;
  bar.half_width_px = half_width_px;
  bar.width_measured = measured;
  return bar;
}

// Distance of `p` from the line through `a` along `deg`.
double LineDistance(const cv::Point2d& p, const cv::Point2d& a, double deg) {
  const cv::Point2d u = DirectionVector(deg);
  const cv::Point2d d = p - a;
  return std::abs(d.x * u.y - d.y * u.x);
}

TEST(LkArmBar, CentringFindsTheSleevesAxisFromAWrongStart) {
  const cv::Point2d shoulder(100, 120);
  const cv::Mat image = DrawSleeve(shoulder, 30, 60, 6);
  for (double start : {22.0, 27.0, 33.0, 38.0}) {
    const BarAxis axis = CentreArmBar(image, Bar(6, false), shoulder, start, 60, 12, false);
    ASSERT_TRUE(axis.found) << "from " << start;
    EXPECT_NEAR(axis.deg, 30, 0.5) << "from " << start;
    EXPECT_LT(LineDistance(axis.point_px, shoulder, 30), 0.5) << "from " << start;
  }
}

TEST(LkArmBar, CentringGivesTheDirectionWhateverTheJoint) {
  // The joint 3 px beside the sleeve's true start: the direction is still the sleeve's.
  const cv::Point2d shoulder(150, 60);
  const cv::Mat image = DrawSleeve(shoulder, -70, 70, 5);
  const cv::Point2d joint = shoulder + cv::Point2d(3, 0);
  const BarAxis axis = CentreArmBar(image, Bar(5, false), joint, -74, 70, 12, false);
  ASSERT_TRUE(axis.found);
  EXPECT_NEAR(axis.deg, -70, 0.6);
  EXPECT_LT(LineDistance(axis.point_px, shoulder, -70), 0.6);
}

TEST(LkArmBar, ANarrowStripLeansInsideAWideSleeveButTheCentreDoesNot) {
  // A bar width read at a quarter of the sleeve's: the strip search prefers either edge, the
  // centring does not.
  const cv::Point2d shoulder(60, 100);
  const cv::Mat image = DrawSleeve(shoulder, 0, 80, 8);
  const ArmBar narrow = Bar(2, false);
  const BarSearch search = SearchArmBar(image, narrow, shoulder, 0, 80, 20, 0.2);
  ASSERT_TRUE(search.found);
  const BarAxis axis = CentreArmBar(image, narrow, shoulder, search.deg, 80, 14, false);
  ASSERT_TRUE(axis.found);
  EXPECT_NEAR(axis.deg, 0, 0.5) << "search alone said " << search.deg;
}

TEST(LkArmBar, OneSidedCentringNeedsAMeasuredWidth) {
  // The sleeve lies against a body in the same cloth on one side.
  const cv::Point2d shoulder(160, 40);
  cv::Mat image = DrawSleeve(shoulder, -90, 90, 6);
  cv::rectangle(image, cv::Rect(100, 20, 54, 150), cv::Scalar(kSleeve[0], kSleeve[1], kSleeve[2]),
                cv::FILLED);
  EXPECT_FALSE(CentreArmBar(image, Bar(6, false), shoulder, -87, 90, 12, true).found);
  EXPECT_FALSE(CentreArmBar(image, Bar(6, true), shoulder, -87, 90, 12, false).found);
  const BarAxis axis = CentreArmBar(image, Bar(6, true), shoulder, -87, 90, 12, true);
  ASSERT_TRUE(axis.found);
  EXPECT_NEAR(axis.deg, -90, 0.6);
}

TEST(LkArmBar, CentringRefusesWhereThereIsNoSleeve) {
  const cv::Mat image(240, 320, CV_8UC3, kWall);
  EXPECT_FALSE(CentreArmBar(image, Bar(5, true), {160, 120}, 0, 60, 12, true).found);
}

TEST(LkArmBar, HalfWidthIsMeasuredAcrossAClearSleeve) {
  const cv::Point2d shoulder(80, 200);
  for (double hw : {3.0, 5.0, 8.0}) {
    const cv::Mat image = DrawSleeve(shoulder, 40, 90, hw);
    EXPECT_NEAR(MeasureBarHalfWidth(image, Bar(2, false), shoulder, 40, 90, 14), hw, 0.6)
        << "half-width " << hw;
  }
}

TEST(LkArmBar, HalfWidthIsNotMeasuredAgainstTheBody) {
  const cv::Point2d shoulder(160, 40);
  cv::Mat image = DrawSleeve(shoulder, -90, 90, 6);
  cv::rectangle(image, cv::Rect(100, 20, 54, 150), cv::Scalar(kSleeve[0], kSleeve[1], kSleeve[2]),
                cv::FILLED);
  EXPECT_LT(MeasureBarHalfWidth(image, Bar(6, false), shoulder, -90, 90, 12), 0);
}

TEST(LkArmBar, LengthEndsWhereTheSleeveDoesAndSaysWhetherItResumes) {
  const cv::Point2d shoulder(40, 120);
  cv::Mat image = DrawSleeve(shoulder, 0, 50, 5);
  double beyond = -1;
  EXPECT_NEAR(MeasureBarLength(image, Bar(5, false), shoulder, 0, 120, &beyond), 50, 1.5);
  EXPECT_LT(beyond, 0.05);
  // A gap in the sleeve, then more sleeve: the run ends at the gap, but the sleeve resumes.
  image = DrawSleeve(shoulder, 0, 100, 5);
  cv::rectangle(image, cv::Rect(88, 100, 4, 40), kWall, cv::FILLED);
  EXPECT_NEAR(MeasureBarLength(image, Bar(5, false), shoulder, 0, 120, &beyond), 48, 1.5);
  EXPECT_GT(beyond, 0.4);
}

TEST(LkArmBar, ShareAroundCountsTheSleeveNearAPoint) {
  const cv::Point2d shoulder(40, 120);
  const cv::Mat image = DrawSleeve(shoulder, 0, 50, 5);
  EXPECT_GT(BarShareAround(image, Bar(5, false), {65, 120}, 4), 0.95);     // inside the sleeve
  EXPECT_LT(BarShareAround(image, Bar(5, false), {100, 120}, 4), 0.01);    // past its end
  const double edge = BarShareAround(image, Bar(5, false), {90, 120}, 4);  // on its end
  EXPECT_GT(edge, 0.3);
  EXPECT_LT(edge, 0.7);
}

}  // namespace
}  // namespace armmimic::lk
