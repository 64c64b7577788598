// Capsule arm scenes: determinism, the thesis protocol, and the truth against the scene's own
// geometry (the pinhole projection of the 3-D joints, the pixels the ray caster gives the arm).
#include "armmimic/synth/capsule_arm_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"

namespace armmimic::synth {
namespace {

CapsuleArmSceneOptions Opt(uint64_t seed, SceneTier tier, cv::Size size = {160, 120}) {
  CapsuleArmSceneOptions o;
  o.seed = seed;
  o.tier = tier;
  o.size = size;
  return o;
}

double MaxDiff(const cv::Mat& a, const cv::Mat& b) { return cv::norm(a, b, cv::NORM_INF); }

double SegmentPointDistance(cv::Point2d a, cv::Point2d b, cv::Point2d p) {
  const cv::Point2d ab = b - a;
  const double len2 = ab.dot(ab);
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return cv::norm(p - (a + t * ab));
}

TEST(CapsuleArmScene, SameSeedAndTierGiveIdenticalFramesInAnyOrder) {
  const CapsuleArmScene a(Opt(3100, SceneTier::kHard));
  const CapsuleArmScene b(Opt(3100, SceneTier::kHard));
  const int last = a.frame_count() - 1;
  for (int f : {last, 0, a.first_motion_frame() + 9, 50, a.first_motion_frame() + 9}) {
    const cv::Mat x = a.Render(f);
    const cv::Mat y = b.Render(f);
    ASSERT_EQ(x.size(), cv::Size(160, 120));
    ASSERT_EQ(x.type(), CV_8UC3);
    EXPECT_EQ(MaxDiff(x, y), 0) << "frame " << f;
  }
  EXPECT_EQ(MaxDiff(a.ArmLengthImage(), b.ArmLengthImage()), 0);
  EXPECT_EQ(MaxDiff(a.EmptyBackground(), b.EmptyBackground()), 0);
  EXPECT_EQ(a.params().Describe(), b.params().Describe());
  EXPECT_EQ(a.Truth(last).ToRow().wrist_x, b.Truth(last).ToRow().wrist_x);
  // Another seed or tier is another scene.
  const CapsuleArmScene c(Opt(3101, SceneTier::kHard));
  const CapsuleArmScene d(Opt(3100, SceneTier::kMedium));
  const double n = 160 * 120 * 3;
  EXPECT_GT(cv::norm(a.EmptyBackground(), c.EmptyBackground(), cv::NORM_L1) / n, 5.0);
  EXPECT_GT(cv::norm(a.EmptyBackground(), d.EmptyBackground(), cv::NORM_L1) / n, 5.0);
}

TEST(CapsuleArmScene, FollowsTheThesisProtocol) {
  for (SceneTier tier : {SceneTier::kMedium, SceneTier::kHard}) {
    const CapsuleArmScene s(Opt(3102, tier));
    ASSERT_EQ(s.background_frames(), 45);
    ASSERT_EQ(s.standstill_frames(), 60);
    EXPECT_GT(s.motion_frames(), 100);
    EXPECT_FALSE(s.Truth(44).person);
    EXPECT_TRUE(std::isnan(s.Truth(44).upper_deg));
    // The empty frames show the room: the background image up to noise and drift.
    EXPECT_LT(cv::norm(s.Render(10), s.EmptyBackground(), cv::NORM_L1) / (160 * 120 * 3), 12.0);
    // The standstill: the arm hangs, and holds still.
    const ArmTruth first = s.Truth(45), last = s.Truth(104);
    EXPECT_NEAR(first.upper_deg, -90, 15);
    EXPECT_NEAR(first.fore_deg, -90, 20);
    EXPECT_EQ(first.elbow_px, last.elbow_px);
    EXPECT_EQ(first.wrist_px, last.wrist_px);
    // Then the arm moves.
    double moved = 0;
    for (int f = s.first_motion_frame(); f < s.frame_count(); ++f) {
      moved = std::max(moved, std::abs(AngleDiff(s.Truth(f).upper_deg, first.upper_deg)));
    }
    EXPECT_GT(moved, 45) << SceneTierName(tier);
  }
}

TEST(CapsuleArmScene, TruthIsThePinholeProjectionOfTheJoints) {
  const CapsuleArmScene s(Opt(3103, SceneTier::kMedium, {320, 240}));
  const double f = 160 / std::tan(RadFromDeg(s.params().fov_deg) / 2);
  for (int frame = 45; frame < s.frame_count(); frame += 17) {
    const ArmTruth t = s.Truth(frame);
    const CapsuleJoints3d j = s.Joints3d(frame);
    auto pinhole = [&](const cv::Vec3d& p) {
      return cv::Point2d(159.5 + f * p[0] / p[2], 119.5 + f * p[1] / p[2]);
    };
    EXPECT_LT(cv::norm(pinhole(j.shoulder) - t.shoulder_px), 1e-6) << frame;
    EXPECT_LT(cv::norm(pinhole(j.elbow) - t.elbow_px), 1e-6) << frame;
    EXPECT_LT(cv::norm(pinhole(j.wrist) - t.wrist_px), 1e-6) << frame;
    // Segment lengths in 3-D are the person's, whatever the pose.
    EXPECT_NEAR(cv::norm(j.elbow - j.shoulder), s.params().upper, 1e-9);
    EXPECT_NEAR(cv::norm(j.wrist - j.elbow), s.params().fore, 1e-9);
    // yaw: the shoulder-to-wrist chord out of the image plane; the 3-D columns.
    const cv::Vec3d chord = j.wrist - j.shoulder;
    EXPECT_NEAR(t.yaw_deg, DegFromRad(std::asin(std::abs(chord[2]) / cv::norm(chord))), 1e-9);
    const std::array<double, 5> x = s.Extras(frame);
    const cv::Vec3d u = j.elbow - j.shoulder, fa = j.wrist - j.elbow;
    EXPECT_NEAR(x[0], DegFromRad(std::atan2(-u[2], u[0])), 1e-9);
    EXPECT_NEAR(x[3], DegFromRad(std::atan2(-fa[1], std::hypot(fa[0], fa[2]))), 1e-9);
    EXPECT_NEAR(x[4], 180 - DegFromRad(std::acos(u.dot(fa) / (cv::norm(u) * cv::norm(fa)))), 1e-6);
  }
}

TEST(CapsuleArmScene, ArmPixelsLieAlongTheProjectedSegments) {
  for (SceneTier tier : {SceneTier::kMedium, SceneTier::kHard}) {
    const CapsuleArmScene s(Opt(3104, tier));
    const CapsuleSceneParams& p = s.params();
    const double f = 80 / std::tan(RadFromDeg(p.fov_deg) / 2);
    int frames = 0, own_label_mid = 0;
    for (int frame = 45; frame < s.frame_count(); frame += 11) {
      const ArmTruth t = s.Truth(frame);
      const CapsuleJoints3d j = s.Joints3d(frame);
      const cv::Mat labels = s.PartLabels(frame);
      // The perspective image of a limb of radius r at depth z lies within f r / (z - r) of its
      // projected axis, stretched by up to 1/cos of the angle off the optical axis (< 1.4 here).
      auto bound = [&](double r, double z) { return 1.4 * f * r / (z - r) + 0.75; };
      const double b_upper = bound(p.upper_radius, std::min(j.shoulder[2], j.elbow[2]));
      const double b_fore = bound(p.fore_radius, std::min(j.elbow[2], j.wrist[2]));
      int upper_px = 0;
      for (int y = 0; y < labels.rows; ++y) {
        for (int x = 0; x < labels.cols; ++x) {
          const uint8_t l = labels.at<uint8_t>(y, x);
          if (l == kPartUpperArm) {
            ++upper_px;
            ASSERT_LE(SegmentPointDistance(t.shoulder_px, t.elbow_px, {double(x), double(y)}),
                      b_upper)
                << "frame " << frame << " pixel " << x << "," << y;
          } else if (l == kPartForearm) {
            ASSERT_LE(SegmentPointDistance(t.elbow_px, t.wrist_px, {double(x), double(y)}), b_fore)
                << "frame " << frame << " pixel " << x << "," << y;
          }
        }
      }
      // Along the projected segments something of the person is always seen, most often the
      // segment itself.
      for (double a : {0.3, 0.5, 0.7}) {
        const cv::Point2d q = t.shoulder_px + a * (t.elbow_px - t.shoulder_px);
        const cv::Point2d r = t.elbow_px + a * (t.wrist_px - t.elbow_px);
        EXPECT_NE(labels.at<uint8_t>(cvRound(q.y), cvRound(q.x)), kPartRoom) << frame;
        EXPECT_NE(labels.at<uint8_t>(cvRound(r.y), cvRound(r.x)), kPartRoom) << frame;
      }
      const cv::Point2d mid = (t.shoulder_px + t.elbow_px) * 0.5;
      own_label_mid += labels.at<uint8_t>(cvRound(mid.y), cvRound(mid.x)) == kPartUpperArm;
      ++frames;
      EXPECT_GT(upper_px, 0) << frame;
    }
    EXPECT_GE(own_label_mid, frames * 8 / 10) << SceneTierName(tier);
  }
}

TEST(CapsuleArmScene, ThePaintedArmHasTheTruthsDirection) {
  // Where the upper arm is seen long and whole, the axis of its pixels is the truth's direction.
  const CapsuleArmScene s(Opt(3105, SceneTier::kMedium, {320, 240}));
  int checked = 0;
  for (int frame = s.first_motion_frame(); frame < s.frame_count(); frame += 7) {
    const ArmTruth t = s.Truth(frame);
    if (cv::norm(t.elbow_px - t.shoulder_px) < 30 || t.yaw_deg > 20) continue;
    const cv::Mat upper = s.PartLabels(frame) == kPartUpperArm;
    const cv::Moments m = cv::moments(upper, true);
    if (m.m00 < 60) continue;
    const double theta =
        -0.5 * DegFromRad(std::atan2(2 * m.mu11, m.mu20 - m.mu02));  // CCW on screen
    EXPECT_LT(AxisDiff(theta, t.upper_deg), 6.0) << "frame " << frame;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

TEST(CapsuleArmScene, ArmLengthImageShowsTheStraightArmParallelToTheImage) {
  for (uint64_t seed : {3106u, 3107u}) {
    const CapsuleArmScene s(Opt(seed, SceneTier::kHard));
    ArmTruth t;
    const cv::Mat img = s.ArmLengthImage(&t);
    EXPECT_EQ(img.size(), cv::Size(160, 120));
    EXPECT_LT(AxisDiff(t.upper_deg, 0), 2.0);
    EXPECT_NEAR(AngleDiff(t.fore_deg, t.upper_deg), 0, 1e-6);
    EXPECT_LT(t.yaw_deg, 1e-6);
    const double sign = s.params().side == ArmSide::kRight ? 1 : -1;
    EXPECT_GT((t.wrist_px.x - t.shoulder_px.x) * sign, 0);
    EXPECT_NEAR(s.upper_length_px(), cv::norm(t.elbow_px - t.shoulder_px), 1e-9);
    EXPECT_NEAR(s.fore_length_px(), cv::norm(t.wrist_px - t.elbow_px), 1e-9);
  }
}

TEST(CapsuleArmScene, JointsStayInTheFrameAndTiersKeepTheirRanges) {
  for (SceneTier tier : {SceneTier::kMedium, SceneTier::kHard}) {
    for (uint64_t seed = 3110; seed < 3116; ++seed) {
      const CapsuleArmScene s(Opt(seed, tier));
      const CapsuleSceneParams& p = s.params();
      const bool hard = tier == SceneTier::kHard;
      EXPECT_GE(p.noise_sigma, hard ? 4 : 2);
      EXPECT_LE(p.jpeg_quality, hard ? 55 : 85);
      EXPECT_GE(p.jpeg_quality, hard ? 30 : 60);
      EXPECT_LE(std::abs(p.body_yaw_deg), hard ? 20 : 8);
      for (int f = s.background_frames(); f < s.frame_count(); ++f) {
        const ArmTruth t = s.Truth(f);
        for (const cv::Point2d& q : {t.shoulder_px, t.elbow_px, t.wrist_px}) {
          ASSERT_TRUE(q.x >= 0 && q.y >= 0 && q.x <= 159 && q.y <= 119)
              << "seed " << seed << " frame " << f;
        }
      }
    }
  }
}

TEST(CapsuleArmScene, RejectsTheEasyTierAndBadSizes) {
  EXPECT_EQ(Opt(1, SceneTier::kEasy).Check().key(), "arm_scene.tier");
  EXPECT_FALSE(Opt(1, SceneTier::kMedium, {100, 80}).Check().ok());
  EXPECT_FALSE(Opt(1, SceneTier::kMedium, {160, 240}).Check().ok());
  EXPECT_THROW(CapsuleArmScene(Opt(1, SceneTier::kEasy)), std::invalid_argument);
}

}  // namespace
}  // namespace armmimic::synth
