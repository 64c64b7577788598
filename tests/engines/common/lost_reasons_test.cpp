// The tally of why rows were lost (armmimic/engines/lost_reasons.h): a note's details in brackets
// and its numbers do not split one reason into many, the most frequent come first, and the rest
// are counted, not dropped.
#include "armmimic/engines/lost_reasons.h"

#include <memory>

#include <gtest/gtest.h>

namespace armmimic {
namespace {

ArmMeasurement Row(MeasurementPhase phase, const std::string& note) {
  ArmMeasurement m;
  m.phase = phase;
  m.note = note;
  return m;
}

TEST(LostReasons, ANotesDetailsAndNumbersDoNotSplitItsReason) {
  EXPECT_EQ(LostReasons::Reason("jump of 150 deg in 0.250 s, faster than an arm turns"),
            "jump of N deg in N s, faster than an arm turns");
  EXPECT_EQ(LostReasons::Reason("evidence too weak (support 0.21)"), "evidence too weak");
  EXPECT_EQ(LostReasons::Reason("re-acquiring (1/3 agreeing frames) (the forearm fits weakly)"),
            "re-acquiring");
  EXPECT_EQ(LostReasons::Reason("turned -40.5 degrees; the rest"), "turned N degrees");
  EXPECT_EQ(LostReasons::Reason("lk: frame 12 of the standstill"), "lk: frame N of the standstill");
  EXPECT_EQ(LostReasons::Reason("marker A3-B"), "marker AN-B") << "a dash inside a word is no sign";
  EXPECT_EQ(LostReasons::Reason(""), "no reason given");
}

TEST(LostReasons, TheMostFrequentComeFirstAndTheRestAreCounted) {
  LostReasons reasons;
  for (int i = 0; i < 5; ++i) reasons.Add(Row(MeasurementPhase::kLost, "no arm"));
  for (int i = 0; i < 3; ++i) {
    reasons.Add(
        Row(MeasurementPhase::kLost, "evidence too weak (support 0." + std::to_string(i) + ")"));
  }
  reasons.Add(Row(MeasurementPhase::kLost, "a"));
  reasons.Add(Row(MeasurementPhase::kLost, "b"));
  reasons.Add(Row(MeasurementPhase::kOk, "both segments fit"));
  reasons.Add(Row(MeasurementPhase::kSetup, "standstill 3/60"));
  EXPECT_EQ(reasons.lost(), 10);
  EXPECT_EQ(reasons.Text(2), "no arm (5); evidence too weak (3); 2 other reasons (2)");
  EXPECT_EQ(reasons.Text(3), "no arm (5); evidence too weak (3); a (1); 1 other reason (1)");
  EXPECT_EQ(reasons.Text(10), "no arm (5); evidence too weak (3); a (1); b (1)");
  EXPECT_EQ(LostReasons().Text(3), "");
}

TEST(LostReasons, EachArmsLostRowCounts) {
  ArmMeasurement left = Row(MeasurementPhase::kLost, "the elbow is not seen");
  left.right_arm =
      std::make_shared<ArmMeasurement>(Row(MeasurementPhase::kLost, "the wrist is not seen"));
  LostReasons reasons;
  reasons.Add(left);
  EXPECT_EQ(reasons.lost(), 2);
  EXPECT_EQ(reasons.Text(3), "the elbow is not seen (1); the wrist is not seen (1)");
}

}  // namespace
}  // namespace armmimic
