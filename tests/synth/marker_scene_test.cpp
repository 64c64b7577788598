// Marker scenes: repeatable, truth from the 3D model, the visibility limit, and the files.
#include <cmath>

#include <gtest/gtest.h>

#include "armmimic/core/image_io.h"
#include "armmimic/synth/marker_scene.h"
#include "armmimic/synth/truth_file.h"
#include "test_util.h"

namespace armmimic::synth {
namespace {

MarkerSceneOptions Small(uint64_t seed) {
  MarkerSceneOptions o;
  o.seed = seed;
  o.views = 4;
  o.clutter = 3;
  return o;
}

TEST(MarkerScene, SameSeedSameImagesWhateverTheOrder) {
  const MarkerSceneRenderer a(Small(11));
  const MarkerSceneRenderer b(Small(11));
  const cv::Mat a2 = a.Render(2);
  const cv::Mat a0 = a.Render(0);
  EXPECT_EQ(cv::norm(a0, b.Render(0), cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a2, b.Render(2), cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a.Reference(), b.Reference(), cv::NORM_INF), 0);
  const MarkerSceneRenderer c(Small(12));
  EXPECT_GT(cv::norm(a0, c.Render(0), cv::NORM_L1), 0);
  EXPECT_EQ(a0.size(), cv::Size(320, 240));
  EXPECT_EQ(a0.type(), CV_8UC3);
}

TEST(MarkerScene, TruthFollowsTheModelGeometry) {
  const MarkerSceneRenderer scene(Small(3));
  const MarkerJointModel& m = scene.model();
  const double alpha = m.marker_angle_deg * 3.14159265358979 / 180;
  for (double yaw : {-30.0, 0.0, 20.0}) {
    for (double bend : {-50.0, 0.0, 35.0}) {
      MarkerTruth t;
      scene.RenderPose({yaw, bend}, 1, &t);
      const double psi = yaw * 3.14159265358979 / 180;
      const double b = bend * 3.14159265358979 / 180;
      EXPECT_DOUBLE_EQ(t.yaw_deg, std::abs(yaw));
      EXPECT_DOUBLE_EQ(t.bend_deg, bend);
      // n = N cos(yaw) with N = 2 R sin(alpha); the lower pair level, e below the pivot.
      EXPECT_NEAR(t.right_px.x - t.left_px.x, 2 * m.radius_px * std::sin(alpha) * std::cos(psi),
                  1e-9);
      EXPECT_NEAR(t.left_px.y - t.pivot_px.y, m.pivot_distance_px, 1e-9);
      // Upper marker: e along the bent axis, R in front of it; only its height is free of yaw.
      EXPECT_NEAR(t.pivot_px.y - t.upper_px.y, m.pivot_distance_px * std::cos(b), 1e-9);
      EXPECT_NEAR(t.upper_px.x - t.pivot_px.x,
                  -m.pivot_distance_px * std::sin(b) * std::cos(psi) + m.radius_px * std::sin(psi),
                  1e-9);
      EXPECT_TRUE(t.readable);
    }
  }
}

TEST(MarkerScene, MarkersPastSeventyFiveDegreesAreUnreadable) {
  const MarkerSceneRenderer scene(Small(3));
  MarkerTruth t;
  scene.RenderPose({34, 0}, 1, &t);
  EXPECT_TRUE(t.readable);  // 40 + 34 = 74 degrees
  scene.RenderPose({36, 0}, 1, &t);
  EXPECT_FALSE(t.readable);
  scene.RenderPose({-36, 10}, 1, &t);
  EXPECT_FALSE(t.readable);
  EXPECT_NEAR(t.min_marker_cos, std::cos(76 * 3.14159265358979 / 180), 1e-9);
}

TEST(MarkerScene, ReferenceShowsThreeDarkMarkers) {
  MarkerSceneOptions o = Small(5);
  o.clutter = 0;
  o.noise_sigma = 0;
  o.lighting = "normal";
  const MarkerSceneRenderer scene(o);
  MarkerTruth t;
  const cv::Mat ref = scene.Reference(&t);
  EXPECT_EQ(t.file, "reference.png");
  EXPECT_DOUBLE_EQ(t.yaw_deg, 0);
  for (const cv::Point2d& p : {t.upper_px, t.left_px, t.right_px}) {
    const cv::Vec3b v = ref.at<cv::Vec3b>(cvRound(p.y), cvRound(p.x));
    EXPECT_LT(v[1], 80) << p;  // inside the thesis' 20..80 window
    EXPECT_GT(v[1], 20) << p;
  }
}

TEST(MarkerScene, CheckNamesTheOption) {
  MarkerSceneOptions o;
  EXPECT_TRUE(o.Check().ok());
  o.lighting = "moon";
  EXPECT_NE(o.Check().message().find("--lighting"), std::string::npos);
  o = MarkerSceneOptions();
  o.size = {100, 100};
  EXPECT_NE(o.Check().message().find("--size"), std::string::npos);
  o = MarkerSceneOptions();
  o.max_yaw_deg = 120;
  EXPECT_NE(o.Check().message().find("--max-yaw"), std::string::npos);
  EXPECT_THROW(MarkerSceneRenderer{o}, std::invalid_argument);
}

TEST(MarkerScene, WritesImagesReferenceAndTruth) {
  test::TempDir dir;
  MarkerSceneOptions o = Small(2);
  o.views = 3;
  ASSERT_TRUE(WriteMarkerScene(o, dir.path(), {}).ok());
  cv::Mat image;
  EXPECT_TRUE(ReadImage(dir.file("reference.png"), &image).ok());
  EXPECT_TRUE(ReadImage(dir.file("views/view_002.png"), &image).ok());
  TruthFile truth;
  ASSERT_TRUE(ReadTruthFile(dir.file("truth.tsv"), &truth).ok());
  EXPECT_EQ(truth.Meta("scene"), "marker");
  ASSERT_EQ(truth.rows.size(), 3u);
  const int file = truth.ExtraColumn("file");
  const int readable = truth.ExtraColumn("readable");
  ASSERT_GE(file, 0);
  ASSERT_GE(readable, 0);
  EXPECT_EQ(truth.rows[1].extra[file], "view_001.png");
  EXPECT_TRUE(std::isnan(truth.rows[1].upper_deg));
  const MarkerSceneRenderer scene(o);
  EXPECT_NEAR(truth.rows[1].yaw_deg, scene.Truth(1).yaw_deg, 1e-3);
  EXPECT_NEAR(truth.rows[1].bend_deg, scene.Truth(1).bend_deg, 1e-3);
}

}  // namespace
}  // namespace armmimic::synth
