// The bgsub engine on frames drawn with known geometry: a flat wall, a dark body with a head, and
// an arm drawn as thick segments from a known shoulder. Checks the phases, the angle conventions,
// the bent/straight decision, ROI and fixed-shoulder handling, and the thesis path.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"

namespace armmimic {
namespace {

const cv::Size kSize(320, 240);
const cv::Point2d kShoulder(190, 100);
constexpr double kUpper = 44, kFore = 50;

cv::Mat Wall() {
  cv::Mat img(kSize, CV_8UC3, cv::Scalar(190, 200, 205));
  cv::RNG rng(7);
  cv::Mat noise(kSize, CV_8UC3);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 6);
  img += noise;
  return img;
}

// The standing figure: its torso's width, and where its moving arm hangs in the standstill.
struct Figure {
  int torso_width = 57;  // from x = 125: up to the moving arm
  double rest_deg = -90;
};

// The person with the moving arm at directions upper/fore (degrees, contract convention).
cv::Mat Person(double upper_deg, double fore_deg, const Figure& figure = {}) {
  cv::Mat img = Wall();
  const cv::Scalar shirt(140, 60, 30), skin(120, 150, 200);
  cv::rectangle(img, cv::Rect(125, 90, figure.torso_width, 150), shirt, cv::FILLED);
  cv::circle(img, cv::Point(155, 62), 16, skin, cv::FILLED);          // head
  cv::line(img, cv::Point(125, 98), cv::Point(122, 190), shirt, 14);  // the other arm, hanging
  const cv::Point2d e = kShoulder + DirectionVector(upper_deg) * kUpper;
  const cv::Point2d w = e + DirectionVector(fore_deg) * kFore;
  cv::line(img, kShoulder, e, shirt, 13);
  cv::line(img, e, w, shirt, 11);
  return img;
}

struct EngineRun {
  std::unique_ptr<Engine> engine;
  int index = 0;
};

EngineRun Start(const BgsubOptions& bo, const EngineContext& base = {}, const Figure& figure = {}) {
  EngineContext ctx = base;
  ctx.frame_size = kSize;
  ctx.background = Wall();
  ctx.arm_length = Person(0, 0, figure);
  EngineOptions eo;
  eo.kind = EngineKind::kBgsub;
  eo.bgsub = bo;
  EngineRun r{Engine::Create(eo), 0};
  EXPECT_TRUE(r.engine->Begin(ctx).ok());
  for (int i = 0; i < bo.standstill_frames; ++i) {
    Frame f;
    f.image = Person(figure.rest_deg, figure.rest_deg, figure);
    f.index = r.index++;
    EXPECT_EQ(r.engine->Process(f).phase, MeasurementPhase::kSetup);
  }
  return r;
}

ArmMeasurement Next(EngineRun* r, double upper, double fore, const Figure& figure = {}) {
  Frame f;
  f.image = Person(upper, fore, figure);
  f.index = r->index++;
  return r->engine->Process(f);
}

BgsubOptions Short() {
  BgsubOptions o;
  o.standstill_frames = 5;
  return o;
}

TEST(BgsubEngine, StraightArmDirectionsFollowTheContract) {
  EngineRun r = Start(Short());
  for (double deg : {-45.0, 0.0, 30.0, 60.0, 90.0}) {
    const ArmMeasurement m = Next(&r, deg, deg);
    ASSERT_EQ(m.phase, MeasurementPhase::kOk) << deg << ": " << m.note;
    EXPECT_NEAR(AngleDiff(m.upper_deg, deg), 0, 3) << m.note;
    EXPECT_NEAR(AngleDiff(m.fore_deg, deg), 0, 3) << m.note;
    EXPECT_FALSE(m.bent) << deg;
    EXPECT_NEAR(m.bend_deg, 0, 4) << deg;
    EXPECT_GE(m.yaw_deg, 0);
    EXPECT_LT(m.yaw_deg, 25) << deg;  // in-plane arm: small yaw
    ASSERT_TRUE(m.shoulder_px.has_value());
    // Drawn arms have no deltoid over the joint, so the arm-length image shows the arm from
    // just past the joint: the derived shoulder sits up to an arm radius inwards.
    EXPECT_NEAR(m.shoulder_px->x, kShoulder.x, 7);
    EXPECT_NEAR(m.shoulder_px->y, kShoulder.y, 3);
    ASSERT_TRUE(m.wrist_px.has_value());
    const cv::Point2d w = kShoulder + DirectionVector(deg) * (kUpper + kFore);
    EXPECT_LT(cv::norm(*m.wrist_px - w), 12) << deg;
    EXPECT_GT(m.confidence, 0.5) << deg;
  }
}

TEST(BgsubEngine, BentArmSplitsAtTheElbow) {
  EngineRun r = Start(Short());
  const struct { double upper, fore; } poses[] = {{0, 90}, {-30, 60}, {20, 140}, {45, -45}};
  for (const auto& p : poses) {
    const ArmMeasurement m = Next(&r, p.upper, p.fore);
    ASSERT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
    EXPECT_TRUE(m.bent) << p.upper << "," << p.fore << ": " << m.note;
    EXPECT_NEAR(AngleDiff(m.upper_deg, p.upper), 0, 7) << m.note;
    EXPECT_NEAR(AngleDiff(m.fore_deg, p.fore), 0, 7) << m.note;
    EXPECT_NEAR(m.bend_deg, AngleDiff(p.fore, p.upper), 10);
    EXPECT_TRUE(std::isnan(m.yaw_deg));
    ASSERT_TRUE(m.elbow_px.has_value());
    const cv::Point2d e = kShoulder + DirectionVector(p.upper) * kUpper;
    EXPECT_LT(cv::norm(*m.elbow_px - e), 8);
  }
}

// An arm that hangs 12 degrees out from straight down, clear of a narrower torso: its outer edge
// is 3-6 px further out on the rows below the shoulder that the calibration reads, so the edge,
// one radius in, would put the shoulder there. Both its edges show, and the axis between them,
// read as a line at the shoulder's row, puts it at the joint.
TEST(BgsubEngine, AnArmHangingOutClearOfTheBodyGivesTheShoulderFromBothEdges) {
  Figure leaning;
  leaning.torso_width = 50;
  leaning.rest_deg = -78;
  EngineRun r = Start(Short(), {}, leaning);
  for (double deg : {0.0, 30.0, -45.0}) {
    const ArmMeasurement m = Next(&r, deg, deg, leaning);
    ASSERT_EQ(m.phase, MeasurementPhase::kOk) << deg << ": " << m.note;
    ASSERT_TRUE(m.shoulder_px.has_value());
    EXPECT_NEAR(m.shoulder_px->x, kShoulder.x, 1.5);
    EXPECT_NEAR(AngleDiff(m.upper_deg, deg), 0, 3) << m.note;
  }
}

TEST(BgsubEngine, ThesisPathMeasuresAStraightAndABentArm) {
  BgsubOptions o = Short();
  o.thesis_mode = true;
  EngineRun r = Start(o);
  const ArmMeasurement s = Next(&r, 0, 0);
  ASSERT_EQ(s.phase, MeasurementPhase::kOk) << s.note;
  EXPECT_NEAR(AngleDiff(s.upper_deg, 0), 0, 3);
  const ArmMeasurement b = Next(&r, 0, 90);
  ASSERT_EQ(b.phase, MeasurementPhase::kOk) << b.note;
  EXPECT_TRUE(b.bent);
  EXPECT_NEAR(AngleDiff(b.upper_deg, 0), 0, 6);
  EXPECT_NEAR(AngleDiff(b.fore_deg, 90), 0, 6);
}

TEST(BgsubEngine, UnmovedArmIsTheRestPoseOrLostOnTheThesisPath) {
  EngineRun improved = Start(Short());
  const ArmMeasurement m = Next(&improved, -90, -90);
  EXPECT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
  EXPECT_NEAR(m.upper_deg, -90, 2);
  BgsubOptions o = Short();
  o.thesis_mode = true;
  EngineRun thesis = Start(o);
  EXPECT_EQ(Next(&thesis, -90, -90).phase, MeasurementPhase::kLost);
}

TEST(BgsubEngine, RoiAndFixedShoulderKeepFullImagePixels) {
  EngineContext ctx;
  ctx.roi = cv::Rect(100, 10, 220, 220);
  ctx.shoulder_px = kShoulder;
  EngineRun r = Start(Short(), ctx);
  const ArmMeasurement m = Next(&r, 30, 30);
  ASSERT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
  EXPECT_NEAR(AngleDiff(m.upper_deg, 30), 0, 3);
  ASSERT_TRUE(m.shoulder_px.has_value());
  EXPECT_NEAR(m.shoulder_px->x, kShoulder.x, 1e-9);
  const cv::Point2d mid = kShoulder + DirectionVector(30) * (kUpper / 2);
  EXPECT_LT(cv::norm(m.upper_com_px - mid), 10);
}

// A person near the image's right edge whose arm reaches left, past the image's centre, and a
// floor edge that differs from the empty room by a thin line across the whole width (drawn a
// little differently, as a drift of the light or a compression can). The line must not join the
// room to the body: the body's centre would move to the image's centre, the arm (its centroid
// right of that) would be taken for one reaching right, and the shoulder searched past the body.
cv::Mat RightPerson(double upper_deg, double fore_deg, bool floor_line) {
  cv::Mat img = Wall();
  const cv::Scalar shirt(140, 60, 30), skin(120, 150, 200);
  const cv::Point2d shoulder(236, 100);
  cv::rectangle(img, cv::Rect(243, 90, 57, 150), shirt, cv::FILLED);
  cv::circle(img, cv::Point(271, 62), 16, skin, cv::FILLED);
  cv::line(img, cv::Point(300, 98), cv::Point(303, 190), shirt, 14);
  const cv::Point2d e = shoulder + DirectionVector(upper_deg) * kUpper;
  cv::line(img, shoulder, e, shirt, 13);
  cv::line(img, e, e + DirectionVector(fore_deg) * kFore, shirt, 11);
  if (floor_line) cv::line(img, cv::Point(0, 210), cv::Point(kSize.width - 1, 210), shirt, 1);
  return img;
}

TEST(BgsubEngine, AThinLineAcrossTheRoomIsNoBody) {
  EngineContext ctx;
  ctx.frame_size = kSize;
  ctx.background = Wall();
  ctx.arm_length = RightPerson(180, 180, true);
  EngineOptions eo;
  eo.bgsub = Short();
  auto engine = Engine::Create(eo);
  ASSERT_TRUE(engine->Begin(ctx).ok());
  int index = 0;
  for (int i = 0; i < eo.bgsub.standstill_frames; ++i) {
    Frame f;
    f.image = RightPerson(-90, -90, true);
    f.index = index++;
    ASSERT_EQ(engine->Process(f).phase, MeasurementPhase::kSetup);
  }
  for (double deg : {180.0, 150.0, -150.0}) {
    Frame f;
    f.image = RightPerson(deg, deg, true);
    f.index = index++;
    const ArmMeasurement m = engine->Process(f);
    ASSERT_EQ(m.phase, MeasurementPhase::kOk) << deg << ": " << m.note;
    EXPECT_NEAR(AngleDiff(m.upper_deg, deg), 0, 3) << m.note;
    EXPECT_NEAR(AngleDiff(m.fore_deg, deg), 0, 3) << m.note;
    ASSERT_TRUE(m.shoulder_px.has_value());
    EXPECT_NEAR(m.shoulder_px->x, 236, 7);
  }
}

TEST(BgsubEngine, BeginNamesTheBadImage) {
  EngineOptions eo;
  auto engine = Engine::Create(eo);
  EngineContext ctx;
  ctx.frame_size = kSize;
  ctx.background = Wall();
  Status st = engine->Begin(ctx);
  EXPECT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "analysis.arm_length") << st.message();
  ctx.arm_length = cv::Mat(10, 10, CV_8UC3, cv::Scalar::all(0));
  st = engine->Begin(ctx);
  EXPECT_FALSE(st.ok());
  EXPECT_NE(st.message().find("10x10"), std::string::npos) << st.message();
}

TEST(BgsubEngine, OptionsCheckNamesTheSetting) {
  BgsubOptions o;
  EXPECT_TRUE(o.Check().ok());
  o.threshold = 0;
  EXPECT_EQ(o.Check().key(), "bgsub.threshold");
  o = BgsubOptions();
  o.standstill_frames = 0;
  EXPECT_EQ(o.Check().key(), "bgsub.standstill_frames");
  EngineOptions eo;
  auto engine = Engine::Create(eo);
  bool has_threshold = false;
  for (const auto& kv : engine->Describe()) has_threshold |= kv.first == "threshold";
  EXPECT_TRUE(has_threshold);
}

}  // namespace
}  // namespace armmimic
