// The rig renderer (`synth marker --renderer rig`): repeatable per seed, each seed its own rig,
// the truth's marker centres where the images show the markers, and options checked by key.
#include "armmimic/synth/marker_rig.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace armmimic::synth {
namespace {

MarkerRigOptions Options(const std::string& set, uint64_t seed) {
  MarkerRigOptions o;
  o.set = set;
  o.seed = seed;
  o.views = 3;
  return o;
}

double Grey(const cv::Mat& bgr, cv::Point2d p) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  return grey.at<uchar>(cvRound(p.y), cvRound(p.x));
}

TEST(MarkerRig, TheSameSeedGivesTheSameViewsAndEachSeedItsOwnRig) {
  const MarkerRigRenderer a(Options("medium", 7)), b(Options("medium", 7)), c(Options("medium", 8));
  EXPECT_EQ(cv::norm(a.Render(1), b.Render(1), cv::NORM_INF), 0);
  EXPECT_EQ(a.Pose(2).yaw_deg, b.Pose(2).yaw_deg);
  EXPECT_NE(a.rig().radius_px, c.rig().radius_px);
  EXPECT_NE(a.rig().fov_deg, c.rig().fov_deg);
  EXPECT_LE(std::abs(a.Pose(0).yaw_deg), 60);
}

TEST(MarkerRig, TheTruthPutsTheMarkersWhereTheReferenceShowsThem) {
  for (const char* set : {"easy", "medium", "hard"}) {
    for (uint64_t seed : {3, 4}) {
      const MarkerRigRenderer rig(Options(set, seed));
      MarkerTruth t;
      const cv::Mat ref = rig.Reference(&t);
      ASSERT_TRUE(t.left_readable && t.right_readable && t.upper_readable) << set << seed;
      // Each marker centre is dark against the ball at the pivot (the joint's bright surface).
      const double surface = Grey(ref, t.pivot_px);
      for (const cv::Point2d& p : {t.left_px, t.right_px, t.upper_px}) {
        EXPECT_LT(Grey(ref, p), 0.6 * surface) << set << " seed " << seed << " at " << p;
      }
      // Zero yaw: the lower markers lie either side of the upper one.
      EXPECT_LT(t.left_px.x, t.upper_px.x);
      EXPECT_GT(t.right_px.x, t.upper_px.x);
      EXPECT_GT(t.left_px.y, t.upper_px.y);
    }
  }
}

TEST(MarkerRig, AYawTurnsTheFrontTowardsScreenRight) {
  const MarkerRigRenderer rig(Options("easy", 5));
  MarkerTruth zero, turned;
  rig.RenderPose({0, 0}, 1, &zero);
  rig.RenderPose({20, 0}, 1, &turned);
  EXPECT_GT(turned.left_px.x, zero.left_px.x);
  EXPECT_GT(turned.right_px.x, zero.right_px.x);
  EXPECT_DOUBLE_EQ(turned.yaw_deg, 20);
  EXPECT_GT(turned.left_cos, zero.left_cos);  // the left marker turns towards the camera
}

TEST(MarkerRig, CheckNamesTheSetting) {
  MarkerRigOptions o;
  o.set = "extreme";
  EXPECT_EQ(o.Check().key(), "marker_scene.set");
  o = MarkerRigOptions();
  o.max_yaw_deg = 200;
  EXPECT_EQ(o.Check().key(), "marker_scene.max_yaw_deg");
  EXPECT_THROW(MarkerRigRenderer{o}, std::invalid_argument);
}

}  // namespace
}  // namespace armmimic::synth
