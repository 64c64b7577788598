// The arm's evidence (arm_appearance.h) on small painted frames: the learnt background does not
// take in the arm where the pose missed it, takes in the scene once it has held still, and the
// evidence does not see a change of the light as the arm.
#include "common/arm_appearance.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace armmimic::arm {
namespace {

const cv::Scalar kWall(90, 140, 170), kSleeve(40, 60, 200), kOther(200, 200, 60);
const cv::Rect kFrame(0, 0, 120, 90);
const cv::Rect kArmAtStart(50, 20, 12, 60);  // the arm where the joints were clicked
const cv::Rect kArmLater(20, 20, 12, 60);    // the arm where the pose did not follow it

cv::Mat Wall() { return cv::Mat(kFrame.size(), CV_8UC3, kWall); }

cv::Mat WithBox(const cv::Mat& frame, const cv::Rect& box, const cv::Scalar& colour) {
  cv::Mat out = frame.clone();
  cv::rectangle(out, box, colour, cv::FILLED);
  return out;
}

cv::Mat Mask(const cv::Rect& box) {
  cv::Mat m = cv::Mat::zeros(kFrame.size(), CV_8U);
  cv::rectangle(m, box, cv::Scalar(255), cv::FILLED);
  return m;
}

// The colour model of the start frame: the sleeve against the wall.
ColourModel SleeveModel() {
  const cv::Mat start = WithBox(Wall(), kArmAtStart, kSleeve);
  cv::Mat around = cv::Mat(kFrame.size(), CV_8U, cv::Scalar(255));
  around.setTo(0, Mask(kArmAtStart));
  ColourModel m;
  m.Learn(start, Mask(kArmAtStart), around);
  return m;
}

float MeanIn(const cv::Mat& map, const cv::Rect& box) {
  return static_cast<float>(cv::mean(map(box & cv::Rect(0, 0, map.cols, map.rows)))[0]);
}

// One update with the evidence of `frame`, the pose (hidden) at kArmAtStart.
void Step(LearntBackground& bg, const ColourModel& colour, const cv::Mat& frame) {
  EvidenceMap ev;
  ev.Compute(frame, bg, colour, kFrame, Mask(kArmAtStart));
  bg.Update(frame, Mask(kArmAtStart), 0.2, kFrame, ev, colour);
}

TEST(LearntBackground, ArmOutsideThePoseIsNotLearnt) {
  const ColourModel colour = SleeveModel();
  ASSERT_GT(colour.Probability(cv::Vec3b(40, 60, 200)), 0.5f);
  LearntBackground bg;
  bg.Reset(WithBox(Wall(), kArmAtStart, kSleeve), Mask(kArmAtStart));
  // The arm is elsewhere than the pose for a few frames: it stays evidence, frame after frame.
  const cv::Mat frame = WithBox(Wall(), kArmLater, kSleeve);
  for (int i = 0; i < 10; ++i) Step(bg, colour, frame);
  EvidenceMap ev;
  ev.Compute(frame, bg, colour, kFrame, Mask(kArmAtStart));
  EXPECT_GT(MeanIn(ev.map(), kArmLater), 0.8f) << "the arm was learnt as the scene";
  EXPECT_LT(MeanIn(ev.map(), cv::Rect(80, 10, 30, 70)), 0.05f);
}

TEST(LearntBackground, UnknownPixelsAreTakenByTheirColour) {
  const ColourModel colour = SleeveModel();
  LearntBackground bg;
  bg.Reset(WithBox(Wall(), kArmAtStart, kSleeve), Mask(kArmAtStart));
  const cv::Rect uncovered(50, 20, 12, 30);
  const cv::Mat hidden = Mask(cv::Rect(50, 50, 12, 30));
  // A poster in another colour behind where the arm hung: the scene at once.
  {
    LearntBackground b;  // a copy of bg would share its pixels
    b.Reset(WithBox(Wall(), kArmAtStart, kSleeve), Mask(kArmAtStart));
    const cv::Mat frame =
        WithBox(WithBox(Wall(), uncovered, kOther), cv::Rect(50, 50, 12, 30), kSleeve);
    EvidenceMap ev;
    ev.Compute(frame, b, colour, kFrame, hidden);
    b.Update(frame, hidden, 0.2, kFrame, ev, colour);
    EXPECT_EQ(cv::countNonZero(b.known()(uncovered)), uncovered.area());
  }
  // Cloth in the sleeve's colour there: unknown until it has held still long enough.
  const cv::Mat frame = WithBox(Wall(), cv::Rect(50, 20, 12, 60), kSleeve);
  int updates = 0;
  while (cv::countNonZero(bg.known()(uncovered)) < uncovered.area() && updates < 100) {
    EvidenceMap ev;
    ev.Compute(frame, bg, colour, kFrame, hidden);
    bg.Update(frame, hidden, 0.2, kFrame, ev, colour);
    ++updates;
    if (updates < 10) {
      EXPECT_EQ(cv::countNonZero(bg.known()(uncovered)), 0) << "after " << updates;
    }
  }
  EXPECT_GE(updates, 10);
  EXPECT_LE(updates, 40) << "still cloth never became the scene";
}

TEST(EvidenceMap, ALightChangeIsNotTheArm) {
  const ColourModel colour = SleeveModel();
  // A wall with a texture, so that the light has something to scale.
  cv::Mat wall = Wall();
  for (int y = 0; y < wall.rows; y += 6) cv::line(wall, {0, y}, {wall.cols, y}, kWall * 0.7);
  LearntBackground bg;
  bg.Reset(WithBox(wall, kArmAtStart, kSleeve), Mask(kArmAtStart));
  // The light drops by a third over the whole picture, the arm has moved out of the pose.
  cv::Mat dim;
  WithBox(wall, kArmLater, kSleeve).convertTo(dim, CV_8UC3, 0.66);
  EvidenceMap ev;
  ev.Compute(dim, bg, colour, kFrame, Mask(kArmAtStart));
  EXPECT_LT(MeanIn(ev.map(), cv::Rect(80, 10, 30, 70)), 0.05f) << "the dimmed wall is evidence";
  EXPECT_GT(MeanIn(ev.map(), kArmLater), 0.6f) << "the dimmed arm is not";
}

}  // namespace
}  // namespace armmimic::arm
