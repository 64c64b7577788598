// The LK engine's body box (thesis 6.1): the standing person where the standstill differs from
// the background, with every large piece of a person whose shirt is close to the wall's colour.
#include "lk/body_box.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace armmimic::lk {
namespace {

// A wall, and a person drawn as a head and neck, a shirt in `shirt` and trousers.
void Scene(const cv::Scalar& shirt, cv::Mat* background, cv::Mat* standstill) {
  *background = cv::Mat(240, 320, CV_8UC3, cv::Scalar(190, 200, 205));
  *standstill = background->clone();
  cv::circle(*standstill, {160, 50}, 14, cv::Scalar(90, 120, 170), cv::FILLED);  // head
  cv::rectangle(*standstill, cv::Rect(154, 60, 12, 12), cv::Scalar(90, 120, 170), cv::FILLED);
  cv::rectangle(*standstill, cv::Rect(130, 70, 60, 100), shirt, cv::FILLED);  // shirt
  cv::rectangle(*standstill, cv::Rect(138, 170, 44, 70), cv::Scalar(60, 40, 30), cv::FILLED);
}

TEST(LkBodyBox, ThePersonIsTheBox) {
  cv::Mat background, standstill;
  Scene(cv::Scalar(120, 50, 25), &background, &standstill);
  const BodyBox body = FindBodyBox(background, standstill, LkOptions());
  ASSERT_TRUE(body.found);
  EXPECT_EQ(body.box, cv::Rect(130, 36, 60, 204));
  EXPECT_LT(body.left_shoulder.x, body.right_shoulder.x);
}

TEST(LkBodyBox, AShirtInTheWallsColourLeavesPiecesThatStillSpanThePerson) {
  cv::Mat background, standstill;
  Scene(cv::Scalar(185, 198, 206), &background, &standstill);
  LkOptions anchored;
  const BodyBox body = FindBodyBox(background, standstill, anchored);
  ASSERT_TRUE(body.found);
  EXPECT_EQ(body.box.y, 36);                     // from the head
  EXPECT_EQ(body.box.y + body.box.height, 240);  // to the trousers
  // The thesis path keeps its rule: the largest region alone (the trousers).
  LkOptions thesis;
  thesis.thesis_mode = true;
  const BodyBox largest = FindBodyBox(background, standstill, thesis);
  ASSERT_TRUE(largest.found);
  EXPECT_EQ(largest.box, cv::Rect(138, 170, 44, 70));
}

TEST(LkBodyBox, NoPersonNoBox) {
  cv::Mat background(240, 320, CV_8UC3, cv::Scalar(190, 200, 205));
  EXPECT_FALSE(FindBodyBox(background, background.clone(), LkOptions()).found);
}

}  // namespace
}  // namespace armmimic::lk
