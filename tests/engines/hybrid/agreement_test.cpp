// When the tracker's and the background difference's rows bear each other out
// (hybrid/agreement.h): within the bound plus a short segment's pixel uncertainty, not beyond
// it, across the +-180 seam, and never without both directions.
#include "hybrid/agreement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace armmimic::internal {
namespace {

// A row with the given directions and, when `upper_px` > 0, joints that give its segments those
// lengths.
ArmMeasurement Row(double upper_deg, double fore_deg, double upper_px = 0, double fore_px = 0) {
  ArmMeasurement m;
  m.phase = MeasurementPhase::kOk;
  m.upper_deg = upper_deg;
  m.fore_deg = fore_deg;
  if (upper_px > 0) {
    const double u = upper_deg * M_PI / 180, f = fore_deg * M_PI / 180;
    m.shoulder_px = cv::Point2d(100, 100);
    m.elbow_px = *m.shoulder_px + upper_px * cv::Point2d(std::cos(u), -std::sin(u));
    m.wrist_px = *m.elbow_px + fore_px * cv::Point2d(std::cos(f), -std::sin(f));
  }
  return m;
}

TEST(HybridAgreement, TheBoundGrowsForAShortSegment) {
  HybridOptions o;  // 12 degrees, 2 px
  EXPECT_DOUBLE_EQ(AllowedDisagreementDeg(0, o), 12);
  EXPECT_NEAR(AllowedDisagreementDeg(40, o), 12 + std::atan(4.0 / 40) * 180 / M_PI, 1e-9);
  EXPECT_GT(AllowedDisagreementDeg(10, o), AllowedDisagreementDeg(80, o));
}

TEST(HybridAgreement, RowsWithinTheBoundAgree) {
  EXPECT_EQ(Disagreement(Row(-90, -60, 50, 45), Row(-84, -52), HybridOptions()), "");
}

TEST(HybridAgreement, AForearmBeyondTheBoundDoesNot) {
  // 50 px forearm: allowed 12 + atan(4/50) = 16.6 degrees; 20 apart.
  const std::string why = Disagreement(Row(-90, -60, 50, 50), Row(-90, -40), HybridOptions());
  EXPECT_NE(why.find("forearm by 20.0 degrees"), std::string::npos) << why;
}

TEST(HybridAgreement, DirectionsAcrossTheSeamAreCloseNotFarApart) {
  EXPECT_EQ(Disagreement(Row(178, -176, 50, 50), Row(-178, 179), HybridOptions()), "");
}

// A pose lk withheld because a rival 20 degrees off explains its evidence as well: decided only
// by a measurement nearer to it than halfway to the rival (10 degrees), though 12 would do
// otherwise.
TEST(HybridAgreement, AnUndecidedPoseNeedsTheOpinionNearerThanHalfwayToItsRival) {
  const ArmMeasurement lk = Row(-90, -60, 50, 50);
  EXPECT_EQ(DisagreementWithRival(lk, Row(-88, -52), HybridOptions(), 20), "");
  const std::string why = DisagreementWithRival(lk, Row(-88, -49), HybridOptions(), 20);
  EXPECT_NE(why.find("forearm by 11.0 degrees (allowed 10.0)"), std::string::npos) << why;
  EXPECT_EQ(Disagreement(lk, Row(-88, -49), HybridOptions()), "");
}

TEST(HybridAgreement, AMissingDirectionIsNoAgreement) {
  const std::string why = Disagreement(Row(-90, kNaN), Row(-90, -90), HybridOptions());
  EXPECT_NE(why.find("no forearm direction"), std::string::npos) << why;
}

}  // namespace
}  // namespace armmimic::internal
