// The marker engine's contract: reference checks with messages naming --reference, fixed views
// read within bounds (near zero yaw of either sign, large yaw from one marker, a covered marker),
// lost views with a reason, overlay data, options checks naming the flag.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/marker_scene.h"

namespace armmimic {
namespace {

std::unique_ptr<Engine> MarkerEngine() {
  EngineOptions o;
  o.kind = EngineKind::kMarker;
  return Engine::Create(o);
}

synth::MarkerSceneOptions PlainScene() {
  synth::MarkerSceneOptions o;
  o.seed = 7;
  o.lighting = "normal";
  o.background = "plain";
  o.views = 1;
  return o;
}

TEST(MarkerEngine, NeedsAReference) {
  auto engine = MarkerEngine();
  EXPECT_EQ(engine->kind(), EngineKind::kMarker);
  EngineContext context;
  const Status st = engine->Begin(context);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "analysis.reference") << st.message();
}

// Three measurable markers on a flat wall, with no joint around them: the joint's model refuses
// them, and says why and how many triples were tried, rather than a blob's contrast.
TEST(MarkerEngine, ARefusedReferenceNamesTheModelsReason) {
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = cv::Mat(240, 320, CV_8UC3, cv::Scalar(180, 180, 180));
  for (const cv::Point c : {cv::Point(160, 90), cv::Point(145, 150), cv::Point(175, 150)}) {
    cv::circle(context.reference, c, 5, cv::Scalar(20, 20, 20), cv::FILLED, cv::LINE_AA);
  }
  const Status st = engine->Begin(context);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "analysis.reference") << st.message();
  EXPECT_EQ(st.message().find("too little contrast"), std::string::npos) << st.message();
  EXPECT_NE(st.message().find("the reference: "), std::string::npos) << st.message();
  EXPECT_NE(st.message().find("of dark blobs tried)"), std::string::npos) << st.message();
}

TEST(MarkerEngine, RejectsAReferenceWithoutMarkers) {
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = cv::Mat(240, 320, CV_8UC3, cv::Scalar(180, 180, 180));
  const Status st = engine->Begin(context);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "analysis.reference") << st.message();
  EXPECT_NE(st.message().find("three markers"), std::string::npos) << st.message();
}

TEST(MarkerEngine, RejectsAReferenceOfAnotherSize) {
  const synth::MarkerSceneRenderer scene(PlainScene());
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = scene.Reference();
  context.frame_size = cv::Size(640, 480);
  const Status st = engine->Begin(context);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("320x240"), std::string::npos) << st.message();
}

// One engine calibrated on a scene's reference, for fixed views of it.
class MarkerViews : public ::testing::Test {
 protected:
  MarkerViews() : scene_(PlainScene()), engine_(MarkerEngine()) {
    EngineContext context;
    context.reference = scene_.Reference();
    begun_ = engine_->Begin(context);
  }
  ArmMeasurement View(double yaw, double bend, synth::MarkerTruth* truth = nullptr) {
    Frame frame;
    frame.image = scene_.RenderPose({yaw, bend}, 3, truth);
    frame.index = 4;
    frame.name = "view_004.png";
    return engine_->Process(frame);
  }
  ArmMeasurement Process(const cv::Mat& image) {
    Frame frame;
    frame.image = image;
    frame.name = "painted.png";
    return engine_->Process(frame);
  }
  synth::MarkerSceneRenderer scene_;
  std::unique_ptr<Engine> engine_;
  Status begun_;
};

TEST_F(MarkerViews, MeasuresAndFillsTheOverlay) {
  ASSERT_TRUE(begun_.ok()) << begun_.message();
  synth::MarkerTruth truth;
  const ArmMeasurement m = View(12, -35, &truth);
  ASSERT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
  EXPECT_EQ(m.file, "view_004.png");
  EXPECT_EQ(m.frame, 4);
  EXPECT_NEAR(m.yaw_signed_deg, 12, 0.5);
  EXPECT_DOUBLE_EQ(m.yaw_deg, std::abs(m.yaw_signed_deg));
  EXPECT_NEAR(m.bend_deg, -35, 0.5);
  EXPECT_GE(m.candidate_boxes.size(), 3u);
  ASSERT_EQ(m.marker_centres.size(), 3u);  // upper first, then left and right
  EXPECT_NEAR(m.marker_centres[0].x, truth.upper_px.x, 1.0);
  EXPECT_NEAR(m.marker_centres[0].y, truth.upper_px.y, 1.0);
  EXPECT_NEAR(m.marker_centres[1].x, truth.left_px.x, 1.0);
  EXPECT_NEAR(m.marker_centres[2].x, truth.right_px.x, 1.0);
  // The fitted cylinder: its axis runs up to the pivot, between the silhouette's edges.
  ASSERT_EQ(m.cylinder_axis_px.size(), 2u);
  ASSERT_EQ(m.cylinder_edges_px.size(), 4u);
  EXPECT_NEAR(cv::norm(m.cylinder_axis_px[1] - truth.pivot_px), 0, 1.5);
  EXPECT_GT(m.cylinder_axis_px[0].y, m.cylinder_axis_px[1].y);
  EXPECT_LT(m.cylinder_edges_px[0].x, m.cylinder_axis_px[0].x);
  EXPECT_GT(m.cylinder_edges_px[2].x, m.cylinder_axis_px[0].x);
  const AngleRow row = m.ToRow();
  EXPECT_TRUE(row.ok());
  EXPECT_EQ(row.file, "view_004.png");
  EXPECT_DOUBLE_EQ(row.yaw_signed_deg, m.yaw_signed_deg);
  // The meta line carries the cylinder calibration from the reference.
  bool has_radius = false;
  for (const auto& [k, v] : engine_->Describe()) has_radius |= k == "radius_px";
  EXPECT_TRUE(has_radius);
}

TEST_F(MarkerViews, NearZeroYawKeepsItsSign) {
  ASSERT_TRUE(begun_.ok()) << begun_.message();
  for (double yaw : {-3.0, -0.8, 0.0, 0.8, 3.0}) {
    const ArmMeasurement m = View(yaw, 20);
    ASSERT_EQ(m.phase, MeasurementPhase::kOk) << yaw << ": " << m.note;
    EXPECT_NEAR(m.yaw_signed_deg, yaw, 0.4) << m.note;
    EXPECT_NEAR(m.bend_deg, 20, 0.5);
  }
}

TEST_F(MarkerViews, LargeYawFromOneMarkerAndTheSilhouette) {
  ASSERT_TRUE(begun_.ok()) << begun_.message();
  // Past 35 degrees one lower marker turns round the side; the other and the silhouette suffice.
  for (double yaw : {-100.0, -55.0, 48.0, 90.0}) {
    synth::MarkerTruth truth;
    const ArmMeasurement m = View(yaw, -15, &truth);
    ASSERT_EQ(m.phase, MeasurementPhase::kOk) << yaw << ": " << m.note;
    EXPECT_FALSE(truth.left_readable && truth.right_readable) << yaw;
    EXPECT_NEAR(m.yaw_signed_deg, yaw, 1.0) << m.note;
    if (std::abs(yaw) <= 55) {
      EXPECT_NEAR(m.bend_deg, -15, 1.0) << yaw;
    } else {
      EXPECT_TRUE(std::isnan(m.bend_deg)) << yaw << ": the upper marker faces away";
    }
  }
}

TEST_F(MarkerViews, CoveredMarkerIsLostNotGuessed) {
  ASSERT_TRUE(begun_.ok()) << begun_.message();
  synth::MarkerTruth truth;
  cv::Mat image = scene_.RenderPose({5, 20}, 9, &truth);
  // Paint a marker over with the joint's own grey just above it: the right marker alone would
  // read as yaw 5 (but then the left one would show) or, as the left one, as about 85 (but then
  // the upper marker would face away, and it plainly faces the camera).
  auto cover = [&](cv::Point2d c) {
    const cv::Vec3b v = image.at<cv::Vec3b>(cvRound(c.y) - 10, cvRound(c.x));
    cv::circle(image, cv::Point(cvRound(c.x), cvRound(c.y)), 8, cv::Scalar(v[0], v[1], v[2]),
               cv::FILLED);
  };
  cover(truth.left_px);
  ArmMeasurement m = Process(image);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost) << "read as " << m.yaw_signed_deg;
  EXPECT_NE(m.note.find("contradicts"), std::string::npos) << m.note;
  cover(truth.right_px);
  m = Process(image);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost);
  EXPECT_FALSE(m.note.empty());
  EXPECT_FALSE(m.ToRow().ok());
  EXPECT_TRUE(std::isnan(m.ToRow().yaw_deg));
  EXPECT_TRUE(std::isnan(m.ToRow().yaw_signed_deg));
}

TEST_F(MarkerViews, NoReadableLowerMarkerIsLost) {
  ASSERT_TRUE(begun_.ok()) << begun_.message();
  for (double yaw : {-150.0, -125.0, 122.0, 180.0}) {
    synth::MarkerTruth truth;
    const ArmMeasurement m = View(yaw, 10, &truth);
    EXPECT_FALSE(truth.readable) << yaw;
    EXPECT_EQ(m.phase, MeasurementPhase::kLost) << yaw << " read as " << m.yaw_signed_deg;
  }
}

TEST(MarkerEngine, AWallAsBrightAsTheLimbStillGivesTheYaw) {
  const synth::MarkerSceneRenderer scene(PlainScene());
  // The lower part's right limb, from the pinhole camera (60 degrees, principal point centred).
  const double f = 160 / std::tan(30 * kPi / 180);
  const cv::Point2d pivot = scene.model().pivot_px;
  const double phi = std::atan((pivot.x - 160) / f);
  const double half = std::asin(scene.model().radius_px / std::hypot(pivot.x - 160, f));
  const int limb = static_cast<int>(std::floor(160 + f * std::tan(phi + half)));
  // Below the pivot, the wall right of the limb takes the limb's own grey in each row.
  auto hide = [&](cv::Mat image) {
    for (int y = static_cast<int>(pivot.y + 40); y < image.rows; ++y) {
      const cv::Vec3b limb_grey = image.at<cv::Vec3b>(y, limb - 1);
      for (int x = limb + 1; x < image.cols; ++x) image.at<cv::Vec3b>(y, x) = limb_grey;
    }
    return image;
  };
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = hide(scene.Reference());
  const Status begun = engine->Begin(context);
  ASSERT_TRUE(begun.ok()) << begun.message();
  for (double yaw : {-70.0, -20.0, 15.0, 60.0}) {
    Frame frame;
    frame.image = hide(scene.RenderPose({yaw, 10}, 5));
    const ArmMeasurement m = engine->Process(frame);
    ASSERT_EQ(m.phase, MeasurementPhase::kOk) << yaw << ": " << m.note;
    EXPECT_NEAR(m.yaw_signed_deg, yaw, 1.0);
  }
}

TEST(MarkerEngine, SideLightKeepsAFaintLitLimbWhereItIs) {
  // Seed 215 of the hard tier: side light makes the lit limb's step faint, and the reference's
  // markers (their centroids shifted by the shading) put the symmetric edge 4 px inside it.
  synth::MarkerSceneOptions o;
  o.seed = 215;
  o.background = "mixed";
  o.lighting = "mixed";
  o.clutter = 8;
  o.noise_sigma = 3;
  o.views = 1;
  const synth::MarkerSceneRenderer scene(o);
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = scene.Reference();
  ASSERT_TRUE(engine->Begin(context).ok());
  for (double yaw : {-38.0, -3.0, 14.0, 55.0, 84.0}) {
    Frame frame;
    frame.image = scene.RenderPose({yaw, -30}, 5);
    const ArmMeasurement m = engine->Process(frame);
    ASSERT_EQ(m.phase, MeasurementPhase::kOk) << yaw << ": " << m.note;
    EXPECT_NEAR(m.yaw_signed_deg, yaw, 1.0) << m.note;
  }
}

TEST(MarkerEngine, ImageOfAnotherSizeIsLost) {
  const synth::MarkerSceneRenderer scene(PlainScene());
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = scene.Reference();
  ASSERT_TRUE(engine->Begin(context).ok());
  Frame frame;
  frame.image = cv::Mat(100, 100, CV_8UC3, cv::Scalar::all(128));
  EXPECT_EQ(engine->Process(frame).phase, MeasurementPhase::kLost);
}

TEST(MarkerEngine, ShiftsTheGreyWindowUnderDimLight) {
  synth::MarkerSceneOptions o = PlainScene();
  o.lighting = "side";
  o.seed = 3;
  const synth::MarkerSceneRenderer scene(o);
  EngineOptions options;
  options.kind = EngineKind::kMarker;
  auto engine = Engine::Create(options);
  EngineContext context;
  context.reference = scene.Reference();
  ASSERT_TRUE(engine->Begin(context).ok());
  // With the window fixed at the thesis' 20..80 the same reference may not show its markers;
  // either way an explicit window is honoured.
  options.marker.auto_window = false;
  options.marker.low = 0;
  options.marker.high = 5;
  auto fixed = Engine::Create(options);
  EXPECT_FALSE(fixed->Begin(context).ok());
}

TEST(MarkerOptions, CheckNamesTheSetting) {
  MarkerOptions o;
  EXPECT_TRUE(o.Check().ok());
  o.low = 90;
  EXPECT_EQ(o.Check().key(), "marker.low");
  o = MarkerOptions();
  o.median_size = 4;
  EXPECT_EQ(o.Check().key(), "marker.median_size");
  o = MarkerOptions();
  o.high = 300;
  EXPECT_EQ(o.Check().key(), "marker.high");
  EngineOptions e;
  e.kind = EngineKind::kMarker;
  e.marker.low = 200;
  EXPECT_THROW(Engine::Create(e), std::invalid_argument);
}

}  // namespace
}  // namespace armmimic
