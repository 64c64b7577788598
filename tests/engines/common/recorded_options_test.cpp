#include "armmimic/engines/recorded_options.h"

#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/engines/option_fields.h"

namespace armmimic {
namespace {

AngleFile Header(const std::string& meta_line) {
  std::istringstream in("# armmimic angles v1\n" + meta_line +
                        "\nframe\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\t"
                        "upper_cx\tupper_cy\tfore_cx\tfore_cy\n");
  AngleFile f;
  EXPECT_TRUE(ParseAngleFile(in, "a.tsv", &f).ok());
  return f;
}

TEST(RecordedOptions, EveryChangedParameterComesBack) {
  EngineOptions changed;
  changed.kind = EngineKind::kLk;
  ASSERT_TRUE(SetEngineOption("lk.max_corners=150", &changed).ok());
  ASSERT_TRUE(SetEngineOption("lk.quality_level=0.0123", &changed).ok());
  ASSERT_TRUE(SetEngineOption("lk.thesis_mode=true", &changed).ok());
  AngleMeta meta = {{"engine", "lk"}, {"source", "scene.avi"}, {"start", "12"}, {"mode", "x"}};
  for (auto& kv : ChangedEngineOptions(changed)) meta.push_back(kv);
  AnalysisOptions o;
  std::vector<std::string> skipped;
  ASSERT_TRUE(RecordedAnalysisOptions(Header(FormatMetaLine(meta)), "a.tsv", &o, &skipped).ok());
  EXPECT_TRUE(skipped.empty());
  EXPECT_EQ(o.engine.kind, EngineKind::kLk);
  EXPECT_EQ(o.start, 12);
  EXPECT_EQ(ChangedEngineOptions(o.engine), ChangedEngineOptions(changed));
  EXPECT_EQ(o.engine.lk.max_corners, 150);
  EXPECT_TRUE(o.inputs.empty());
}

TEST(RecordedOptions, UnknownOrRefusedEntriesAreSkippedAndNamed) {
  AnalysisOptions o;
  std::vector<std::string> skipped;
  ASSERT_TRUE(RecordedAnalysisOptions(
                  Header("# engine=bgsub start=x bgsub.threshold=40 bgsub.no_such_key=1 "
                         "bgsub.closing_size=-5"),
                  "a.tsv", &o, &skipped)
                  .ok());
  EXPECT_EQ(o.engine.kind, EngineKind::kBgsub);
  EXPECT_EQ(o.engine.bgsub.threshold, 40);
  EXPECT_EQ(o.start, 0);
  ASSERT_EQ(skipped.size(), 3u);
  EXPECT_NE(skipped[0].find("start=x"), std::string::npos);
  EXPECT_NE(skipped[1].find("no_such_key"), std::string::npos);
  EXPECT_NE(skipped[2].find("closing_size"), std::string::npos);
}

TEST(RecordedOptions, AHeaderWithoutAnEngineIsRefusedByName) {
  AnalysisOptions o;
  const Status st = RecordedAnalysisOptions(Header("# source=x.avi"), "old.tsv", &o, nullptr);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("old.tsv"), std::string::npos) << st.message();
}

}  // namespace
}  // namespace armmimic
