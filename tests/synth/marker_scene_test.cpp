// Marker scenes: repeatable, truth from the 3D model, the visibility limit, and the files.
#include <cmath>

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

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

constexpr double kRad = 3.14159265358979 / 180;

TEST(MarkerScene, FlatModelTruthFollowsTheParallelProjection) {
  MarkerSceneOptions o = Small(3);
  o.camera.projection = "orthographic";
  const MarkerSceneRenderer scene(o);
  const MarkerJointModel& m = scene.model();
  const double alpha = m.marker_angle_deg * kRad;
  for (double yaw : {-30.0, 0.0, 20.0}) {
    for (double bend : {-50.0, 0.0, 35.0}) {
      MarkerTruth t;
      scene.RenderPose({yaw, bend}, 1, &t);
      const double psi = yaw * kRad;
      const double b = bend * kRad;
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
      EXPECT_NEAR(t.left_cos, std::cos(psi - alpha), 1e-9);
      EXPECT_TRUE(t.readable);
    }
  }
}

TEST(MarkerScene, PerspectiveTruthIsThePinholeProjection) {
  MarkerSceneOptions o = Small(4);
  o.camera.fov_deg = 50;
  const MarkerSceneRenderer scene(o);
  const MarkerJointModel& m = scene.model();
  const double f = 160 / std::tan(25 * kRad), cx = 160, cy = 120;
  // The pivot sits f from the camera, where one model unit is one pixel.
  const cv::Vec3d pivot(m.pivot_px.x - cx, cy - m.pivot_px.y, -f);
  auto image = [&](const cv::Vec3d& w) {
    const cv::Vec3d c = pivot + w;
    return cv::Point2d(cx + f * c[0] / -c[2], cy - f * c[1] / -c[2]);
  };
  const double psi = 25 * kRad, b = -30 * kRad, a = m.marker_angle_deg * kRad;
  const double R = m.radius_px, e = m.pivot_distance_px;
  // Object point -> world: yaw turns x towards z.
  auto turn = [&](double x, double y, double z) {
    return cv::Vec3d(x * std::cos(psi) + z * std::sin(psi), y,
                     -x * std::sin(psi) + z * std::cos(psi));
  };
  MarkerTruth t;
  scene.RenderPose({25, -30}, 1, &t);
  EXPECT_NEAR(cv::norm(t.pivot_px - m.pivot_px), 0, 1e-9);
  EXPECT_NEAR(cv::norm(t.left_px - image(turn(-R * std::sin(a), -e, R * std::cos(a)))), 0, 1e-9);
  EXPECT_NEAR(cv::norm(t.right_px - image(turn(R * std::sin(a), -e, R * std::cos(a)))), 0, 1e-9);
  EXPECT_NEAR(cv::norm(t.upper_px - image(turn(-e * std::sin(b), e * std::cos(b), R))), 0, 1e-9);
  // Nearer the camera than the pivot, the upper marker projects further from it than e.
  scene.RenderPose({0, 0}, 1, &t);
  EXPECT_GT(t.pivot_px.y - t.upper_px.y, e * 1.05);
}

TEST(MarkerScene, AViewIsReadableWhileALowerMarkerFacesTheCamera) {
  MarkerSceneOptions o = Small(3);
  o.camera.projection = "orthographic";  // facing angles are then exactly yaw -+ alpha
  const MarkerSceneRenderer scene(o);
  MarkerTruth t;
  scene.RenderPose({34, 0}, 1, &t);  // 40 + 34 = 74 degrees
  EXPECT_TRUE(t.left_readable && t.right_readable && t.upper_readable);
  scene.RenderPose({36, 0}, 1, &t);  // the right marker is past 75, the left one is not
  EXPECT_TRUE(t.readable);
  EXPECT_FALSE(t.right_readable);
  EXPECT_TRUE(t.left_readable);
  scene.RenderPose({-114, 10}, 1, &t);  // only the right marker, 74 degrees from the camera
  EXPECT_TRUE(t.readable);
  EXPECT_FALSE(t.upper_readable);
  scene.RenderPose({-116, 10}, 1, &t);  // no lower marker faces the camera within 75
  EXPECT_FALSE(t.readable);
  EXPECT_NEAR(t.right_cos, std::cos(76 * kRad), 1e-9);
}

TEST(MarkerScene, TheCylinderIsShadedAndCutsItsMarkersAtTheLimb) {
  MarkerSceneOptions o = Small(6);
  o.background = "plain";
  o.lighting = "normal";
  o.clutter = 0;
  o.noise_sigma = 0;
  const MarkerSceneRenderer scene(o);
  MarkerTruth t;
  cv::Mat grey;
  cv::cvtColor(scene.RenderPose({0, 0}, 1, &t), grey, cv::COLOR_BGR2GRAY);
  // The silhouette of an upright cylinder seen by a level pinhole camera.
  const double f = 160 / std::tan(30 * kRad);
  const double phi = std::atan((t.pivot_px.x - 160) / f);
  const double half = std::asin(scene.model().radius_px / std::hypot(t.pivot_px.x - 160, f));
  const int row = static_cast<int>(t.left_px.y) + 20;
  const double left = 160 + f * std::tan(phi - half), right = 160 + f * std::tan(phi + half);
  const int axis = static_cast<int>(std::lround(0.5 * (left + right)));
  // Lambertian: darker towards both limbs than at the front.
  EXPECT_LT(grey.at<uchar>(row, static_cast<int>(std::ceil(left + 1))), grey.at<uchar>(row, axis));
  EXPECT_LT(grey.at<uchar>(row, static_cast<int>(std::floor(right - 1))),
            grey.at<uchar>(row, axis));
  // The lower part's shading does not turn with it: at yaw 180 it shows no marker, which makes
  // it the surface under the markers of every other view.
  cv::Mat bare;
  cv::cvtColor(scene.RenderPose({180, 0}, 1), bare, cv::COLOR_BGR2GRAY);
  auto marked = [&](const cv::Mat& g, cv::Point2d c) {
    int n = 0;
    for (int y = static_cast<int>(c.y) - 10; y <= c.y + 10; ++y) {
      for (int x = static_cast<int>(c.x) - 10; x <= c.x + 10; ++x) {
        n += bare.at<uchar>(y, x) - g.at<uchar>(y, x) > 25;
      }
    }
    return n;
  };
  const int facing = marked(grey, t.right_px);
  // Turned 82 degrees round, the right marker's far half lies beyond the limb: a sliver shows.
  cv::cvtColor(scene.RenderPose({42, 0}, 1, &t), grey, cv::COLOR_BGR2GRAY);
  EXPECT_FALSE(t.right_readable);
  const int cut = marked(grey, {right - 10, t.right_px.y});
  EXPECT_GT(cut, 0);
  EXPECT_LT(cut, facing / 3);
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
  EXPECT_EQ(o.Check().key(), "marker_scene.lighting");
  EXPECT_NE(o.Check().message().find("moon"), std::string::npos);
  o = MarkerSceneOptions();
  o.size = {100, 100};
  EXPECT_EQ(o.Check().key(), "marker_scene.size");
  o = MarkerSceneOptions();
  o.max_yaw_deg = 200;
  EXPECT_EQ(o.Check().key(), "marker_scene.max_yaw_deg");
  EXPECT_THROW(MarkerSceneRenderer{o}, std::invalid_argument);
  o = MarkerSceneOptions();
  o.camera.projection = "fisheye";
  EXPECT_EQ(o.Check().key(), "marker_scene.camera");
  o = MarkerSceneOptions();
  o.camera.fov_deg = 5;
  EXPECT_EQ(o.Check().key(), "marker_scene.fov_deg");
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
  for (const char* c : {"yaw_signed_deg", "upper_readable", "left_readable", "right_readable"}) {
    EXPECT_GE(truth.ExtraColumn(c), 0) << c;
  }
  EXPECT_EQ(truth.Meta("camera"), "perspective");
  EXPECT_EQ(truth.rows[1].extra[file], "view_001.png");
  EXPECT_TRUE(std::isnan(truth.rows[1].upper_deg));
  const MarkerSceneRenderer scene(o);
  EXPECT_NEAR(truth.rows[1].yaw_deg, scene.Truth(1).yaw_deg, 1e-3);
  EXPECT_NEAR(truth.rows[1].bend_deg, scene.Truth(1).bend_deg, 1e-3);
}

}  // namespace
}  // namespace armmimic::synth
