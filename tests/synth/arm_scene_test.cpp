#include "armmimic/synth/arm_scene.h"

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "armmimic/core/angles.h"
#include "test_util.h"

namespace armmimic::synth {
namespace {

ArmSceneOptions Small(ArmMotion motion = ArmMotion::kMixed, uint64_t seed = 7) {
  ArmSceneOptions o;
  o.seed = seed;
  o.background_frames = 3;
  o.standstill_frames = 4;
  o.motion_frames = 120;
  o.noise_sigma = 2;
  o.motion = motion;
  return o;
}

// The moving arm wears the dark blue shirt on the light wall: blue clearly above red.
bool ShirtLike(const cv::Mat& img, cv::Point2d p) {
  const cv::Point q(cvRound(p.x), cvRound(p.y));
  if (!cv::Rect(0, 0, img.cols, img.rows).contains(q)) return false;
  const cv::Vec3b c = img.at<cv::Vec3b>(q);
  return c[0] > c[2] + 30;
}

double Diff(const cv::Mat& a, const cv::Mat& b, cv::Point2d p) {
  const cv::Point q(cvRound(p.x), cvRound(p.y));
  const cv::Vec3b x = a.at<cv::Vec3b>(q), y = b.at<cv::Vec3b>(q);
  return (std::abs(x[0] - y[0]) + std::abs(x[1] - y[1]) + std::abs(x[2] - y[2])) / 3.0;
}

TEST(ArmScene, SameSeedGivesIdenticalFramesInAnyOrder) {
  const ArmSceneRenderer a(Small()), b(Small());
  for (int f : {100, 0, 5, 60}) {
    const cv::Mat x = a.Render(f);
    const cv::Mat y = b.Render(f);
    ASSERT_EQ(x.size(), cv::Size(320, 240));
    ASSERT_EQ(x.type(), CV_8UC3);
    EXPECT_EQ(cv::norm(x, y, cv::NORM_INF), 0) << "frame " << f;
  }
  EXPECT_EQ(cv::norm(a.ArmLengthImage(), b.ArmLengthImage(), cv::NORM_INF), 0);
}

TEST(ArmScene, DifferentSeedGivesDifferentScenes) {
  const ArmSceneRenderer a(Small(ArmMotion::kMixed, 1)), b(Small(ArmMotion::kMixed, 2));
  EXPECT_GT(cv::norm(a.EmptyBackground(), b.EmptyBackground(), cv::NORM_L1) / (320 * 240 * 3), 1.0);
  EXPECT_GT(cv::norm(a.Render(60), b.Render(60), cv::NORM_L1) / (320 * 240 * 3), 1.0);
  // The mixed motion differs too.
  double d = 0;
  for (int f = 7; f < 127; ++f)
    d = std::max(d, std::fabs(a.Truth(f).upper_deg - b.Truth(f).upper_deg));
  EXPECT_GT(d, 10);
}

TEST(ArmScene, BackgroundFramesAreEmptyAndHaveNoAngles) {
  const ArmSceneRenderer r(Small());
  ArmTruth t;
  const cv::Mat f0 = r.Render(0, &t);
  EXPECT_FALSE(t.person);
  EXPECT_TRUE(std::isnan(t.upper_deg));
  EXPECT_TRUE(std::isnan(t.shoulder_px.x));
  EXPECT_FALSE(t.ToRow().HasAngles());
  cv::Mat diff;
  cv::absdiff(f0, r.EmptyBackground(), diff);
  // Only sensor noise (sigma 2) separates a background frame from the empty scene.
  EXPECT_LT(cv::mean(diff)[0], 3.0);
}

TEST(ArmScene, StandstillShowsTheArmHangingAlongItsTruth) {
  const ArmSceneRenderer r(Small());
  const cv::Mat bg = r.EmptyBackground();
  for (int f : {3, 6}) {
    ArmTruth t;
    const cv::Mat img = r.Render(f, &t);
    EXPECT_TRUE(t.person);
    EXPECT_DOUBLE_EQ(t.upper_deg, -90);
    EXPECT_DOUBLE_EQ(t.fore_deg, -90);
    EXPECT_DOUBLE_EQ(t.bend_deg, 0);
    EXPECT_DOUBLE_EQ(t.yaw_deg, 0);
    EXPECT_NEAR(t.shoulder_px.x, t.elbow_px.x, 1e-9);
    EXPECT_NEAR(t.elbow_px.x, t.wrist_px.x, 1e-9);
    EXPECT_GT(t.wrist_px.y, t.elbow_px.y);
    for (double k : {0.3, 0.6, 0.8}) {
      EXPECT_TRUE(ShirtLike(img, t.shoulder_px + (t.elbow_px - t.shoulder_px) * k)) << k;
      EXPECT_TRUE(ShirtLike(img, t.elbow_px + (t.wrist_px - t.elbow_px) * k)) << k;
    }
    // Outside the arm (away from the body) is the wall.
    EXPECT_LT(Diff(img, bg, t.elbow_px + cv::Point2d(14, 0)), 12);
    EXPECT_LT(Diff(img, bg, t.wrist_px + cv::Point2d(14, 0)), 12);
  }
}

// Over the whole motion, the arm is drawn where the truth says it is.
void ExpectArmFollowsTruth(const ArmSceneOptions& o) {
  const ArmSceneRenderer r(o);
  int checked = 0;
  for (int f = o.first_motion_frame(); f < r.frame_count(); f += 3) {
    ArmTruth t;
    const cv::Mat img = r.Render(f, &t);
    ASSERT_TRUE(t.person);
    EXPECT_NEAR(DirectionDeg(t.shoulder_px, t.elbow_px), t.upper_deg, 1e-6) << f;
    EXPECT_NEAR(DirectionDeg(t.elbow_px, t.wrist_px), t.fore_deg, 1e-6) << f;
    EXPECT_NEAR(AngleDiff(t.fore_deg, t.upper_deg), t.bend_deg, 1e-6) << f;
    for (double k : {0.35, 0.6, 0.85}) {
      EXPECT_TRUE(ShirtLike(img, t.shoulder_px + (t.elbow_px - t.shoulder_px) * k))
          << "upper arm, frame " << f << " k " << k;
      EXPECT_TRUE(ShirtLike(img, t.elbow_px + (t.wrist_px - t.elbow_px) * k))
          << "forearm, frame " << f << " k " << k;
    }
    ++checked;
  }
  EXPECT_GT(checked, 30);
}

TEST(ArmScene, RenderedArmLiesAlongTheTruthSegments) {
  ExpectArmFollowsTruth(Small(ArmMotion::kMixed));
  ExpectArmFollowsTruth(Small(ArmMotion::kBend));
}

TEST(ArmScene, LeftSideIsTheMirrorImage) {
  ArmSceneOptions o = Small(ArmMotion::kSwing);
  o.side = ArmSide::kLeft;
  ExpectArmFollowsTruth(o);
  const ArmSceneRenderer r(o);
  EXPECT_LT(r.shoulder_px().x, 160);
  ArmTruth t;
  r.ArmLengthImage(&t);
  EXPECT_DOUBLE_EQ(t.upper_deg, 180);
  EXPECT_LT(t.wrist_px.x, t.shoulder_px.x);
  // Swinging up on the left passes through 180 (pointing left) to 90.
  double max_up = -180;
  for (int f = o.first_motion_frame(); f < r.frame_count(); ++f) {
    const ArmTruth a = r.Truth(f);
    EXPECT_TRUE(a.upper_deg <= -90 + 1e-9 || a.upper_deg >= 90 - 1e-9) << f << " " << a.upper_deg;
    if (a.upper_deg > 0) max_up = std::max(max_up, 180 - a.upper_deg);
  }
  EXPECT_GT(max_up, 80);
}

TEST(ArmScene, ArmLengthImageShowsAStraightHorizontalArm) {
  const ArmSceneRenderer r(Small());
  ArmTruth t;
  const cv::Mat img = r.ArmLengthImage(&t);
  EXPECT_DOUBLE_EQ(t.upper_deg, 0);
  EXPECT_DOUBLE_EQ(t.fore_deg, 0);
  EXPECT_DOUBLE_EQ(t.yaw_deg, 0);
  EXPECT_NEAR(t.wrist_px.x - t.shoulder_px.x, r.upper_length_px() + r.fore_length_px(), 1e-9);
  // The arm beyond the torso, segmented against the empty scene, is a horizontal band.
  cv::Mat diff, grey, mask;
  cv::absdiff(img, r.EmptyBackground(), diff);
  cv::cvtColor(diff, grey, cv::COLOR_BGR2GRAY);
  mask = grey > 40;
  const int x0 = cvRound(t.shoulder_px.x + 12);
  mask(cv::Rect(0, 0, x0, mask.rows)).setTo(0);
  const cv::Moments m = cv::moments(mask, true);
  ASSERT_GT(m.m00, 500);
  const double theta = 0.5 * std::atan2(2 * m.mu11, m.mu20 - m.mu02) * 180 / CV_PI;
  EXPECT_NEAR(theta, 0, 2.0);
  EXPECT_NEAR(m.m01 / m.m00, t.shoulder_px.y, 2.0);
  // The band ends at the hand's tip, a hand's length past the wrist.
  int last = 0;
  const int row = cvRound(t.shoulder_px.y);
  for (int x = x0; x < mask.cols; ++x) {
    if (mask.at<uchar>(row, x)) last = x;
  }
  EXPECT_GT(last, t.wrist_px.x + 5);
  EXPECT_LT(last, t.wrist_px.x + 20);
}

TEST(ArmScene, MotionsCoverTheirRangesSmoothly) {
  struct Case {
    ArmMotion motion;
    double min_upper, max_upper, max_bend, max_yaw;
  };
  for (const Case& c :
       {Case{ArmMotion::kSwing, -90, 85, 0, 0}, Case{ArmMotion::kBend, -90, -15, 145, 0},
        Case{ArmMotion::kYaw, -90, -5, 0, 65}, Case{ArmMotion::kMixed, -90, 20, 60, 0}}) {
    ArmSceneOptions o = Small(c.motion, 11);
    if (c.motion == ArmMotion::kMixed) o.motion_frames = 300;  // several random poses
    const ArmSceneRenderer r(o);
    double hi_upper = -180, hi_bend = 0, hi_yaw = 0;
    ArmTruth prev = r.Truth(o.first_motion_frame() - 1);
    for (int f = o.first_motion_frame(); f < r.frame_count(); ++f) {
      const ArmTruth t = r.Truth(f);
      EXPECT_GE(t.upper_deg, -90 - 1e-9);
      EXPECT_LE(t.upper_deg, 90 + 1e-9);
      EXPECT_GE(t.bend_deg, -1e-9);
      EXPECT_LE(t.bend_deg, 150 + 1e-9);
      EXPECT_GE(t.yaw_deg, 0);
      EXPECT_LE(t.yaw_deg, 70 + 1e-9);
      if (t.yaw_deg > 0) {
        EXPECT_DOUBLE_EQ(t.bend_deg, 0);
      }
      // Human speeds: a few degrees per frame at 30 fps.
      EXPECT_LT(std::fabs(AngleDiff(t.upper_deg, prev.upper_deg)), 8.0) << f;
      EXPECT_LT(std::fabs(t.bend_deg - prev.bend_deg), 8.0) << f;
      EXPECT_LT(std::fabs(t.yaw_deg - prev.yaw_deg), 8.0) << f;
      // The projected segment length is L cos(yaw).
      const double k = std::cos(t.yaw_deg * CV_PI / 180);
      EXPECT_NEAR(cv::norm(t.elbow_px - t.shoulder_px), r.upper_length_px() * k, 1e-6);
      hi_upper = std::max(hi_upper, t.upper_deg);
      hi_bend = std::max(hi_bend, t.bend_deg);
      hi_yaw = std::max(hi_yaw, t.yaw_deg);
      prev = t;
    }
    EXPECT_GE(hi_upper, c.max_upper) << ArmMotionName(c.motion);
    EXPECT_GE(hi_bend, c.max_bend) << ArmMotionName(c.motion);
    EXPECT_GE(hi_yaw, c.max_yaw) << ArmMotionName(c.motion);
  }
}

TEST(ArmScene, YawShortensTheDrawnArm) {
  const ArmSceneOptions o = Small(ArmMotion::kYaw);
  const ArmSceneRenderer r(o);
  int best = o.first_motion_frame();
  for (int f = best; f < r.frame_count(); ++f) {
    if (r.Truth(f).yaw_deg > r.Truth(best).yaw_deg) best = f;
  }
  ArmTruth t;
  const cv::Mat img = r.Render(best, &t);
  ASSERT_GT(t.yaw_deg, 60);
  const double full = r.upper_length_px() + r.fore_length_px();
  const cv::Point2d dir(1, 0);
  EXPECT_TRUE(ShirtLike(img, t.shoulder_px + dir * (0.5 * (t.wrist_px.x - t.shoulder_px.x))));
  // Where the wrist would be at zero yaw there is only wall.
  EXPECT_LT(Diff(img, r.EmptyBackground(), t.shoulder_px + dir * full), 12);
}

TEST(ArmScene, KnobsChangeTheImageAsDescribed) {
  ArmSceneOptions o = Small(ArmMotion::kSwing);
  o.noise_sigma = 0;
  const ArmSceneRenderer plain(o);
  const int f = o.first_motion_frame() + 30;
  const cv::Mat base = plain.Render(f);
  const cv::Mat bg = plain.EmptyBackground();
  ArmTruth t = plain.Truth(f);
  const cv::Point2d mid = (t.elbow_px + t.wrist_px) * 0.5;

  ArmSceneOptions low = o;
  low.clothing_contrast = 0;
  const cv::Mat lo = ArmSceneRenderer(low).Render(f);
  EXPECT_GT(Diff(base, bg, mid), 50);
  EXPECT_LT(Diff(lo, bg, mid), 30);

  ArmSceneOptions drift = o;
  drift.lighting_drift = 0.3;
  const ArmSceneRenderer dr(drift);
  const cv::Rect wall(20, 10, 40, 30);
  const double first = cv::mean(dr.Render(0)(wall))[1];
  const double last = cv::mean(dr.Render(dr.frame_count() - 1)(wall))[1];
  EXPECT_NEAR(last / first, 1.3, 0.03);

  ArmSceneOptions shadow = o;
  shadow.shadow = true;
  const ArmSceneRenderer sh(shadow);
  double darkest = 1;
  for (int g = o.first_motion_frame(); g < sh.frame_count(); g += 10) {
    darkest = std::min(darkest, cv::mean(sh.Render(g))[1] / cv::mean(plain.Render(g))[1]);
  }
  EXPECT_LT(darkest, 0.97);
  EXPECT_EQ(cv::norm(sh.Render(2), plain.Render(2), cv::NORM_INF), 0);  // not before the motion

  ArmSceneOptions head = o;
  head.head_motion = true;
  const ArmSceneRenderer hd(head);
  const cv::Rect head_box(140, 30, 40, 45);
  double moved = 0;
  for (int g = o.first_motion_frame() + 20; g < hd.frame_count(); g += 10) {
    moved =
        std::max(moved, cv::norm(hd.Render(g)(head_box), plain.Render(g)(head_box), cv::NORM_INF));
  }
  EXPECT_GT(moved, 40);
}

TEST(ArmScene, OptionChecksNameTheOption) {
  struct Case {
    void (*edit)(ArmSceneOptions*);
    const char* expect;
  };
  const Case cases[] = {
      {[](ArmSceneOptions* o) {
         o->size = {100, 80};
       },
       "size 100x80"},
      {[](ArmSceneOptions* o) { o->fps = 0; }, "fps"},
      {[](ArmSceneOptions* o) { o->motion_frames = 0; }, "motion frames"},
      {[](ArmSceneOptions* o) { o->background_frames = -1; }, "background frames"},
      {[](ArmSceneOptions* o) { o->noise_sigma = -1; }, "noise"},
      {[](ArmSceneOptions* o) { o->codec = "DIVX"; }, "codec 'DIVX'"},
      {[](ArmSceneOptions* o) { o->clothing_contrast = 3; }, "clothing contrast"},
      {[](ArmSceneOptions* o) { o->lighting_drift = -1; }, "lighting drift"},
  };
  for (const Case& c : cases) {
    ArmSceneOptions o;
    c.edit(&o);
    const Status st = o.Check();
    EXPECT_FALSE(st.ok()) << c.expect;
    EXPECT_NE(st.message().find(c.expect), std::string::npos) << st.message();
    EXPECT_THROW(ArmSceneRenderer{o}, std::invalid_argument);
  }
  EXPECT_TRUE(ArmSceneOptions().Check().ok());
}

TEST(ArmScene, WritesTheSceneFolder) {
  test::TempDir dir;
  ArmSceneOptions o;
  o.size = {160, 120};
  o.background_frames = 2;
  o.standstill_frames = 2;
  o.motion_frames = 12;
  const std::string out = dir.file("scene/nested");
  int calls = 0;
  const Status st = WriteArmScene(o, out, [&](int done, int total) {
    ++calls;
    EXPECT_EQ(total, 16);
  });
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(calls, 16);
  cv::VideoCapture cap(out + "/scene.avi");
  ASSERT_TRUE(cap.isOpened());
  int frames = 0;
  cv::Mat img;
  while (cap.read(img)) {
    EXPECT_EQ(img.size(), cv::Size(160, 120));
    ++frames;
  }
  EXPECT_EQ(frames, 16);
  EXPECT_TRUE(std::filesystem::exists(out + "/armlength.png"));
  EXPECT_TRUE(std::filesystem::exists(out + "/background.png"));
  TruthFile truth;
  ASSERT_TRUE(ReadTruthFile(out + "/truth.tsv", &truth).ok());
  ASSERT_EQ(truth.rows.size(), 16u);
  EXPECT_EQ(truth.Meta("seed"), "1");
  EXPECT_EQ(truth.Meta("motion"), "mixed");
  const ArmSceneRenderer r(o);
  for (const TruthRow& row : truth.rows) {
    const ArmTruth t = r.Truth(row.frame);
    if (std::isnan(t.upper_deg)) {
      EXPECT_TRUE(std::isnan(row.upper_deg));
    } else {
      EXPECT_NEAR(row.upper_deg, t.upper_deg, 1e-3);
      EXPECT_NEAR(row.bend_deg, t.bend_deg, 1e-3);
      EXPECT_NEAR(row.wrist_x, t.wrist_px.x, 1e-2);
    }
  }
  // No temporary is left beside the outputs.
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(out)) {
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
    ++entries;
  }
  EXPECT_EQ(entries, 4);
}

TEST(ArmScene, WriteFailsClearlyForAFileInTheWay) {
  test::TempDir dir;
  test::WriteFile(dir.file("taken"), "x");
  ArmSceneOptions o;
  o.motion_frames = 2;
  const Status st = WriteArmScene(o, dir.file("taken"), {});
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("taken"), std::string::npos) << st.message();
}

}  // namespace
}  // namespace armmimic::synth
