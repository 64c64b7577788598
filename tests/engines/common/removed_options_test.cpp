// The settings this version removed (removed_options.h): no table offers them, setting one is
// refused with what replaced it, and every reader of a recorded run skips them and names them
// once.
#include "armmimic/engines/removed_options.h"

#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/engines/option_fields.h"
#include "armmimic/engines/recorded_options.h"
#include "armmimic/engines/run_record.h"

namespace armmimic {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// "bgsub.reject_shadow" -> "reject_shadow" in BgsubOptionFields()?
bool InATable(const std::string& key) {
  const auto dot = key.find('.');
  const std::string engine = key.substr(0, dot), name = key.substr(dot + 1);
  if (engine == "bgsub") return FindOptionField(BgsubOptionFields(), name) != nullptr;
  if (engine == "lk") return FindOptionField(LkOptionFields(), name) != nullptr;
  if (engine == "marker") return FindOptionField(MarkerOptionFields(), name) != nullptr;
  if (engine == "pose") return FindOptionField(PoseOptionFields(), name) != nullptr;
  ADD_FAILURE() << key << ": no such engine";
  return false;
}

TEST(RemovedOptions, NoTableOffersThemAndEachSaysWhatReplacedIt) {
  ASSERT_FALSE(RemovedEngineOptions().empty());
  for (const RemovedEngineOption& r : RemovedEngineOptions()) {
    SCOPED_TRACE(r.key);
    EXPECT_FALSE(InATable(r.key)) << "a removed key is still in its table";
    EXPECT_EQ(FindRemovedEngineOption(r.key), &r);
    EXPECT_FALSE(std::string(r.replaced_by).empty());
    // Library messages name settings by key, never by a command-line flag.
    EXPECT_FALSE(Contains(r.replaced_by, "--"));
  }
  EXPECT_EQ(FindRemovedEngineOption("bgsub.threshold"), nullptr);
  EXPECT_EQ(FindRemovedEngineOption("reject_shadow"), nullptr);  // keys carry their engine
  const std::string text = DescribeEngineOptions();
  EXPECT_FALSE(Contains(text, "bgsub.reject_shadow="));
  EXPECT_FALSE(Contains(text, "bgsub.background_frames="));
}

TEST(RemovedOptions, SettingOneIsRefusedWithWhatReplacedIt) {
  EngineOptions o;
  const Status st = SetEngineOption("bgsub.reject_shadow=false", &o);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.key(), "bgsub.reject_shadow");
  EXPECT_TRUE(Contains(st.message(), "bgsub.reject_shadow was removed")) << st.message();
  EXPECT_TRUE(Contains(st.message(), "the default path no longer read it")) << st.message();
  EXPECT_TRUE(Contains(st.message(), FindRemovedEngineOption("bgsub.reject_shadow")->replaced_by))
      << st.message();
  EXPECT_FALSE(Contains(st.message(), "is no bgsub parameter")) << st.message();
  // Whatever the value: the key decides.
  EXPECT_FALSE(SetEngineOption("bgsub.bend_hysteresis=banana", &o).ok());
  EXPECT_TRUE(Contains(SetEngineOption("bgsub.bend_hysteresis=banana", &o).message(),
                       "bgsub.bend_hysteresis was removed"));
}

// The header of an angle file written before the removal: the engine's own settings, changed
// ones among them, and removed ones recorded with their old defaults or changed.
AngleMeta OldHeader() {
  return {{"engine", "bgsub"},
          {"source", "scene.avi"},
          {"threshold", "40"},
          {"background_frames", "45"},
          {"bgsub.threshold", "40"},
          {"bgsub.background_frames", "45"},
          {"bgsub.closing_size", "3"},
          {"bgsub.compensate_drift", "true"},
          {"bgsub.reject_shadow", "false"},
          {"bgsub.bend_hysteresis", "0.05"},
          {"bgsub.min_support", "0.45"}};
}

TEST(RemovedOptions, ARecordedRunSkipsThemAndKeepsTheRest) {
  AnalysisOptions o;
  std::vector<std::string> ignored;
  const Status st = RunFromMeta(OldHeader(), "old.tsv", &o, &ignored);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(o.engine.kind, EngineKind::kBgsub);
  EXPECT_EQ(o.engine.bgsub.threshold, 40);
  EXPECT_EQ(o.engine.bgsub.closing_size, 3);
  EXPECT_DOUBLE_EQ(o.engine.bgsub.min_support, 0.45);
  EXPECT_EQ(o.background_frames, 45);  // the run's own background length, which replaced it
  EXPECT_EQ(ignored, (std::vector<std::string>{"bgsub.background_frames", "bgsub.compensate_drift",
                                               "bgsub.reject_shadow", "bgsub.bend_hysteresis"}));
  // Without a list to fill, the run reads the same.
  AnalysisOptions quiet;
  ASSERT_TRUE(RunFromMeta(OldHeader(), "old.tsv", &quiet).ok());
  EXPECT_EQ(EngineOptionValues(quiet.engine), EngineOptionValues(o.engine));
  // A file of this version ignores nothing.
  AngleMeta meta = RunRecordMeta(o);
  meta.emplace_back("engine", "bgsub");
  AnalysisOptions again;
  ASSERT_TRUE(RunFromMeta(meta, "new.tsv", &again, &ignored).ok());
  EXPECT_TRUE(ignored.empty());
}

TEST(RemovedOptions, OpeningAnOldFileNamesThemInOneEntry) {
  AngleMeta meta = OldHeader();
  meta.emplace_back("bgsub.nope", "1");  // unknown, not removed: its own entry as before
  std::istringstream in("# armmimic angles v1\n" + FormatMetaLine(meta) +
                        "\nframe\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\t"
                        "upper_cx\tupper_cy\tfore_cx\tfore_cy\n");
  AngleFile file;
  ASSERT_TRUE(ParseAngleFile(in, "old.tsv", &file).ok());
  AnalysisOptions o;
  std::vector<std::string> skipped;
  ASSERT_TRUE(RecordedAnalysisOptions(file, "old.tsv", &o, &skipped).ok());
  EXPECT_EQ(o.engine.bgsub.closing_size, 3);
  ASSERT_EQ(skipped.size(), 2u);
  EXPECT_TRUE(Contains(skipped[0], "bgsub.nope")) << skipped[0];
  const std::string& line = skipped[1];
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_TRUE(Contains(line, "ignored 4 recorded settings")) << line;
  EXPECT_TRUE(Contains(line, "the default path no longer reads them")) << line;
  for (const char* key : {"bgsub.background_frames", "bgsub.compensate_drift",
                          "bgsub.reject_shadow", "bgsub.bend_hysteresis"}) {
    EXPECT_TRUE(Contains(line, std::string(key) + ": " + FindRemovedEngineOption(key)->replaced_by))
        << key << ": " << line;
  }
}

}  // namespace
}  // namespace armmimic
