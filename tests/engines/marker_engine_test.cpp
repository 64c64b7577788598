// The marker engine's contract: reference checks with messages naming --reference, lost views
// with a reason, overlay data, options checks naming the flag.
#include <memory>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

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
  EXPECT_NE(st.message().find("--reference"), std::string::npos) << st.message();
}

TEST(MarkerEngine, RejectsAReferenceWithoutMarkers) {
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = cv::Mat(240, 320, CV_8UC3, cv::Scalar(180, 180, 180));
  const Status st = engine->Begin(context);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("--reference"), std::string::npos) << st.message();
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

TEST(MarkerEngine, MeasuresAndFillsTheOverlay) {
  const synth::MarkerSceneRenderer scene(PlainScene());
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = scene.Reference();
  ASSERT_TRUE(engine->Begin(context).ok());
  synth::MarkerTruth truth;
  Frame frame;
  frame.image = scene.RenderPose({12, -35}, 3, &truth);
  frame.index = 4;
  frame.name = "view_004.png";
  const ArmMeasurement m = engine->Process(frame);
  ASSERT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
  EXPECT_EQ(m.file, "view_004.png");
  EXPECT_EQ(m.frame, 4);
  EXPECT_NEAR(m.yaw_deg, 12, 1.5);
  EXPECT_NEAR(m.bend_deg, -35, 1.5);
  EXPECT_GE(m.candidate_boxes.size(), 3u);
  ASSERT_EQ(m.marker_centres.size(), 3u);  // upper first, then left and right
  EXPECT_NEAR(m.marker_centres[0].x, truth.upper_px.x, 1.0);
  EXPECT_NEAR(m.marker_centres[0].y, truth.upper_px.y, 1.0);
  EXPECT_NEAR(m.marker_centres[1].x, truth.left_px.x, 1.0);
  EXPECT_NEAR(m.marker_centres[2].x, truth.right_px.x, 1.0);
  const AngleRow row = m.ToRow();
  EXPECT_TRUE(row.ok());
  EXPECT_EQ(row.file, "view_004.png");
  // The meta line carries N and e from the reference.
  bool has_n = false;
  for (const auto& [k, v] : engine->Describe()) has_n |= k == "N_px";
  EXPECT_TRUE(has_n);
}

TEST(MarkerEngine, CoveredMarkerIsLostNotGuessed) {
  const synth::MarkerSceneRenderer scene(PlainScene());
  auto engine = MarkerEngine();
  EngineContext context;
  context.reference = scene.Reference();
  ASSERT_TRUE(engine->Begin(context).ok());
  synth::MarkerTruth truth;
  Frame frame;
  frame.image = scene.RenderPose({5, 20}, 9, &truth);
  // Paint the left marker over with the joint's own colour.
  const cv::Vec3b skin =
      frame.image.at<cv::Vec3b>(cvRound(truth.left_px.y) - 12, cvRound(truth.left_px.x));
  cv::circle(frame.image, cv::Point(cvRound(truth.left_px.x), cvRound(truth.left_px.y)), 9,
             cv::Scalar(skin[0], skin[1], skin[2]), cv::FILLED);
  const ArmMeasurement m = engine->Process(frame);
  EXPECT_EQ(m.phase, MeasurementPhase::kLost);
  EXPECT_FALSE(m.note.empty());
  EXPECT_FALSE(m.ToRow().ok());
  EXPECT_TRUE(std::isnan(m.ToRow().yaw_deg));
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

TEST(MarkerOptions, CheckNamesTheFlag) {
  MarkerOptions o;
  EXPECT_TRUE(o.Check().ok());
  o.low = 90;
  EXPECT_NE(o.Check().message().find("--low"), std::string::npos);
  o = MarkerOptions();
  o.median_size = 4;
  EXPECT_NE(o.Check().message().find("--median"), std::string::npos);
  o = MarkerOptions();
  o.high = 300;
  EXPECT_NE(o.Check().message().find("--high"), std::string::npos);
  EngineOptions e;
  e.kind = EngineKind::kMarker;
  e.marker.low = 200;
  EXPECT_THROW(Engine::Create(e), std::invalid_argument);
}

}  // namespace
}  // namespace armmimic
