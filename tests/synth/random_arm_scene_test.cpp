// Randomised arm scenes: determinism, the truth against the painted arm, and the tiers' knobs
// staying in the ranges docs/synth.md lists.
#include "armmimic/synth/random_arm_scene.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"

namespace armmimic::synth {
namespace {

RandomArmSceneOptions Opt(uint64_t seed, SceneTier tier, cv::Size size = {320, 240}) {
  RandomArmSceneOptions o;
  o.seed = seed;
  o.tier = tier;
  o.size = size;
  return o;
}

double MaxDiff(const cv::Mat& a, const cv::Mat& b) { return cv::norm(a, b, cv::NORM_INF); }

TEST(RandomArmScene, SameSeedAndTierGiveIdenticalFramesInAnyOrder) {
  const RandomArmScene a(Opt(1234, SceneTier::kHard, {160, 120}));
  const RandomArmScene b(Opt(1234, SceneTier::kHard, {160, 120}));
  const int last = a.frame_count() - 1;
  for (int f : {last, 0, a.first_motion_frame() + 7, 3, a.first_motion_frame() + 7}) {
    const cv::Mat x = a.Render(f);
    const cv::Mat y = b.Render(f);
    ASSERT_EQ(x.size(), cv::Size(160, 120));
    ASSERT_EQ(x.type(), CV_8UC3);
    EXPECT_EQ(MaxDiff(x, y), 0) << "frame " << f;
    const TruthRow ra = a.Truth(f).ToRow(), rb = b.Truth(f).ToRow();
    EXPECT_TRUE(ra.elbow_x == rb.elbow_x || (std::isnan(ra.elbow_x) && std::isnan(rb.elbow_x)));
    EXPECT_TRUE(ra.fore_deg == rb.fore_deg || (std::isnan(ra.fore_deg) && std::isnan(rb.fore_deg)));
  }
  EXPECT_EQ(MaxDiff(a.ArmLengthImage(), b.ArmLengthImage()), 0);
  EXPECT_EQ(MaxDiff(a.EmptyBackground(), b.EmptyBackground()), 0);
  EXPECT_EQ(a.params().Describe(), b.params().Describe());
}

TEST(RandomArmScene, SeedAndTierEachChangeTheWholeScene) {
  const RandomArmScene a(Opt(1000, SceneTier::kMedium, {160, 120}));
  const RandomArmScene b(Opt(1001, SceneTier::kMedium, {160, 120}));
  const RandomArmScene c(Opt(1000, SceneTier::kHard, {160, 120}));
  const double n = 160 * 120 * 3;
  EXPECT_GT(cv::norm(a.EmptyBackground(), b.EmptyBackground(), cv::NORM_L1) / n, 5.0);
  EXPECT_GT(cv::norm(a.EmptyBackground(), c.EmptyBackground(), cv::NORM_L1) / n, 5.0);
  EXPECT_NE(a.params().Describe(), b.params().Describe());
}

TEST(RandomArmScene, ProtocolAndSegmentLengthsHoldInEveryFrame) {
  for (SceneTier tier : {SceneTier::kEasy, SceneTier::kMedium, SceneTier::kHard}) {
    const RandomArmScene r(Opt(1007, tier));
    const int k = r.background_frames(), first = r.first_motion_frame();
    EXPECT_FALSE(r.Truth(k - 1).person);
    EXPECT_FALSE(r.Truth(k - 1).ToRow().HasAngles());
    for (int f = k; f < r.frame_count(); ++f) {
      const ArmTruth t = r.Truth(f);
      ASSERT_TRUE(t.person);
      EXPECT_NEAR(cv::norm(t.elbow_px - t.shoulder_px), r.upper_length_px(), 1e-6) << f;
      EXPECT_NEAR(cv::norm(t.wrist_px - t.elbow_px), r.fore_length_px(), 1e-6) << f;
      EXPECT_NEAR(AngleDiff(t.upper_deg, DirectionDeg(t.shoulder_px, t.elbow_px)), 0, 1e-6) << f;
      EXPECT_NEAR(AngleDiff(t.fore_deg, DirectionDeg(t.elbow_px, t.wrist_px)), 0, 1e-6) << f;
      EXPECT_EQ(t.yaw_deg, 0);
      if (f < first) {  // the standstill: both arms hanging, the body still
        EXPECT_DOUBLE_EQ(t.upper_deg, -90);
        EXPECT_DOUBLE_EQ(t.fore_deg, -90);
        EXPECT_EQ(t.shoulder_px, r.Truth(first).shoulder_px);
      }
    }
    // The arm-length image: the straight arm, horizontal, pointing away from the body.
    ArmTruth t;
    r.ArmLengthImage(&t);
    EXPECT_NEAR(std::fabs(t.upper_deg), r.params().side == ArmSide::kRight ? 0 : 180, 1e-9);
    EXPECT_DOUBLE_EQ(t.upper_deg, t.fore_deg);
  }
}

// The painted arm lies where the truth says: the arm's coverage at the projected middle of each
// segment, and there the frame shows the limb's colour (up to brightness: shading, vignetting,
// shadow and drift scale it).
TEST(RandomArmScene, TheRenderedArmLiesOnItsTruth) {
  int checked = 0;
  for (SceneTier tier : {SceneTier::kEasy, SceneTier::kMedium}) {
    for (uint64_t seed = 1000; seed < 1006; ++seed) {
      const RandomArmScene r(Opt(seed, tier));
      for (int k = 0; k < 4; ++k) {
        const int f = r.first_motion_frame() + (k + 1) * r.motion_frames() / 5;
        ArmTruth t;
        const cv::Mat img = r.Render(f, &t);
        const cv::Mat mask = r.ArmMask(f);
        const double upper = r.upper_length_px(), arm = upper + r.fore_length_px();
        const std::pair<cv::Point2d, double> mids[] = {
            {(t.shoulder_px + t.elbow_px) * 0.5, 0.5 * upper / arm},
            {(t.elbow_px + t.wrist_px) * 0.5, (upper + 0.5 * r.fore_length_px()) / arm}};
        const double hem = r.params().sleeve_cover * upper / arm;
        for (const auto& [p, along] : mids) {
          const cv::Point q(cvRound(p.x), cvRound(p.y));
          EXPECT_GT(mask.at<float>(q), 0.99f) << "seed " << seed << " frame " << f;
          ++checked;
          if (r.params().short_sleeves && std::fabs(along - hem) * arm < 4) continue;  // a hem
          const cv::Scalar seen = cv::mean(img(cv::Rect(q.x - 1, q.y - 1, 3, 3)));
          const cv::Vec3f limb = r.LimbColour(along);
          // Best brightness factor, then what is left over.
          const double dot = seen[0] * limb[0] + seen[1] * limb[1] + seen[2] * limb[2];
          const double k2 =
              std::clamp(dot / std::max(1.0, static_cast<double>(limb.dot(limb))), 0.4, 1.3);
          double residual = 0;
          for (int c = 0; c < 3; ++c) residual += std::pow(seen[c] - k2 * limb[c], 2);
          EXPECT_LT(std::sqrt(residual), 22)
              << "seed " << seed << " frame " << f << ": " << seen << " for " << limb;
        }
      }
    }
  }
  EXPECT_EQ(checked, 96);
}

TEST(RandomArmScene, TheArmMaskIsEmptyBeforeThePersonAndFollowsTheSide) {
  const RandomArmScene r(Opt(1003, SceneTier::kMedium, {160, 120}));
  EXPECT_EQ(cv::countNonZero(r.ArmMask(0)), 0);
  const int f = r.first_motion_frame() + r.motion_frames() / 2;
  const cv::Mat mask = r.ArmMask(f);
  const ArmTruth t = r.Truth(f);
  const cv::Point e(cvRound(t.elbow_px.x), cvRound(t.elbow_px.y));
  EXPECT_GT(mask.at<float>(e), 0.99f);
  EXPECT_THROW(r.ArmMask(r.frame_count()), std::out_of_range);
  EXPECT_THROW(r.Render(-1), std::out_of_range);
}

struct TierRanges {
  std::set<double> fps;
  double arm_lo, arm_hi, noise_lo, noise_hi;
  int quality_lo, quality_hi;
  double drift_abs_lo, drift_abs_hi, sway_hi, speed_limit;
};

// One scene's knobs against its tier's ranges; its arm in the frame and within the speed limit.
void CheckKnobs(const RandomArmScene& r, const TierRanges& want, const std::string& at) {
  const RandomSceneParams& p = r.params();
  EXPECT_EQ(want.fps.count(p.fps), 1u) << at;
  EXPECT_GE(p.arm_fraction, want.arm_lo - 1e-9) << at;
  EXPECT_LE(p.arm_fraction, want.arm_hi + 1e-9) << at;
  EXPECT_NEAR(p.upper_px + p.fore_px, p.arm_fraction * 240, 1e-6) << at;
  EXPECT_GE(p.noise_sigma, want.noise_lo) << at;
  EXPECT_LE(p.noise_sigma, want.noise_hi) << at;
  EXPECT_GE(p.jpeg_quality, want.quality_lo) << at;
  EXPECT_LE(p.jpeg_quality, want.quality_hi) << at;
  EXPECT_GE(std::fabs(p.drift), want.drift_abs_lo) << at;
  EXPECT_LE(std::fabs(p.drift), want.drift_abs_hi) << at;
  EXPECT_LE(p.sway_px, want.sway_hi + 1e-9) << at;
  EXPECT_DOUBLE_EQ(p.speed_limit_deg, want.speed_limit) << at;
  EXPECT_LE(p.max_step_deg, want.speed_limit + 1e-6) << at;
  EXPECT_GE(p.background_frames, 10) << at;
  EXPECT_GE(p.standstill_frames, 15) << at;
  // The moving arm's joints stay in the frame, and every step obeys the speed limit.
  double prev_upper = r.Truth(r.first_motion_frame() - 1).upper_deg;
  double prev_fore = r.Truth(r.first_motion_frame() - 1).fore_deg;
  for (int f = r.first_motion_frame(); f < r.frame_count(); ++f) {
    const ArmTruth t = r.Truth(f);
    for (const cv::Point2d& j : {t.elbow_px, t.wrist_px}) {
      ASSERT_TRUE(j.x >= 0 && j.y >= 0 && j.x < 320 && j.y < 240) << at << " frame " << f;
    }
    EXPECT_LE(std::fabs(AngleDiff(t.upper_deg, prev_upper)), want.speed_limit + 1e-6) << at;
    EXPECT_LE(std::fabs(AngleDiff(t.fore_deg, prev_fore)), want.speed_limit + 1e-6) << at;
    prev_upper = t.upper_deg, prev_fore = t.fore_deg;
  }
}

TEST(RandomArmScene, TierKnobsStayInTheirDocumentedRanges) {
  const std::pair<SceneTier, TierRanges> tiers[] = {
      {SceneTier::kEasy, {{30}, 0.30, 0.40, 1, 2, 90, 95, 0, 0, 0, 4}},
      {SceneTier::kMedium, {{15, 20, 24, 25, 30}, 0.25, 0.50, 2, 4, 60, 85, 0, 0.1, 1, 8}},
      {SceneTier::kHard, {{10, 12, 15}, 0.25, 0.60, 4, 8, 25, 50, 0.15, 0.35, 4, 15}}};
  for (const auto& [tier, want] : tiers) {
    int short_sleeves = 0, camouflaged = 0, by_head = 0, above = 0, across = 0, left = 0;
    int behind = 0, fast = 0;
    double max_offcentre = 0;
    const int n = 40;
    for (uint64_t seed = 1000; seed < 1000 + n; ++seed) {
      const RandomArmScene r(Opt(seed, tier));
      const RandomSceneParams& p = r.params();
      const std::string at = std::string(SceneTierName(tier)) + " seed " + std::to_string(seed);
      CheckKnobs(r, want, at);
      short_sleeves += p.short_sleeves;
      camouflaged += p.camouflage != "none";
      by_head += p.hand_by_head, above += p.hand_above_head, across += p.across_torso;
      left += p.side == ArmSide::kLeft;
      behind += p.furniture_behind_arm;
      fast += p.max_step_deg > 10;
      max_offcentre = std::max(max_offcentre, p.offcentre);
      if (tier == SceneTier::kEasy) {
        EXPECT_FALSE(p.short_sleeves) << at;
        EXPECT_EQ(p.camouflage, "none") << at;
        EXPECT_GE(p.sleeve_wall_distance, 100) << at;
        EXPECT_FALSE(p.shadow) << at;
        EXPECT_LE(p.offcentre, 0.08 + 1e-9) << at;
      }
      if (tier == SceneTier::kHard) {
        EXPECT_NE(p.camouflage, "none") << at;
      }
    }
    const std::string name = SceneTierName(tier);
    EXPECT_GT(left, n / 5) << name;
    EXPECT_LT(left, n - n / 5) << name;
    if (tier != SceneTier::kEasy) {
      // Every failure class the tier promises turns up.
      EXPECT_GT(short_sleeves, n / 5) << name;
      EXPECT_GT(camouflaged, n / 5) << name;
      EXPECT_GT(by_head, n / 10) << name;
      EXPECT_GT(above, 0) << name;
      EXPECT_GT(across, n / 10) << name;
      EXPECT_GT(behind, n / 5) << name;
      EXPECT_GT(max_offcentre, 0.15) << name;
    }
    if (tier == SceneTier::kHard) {
      EXPECT_GT(fast, n / 2) << name;
    }
  }
}

TEST(RandomArmScene, CheckNamesTheSizeAndTiersParse) {
  RandomArmSceneOptions o;
  o.size = {100, 80};
  EXPECT_NE(o.Check().message().find("size 100x80"), std::string::npos);
  o.size = {160, 240};
  EXPECT_NE(o.Check().message().find("size 160x240"), std::string::npos);
  EXPECT_THROW(RandomArmScene{o}, std::invalid_argument);
  o.size = {640, 480};
  EXPECT_TRUE(o.Check().ok());
  SceneTier t = SceneTier::kEasy;
  EXPECT_TRUE(ParseSceneTier("hard", &t));
  EXPECT_EQ(t, SceneTier::kHard);
  EXPECT_FALSE(ParseSceneTier("extreme", &t));
  EXPECT_STREQ(SceneTierName(SceneTier::kMedium), "medium");
}

TEST(RandomArmScene, MetaLineNamesTheSceneAndItsKnobs) {
  const RandomArmScene r(Opt(4243, SceneTier::kEasy, {160, 120}));
  const AngleMeta meta = RandomSceneMeta(r);
  auto value = [&meta](const std::string& key) {
    for (const auto& [k, v] : meta) {
      if (k == key) return v;
    }
    return std::string("(missing)");
  };
  EXPECT_EQ(value("random"), "1");
  EXPECT_EQ(value("tier"), "easy");
  EXPECT_EQ(value("seed"), "4243");
  EXPECT_EQ(value("background_frames"), std::to_string(r.background_frames()));
  EXPECT_EQ(value("motion_frames"), std::to_string(r.motion_frames()));
  EXPECT_EQ(value("sleeves"), "long");
  EXPECT_NE(value("upper_length_px"), "(missing)");
  EXPECT_NE(value("fore_length_px"), "(missing)");
}

TEST(RandomArmScene, JpegRoundTripKeepsSizeAndLosesDetail) {
  const RandomArmScene r(Opt(1010, SceneTier::kHard, {160, 120}));
  const cv::Mat img = r.Render(r.first_motion_frame());
  const cv::Mat q30 = JpegRoundTrip(img, 30), q95 = JpegRoundTrip(img, 95);
  ASSERT_EQ(q30.size(), img.size());
  ASSERT_EQ(q30.type(), CV_8UC3);
  EXPECT_GT(cv::norm(img, q30, cv::NORM_L2), cv::norm(img, q95, cv::NORM_L2));
}

}  // namespace
}  // namespace armmimic::synth
