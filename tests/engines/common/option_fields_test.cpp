// The engines' parameter tables (option_fields.h) against their structs: every member listed
// once, the documented defaults equal the struct's, every range end passes Check(), and a value
// just outside a range is refused by Check() with the row's key.
#include "armmimic/engines/option_fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

namespace armmimic {
namespace {

// Counts an aggregate's members: the largest N for which T{AnyValue x N} is well-formed.
struct AnyValue {
  template <typename T>
  operator T() const;  // NOLINT: declared only, used in unevaluated contexts
};

template <typename T, typename Seq, typename = void>
struct BracesWork : std::false_type {};
template <typename T, std::size_t... I>
struct BracesWork<T, std::index_sequence<I...>,
                  std::void_t<decltype(T{(static_cast<void>(I), AnyValue{})...})>>
    : std::true_type {};

template <typename T, std::size_t N = 0>
constexpr std::size_t MemberCount() {
  if constexpr (BracesWork<T, std::make_index_sequence<N + 1>>::value) {
    return MemberCount<T, N + 1>();
  } else {
    return N;
  }
}

// A value of `f` other than `v`, inside its range.
template <typename O>
double OtherValue(const OptionField<O>& f, double v) {
  if (f.kind == OptionKind::kBool) return v != 0 ? 0 : 1;
  return v != f.max ? f.max : f.min;
}

template <typename O>
void CheckTable(const std::vector<OptionField<O>>& fields, const char* name) {
  SCOPED_TRACE(name);
  const O defaults;
  ASSERT_TRUE(defaults.Check().ok()) << defaults.Check().message();
  // Every member once: as many rows as members, and each row writes a member no other reads.
  EXPECT_EQ(fields.size(), MemberCount<O>())
      << "a member of the options struct has no row in src/engines/common/option_fields.cpp";
  std::set<std::string> keys;
  for (const auto& f : fields) {
    SCOPED_TRACE(f.key);
    EXPECT_TRUE(keys.insert(f.key).second) << "duplicate key";
    EXPECT_FALSE(f.label.empty());
    EXPECT_FALSE(f.help.empty());
    ASSERT_TRUE(f.get && f.set);
    EXPECT_DOUBLE_EQ(f.get(defaults), f.default_value) << "the table's default is not the struct's";
    EXPECT_LE(f.min, f.default_value);
    EXPECT_GE(f.max, f.default_value);
    EXPECT_LT(f.min, f.max);
    if (f.kind == OptionKind::kEnum) {
      EXPECT_EQ(f.choices.size(), static_cast<std::size_t>(f.max) + 1);
    }
    O changed;
    const double v = OtherValue(f, f.get(defaults));
    f.set(changed, v);
    EXPECT_DOUBLE_EQ(f.get(changed), v);
    for (const auto& g : fields) {
      if (&g != &f) {
        EXPECT_DOUBLE_EQ(g.get(changed), g.get(defaults)) << "also changed " << g.key;
      }
    }
  }
  // Both ends of every range pass Check(), with the fields it must stay below (or above) moved
  // to the far end of their own ranges.
  for (const auto& f : fields) {
    for (const double end : {f.min, f.max}) {
      SCOPED_TRACE(f.key + " = " + std::to_string(end));
      O o;
      f.set(o, end);
      if (!f.below.empty()) {
        const OptionField<O>* upper = FindOptionField(fields, f.below);
        ASSERT_NE(upper, nullptr) << "unknown key " << f.below;
        upper->set(o, upper->max);
      }
      for (const auto& g : fields) {
        if (g.below == f.key) g.set(o, g.min);
      }
      const Status st = o.Check();
      EXPECT_TRUE(st.ok()) << st.message();
    }
  }
}

// Check() is the table: a value just outside either end of a row's range is refused, keyed by
// that row ("<table>.<key>"), and the message says what the setting must be.
template <typename O>
void CheckRefusesOutsideEachRange(const std::vector<OptionField<O>>& fields, const char* table) {
  SCOPED_TRACE(table);
  ASSERT_TRUE(O().Check().ok()) << O().Check().message();
  int refused = 0;
  for (const auto& f : fields) {
    if (f.kind != OptionKind::kInt && f.kind != OptionKind::kDouble) continue;
    const bool whole = f.kind == OptionKind::kInt;
    std::vector<double> outside = {f.min_exclusive ? f.min
                                   : whole         ? f.min - 1
                                                   : std::nextafter(f.min, -HUGE_VAL)};
    if (!std::isinf(f.max)) outside.push_back(whole ? f.max + 1 : std::nextafter(f.max, HUGE_VAL));
    if (!whole) outside.push_back(std::nan(""));
    for (const double v : outside) {
      SCOPED_TRACE(f.key + " = " + std::to_string(v));
      O o;
      f.set(o, v);
      const Status st = o.Check();
      ASSERT_FALSE(st.ok());
      EXPECT_EQ(st.key(), std::string(table) + "." + f.key);
      // The refused value is repeated: "<noun> is <value>[ unit]; it must be ...".
      EXPECT_EQ(st.message().rfind(
                    OptionNoun(f.label) + " is " + OptionRefusedText(f, v) + "; it must be ", 0),
                0u)
          << st.message();
      ++refused;
    }
  }
  EXPECT_GT(refused, 0);
}

TEST(OptionFieldsTest, ChecksRefuseAValueOutsideEachRangeWithItsKey) {
  CheckRefusesOutsideEachRange(BgsubOptionFields(), "bgsub");
  CheckRefusesOutsideEachRange(LkOptionFields(), "lk");
  CheckRefusesOutsideEachRange(MarkerOptionFields(), "marker");
  CheckRefusesOutsideEachRange(PoseOptionFields(), "pose");
  EngineOptions e;
  for (const EngineKind kind : AllEngineKinds()) {
    e.kind = kind;
    EXPECT_TRUE(e.Check().ok()) << EngineName(kind);
  }
  e.kind = EngineKind::kLk;
  e.lk.max_corners = 3;
  EXPECT_EQ(e.Check().key(), "lk.max_corners");
}

TEST(OptionFieldsTest, ChecksKeepTheRulesNoRangeSays) {
  LkOptions lk;
  lk.window_px = 16;  // in [5, 101], but even
  EXPECT_EQ(lk.Check().key(), "lk.window_px");
  EXPECT_NE(lk.Check().message().find("odd"), std::string::npos) << lk.Check().message();
  MarkerOptions marker;
  marker.median_size = 4;
  EXPECT_EQ(marker.Check().key(), "marker.median_size");
  EXPECT_EQ(marker.Check().message(), "median window is 4; it must be odd");
  PoseOptions pose;
  pose.arm_crop = 0.5;  // in [0, 4], but neither 0 (one look) nor a look of at least 1
  EXPECT_EQ(pose.Check().key(), "pose.arm_crop");
  EXPECT_EQ(pose.Check().message(), "arm look size is 0.5; it must be 0 (one look) or in [1, 4]");
  pose.arm_crop = 0;
  EXPECT_TRUE(pose.Check().ok());
}

TEST(OptionFieldsTest, BgsubTableMatchesItsStruct) {
  CheckTable(BgsubOptionFields(), "BgsubOptions");
}

TEST(OptionFieldsTest, LkTableMatchesItsStruct) { CheckTable(LkOptionFields(), "LkOptions"); }

TEST(OptionFieldsTest, MarkerTableMatchesItsStruct) {
  CheckTable(MarkerOptionFields(), "MarkerOptions");
}

TEST(OptionFieldsTest, PoseTableMatchesItsStruct) { CheckTable(PoseOptionFields(), "PoseOptions"); }

TEST(OptionFieldsTest, ChecksRefuseWhatTheRelationsForbid) {
  // The relations the tables declare are the ones Check() enforces.
  MarkerOptions m;
  FindOptionField(MarkerOptionFields(), "low")->set(m, 90);  // above high = 80
  EXPECT_EQ(m.Check().key(), "marker.low");  // the lower bound people set: its own key
  EXPECT_EQ(m.Check().message(), "low threshold 90 is above the high threshold 80");
  m = MarkerOptions();
  m.min_area = 300;  // above max_area = 200
  EXPECT_EQ(m.Check().key(), "marker.max_area");
  EXPECT_EQ(m.Check().message(), "max. area is 200; it must not be below the min. area 300");
  m = MarkerOptions();
  m.max_aspect = 0.1;  // below min_aspect = 0.2
  EXPECT_EQ(m.Check().key(), "marker.max_aspect");
}

TEST(OptionFieldsTest, IntFieldsRoundAndEnumsTakeTheChoiceIndex) {
  LkOptions o;
  FindOptionField(LkOptionFields(), "max_corners")->set(o, 41.6);
  EXPECT_EQ(o.max_corners, 42);
  const auto* side = FindOptionField(LkOptionFields(), "side");
  ASSERT_NE(side, nullptr);
  side->set(o, 2);
  EXPECT_EQ(o.side, LkArmSide::kRight);
  EXPECT_EQ(side->choices[2], LkArmSideName(LkArmSide::kRight));
}

TEST(OptionFieldsTest, SetEngineOptionTakesTableKeysAndRefusesWithAReason) {
  EngineOptions o;
  ASSERT_TRUE(SetEngineOption("lk.max_corners=200", &o).ok());
  EXPECT_EQ(o.lk.max_corners, 200);
  ASSERT_TRUE(SetEngineOption("bgsub.thesis_mode=on", &o).ok());
  EXPECT_TRUE(o.bgsub.thesis_mode);
  ASSERT_TRUE(SetEngineOption("lk.side=left", &o).ok());
  EXPECT_EQ(o.lk.side, LkArmSide::kLeft);
  ASSERT_TRUE(SetEngineOption("marker.min_fill=0.55", &o).ok());
  EXPECT_DOUBLE_EQ(o.marker.min_fill, 0.55);
  const struct {
    const char* assignment;
    const char* says;
  } bad[] = {
      {"lk.max_corners=2.5", "whole number in [4, 10000]"},
      {"lk.max_corners=3", "[4, 10000]"},
      {"lk.side=up", "one of auto, left, right"},
      {"bgsub.thesis_mode=maybe", "true or false"},
      {"marker.min_fill=1,5", "a number in [0, 1]"},
      {"lk.nope=1", "'lk.nope' is no lk parameter"},
      {"arm.threshold=4", "unknown engine 'arm'"},
      {"threshold=45", "ENGINE.KEY=VALUE"},
  };
  for (const auto& b : bad) {
    const EngineOptions before = o;
    const Status st = SetEngineOption(b.assignment, &o);
    ASSERT_FALSE(st.ok()) << b.assignment;
    EXPECT_NE(st.message().find(b.says), std::string::npos) << st.message();
    EXPECT_EQ(o.lk.max_corners, before.lk.max_corners);
  }
}

TEST(OptionFieldsTest, DescribeListsEveryKeyWithItsDefault) {
  const std::string text = DescribeEngineOptions();
  for (const auto& f : LkOptionFields()) {
    EXPECT_NE(text.find("lk." + f.key + "="), std::string::npos) << f.key;
  }
  for (const auto& f : MarkerOptionFields()) {
    EXPECT_NE(text.find("marker." + f.key + "="), std::string::npos) << f.key;
  }
  EXPECT_NE(text.find("bgsub.threshold=45 "), std::string::npos);
  EXPECT_TRUE(text.find("bgsub.straight_ratio=0.3 ") != std::string::npos ||
              text.find("bgsub.straight_ratio=0.3\n") != std::string::npos);
  EXPECT_NE(text.find("lk.side=auto "), std::string::npos);
  for (std::size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos;
       start = end + 1) {
    EXPECT_LE(end - start, 78u) << text.substr(start, end - start);
  }
}

}  // namespace
}  // namespace armmimic
