// The run an angle file's header records (run_record.h): every engine setting and input image
// is written, and reading it back gives the same options.
#include "armmimic/engines/run_record.h"

#include <filesystem>
#include <memory>
#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/engines/engine.h"
#include "armmimic/engines/option_fields.h"
#include "armmimic/synth/marker_rig.h"

namespace armmimic {
namespace {

std::string Value(const AngleMeta& meta, const std::string& key) {
  return MetaValue(meta, key, "<absent>");
}

TEST(RunRecord, WritesEverySettingOfTheEngineChangedOrNot) {
  for (EngineKind kind :
       {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kMarker, EngineKind::kPose}) {
    AnalysisOptions o;
    o.engine.kind = kind;
    const AngleMeta meta = RunRecordMeta(o);
    const std::string engine = EngineName(kind);
    std::size_t fields = kind == EngineKind::kBgsub    ? BgsubOptionFields().size()
                         : kind == EngineKind::kLk     ? LkOptionFields().size()
                         : kind == EngineKind::kMarker ? MarkerOptionFields().size()
                                                       : PoseOptionFields().size();
    std::size_t found = 0;
    for (const auto& [k, v] : meta) {
      if (k.rfind(engine + ".", 0) == 0) ++found;
      EXPECT_TRUE(k.find('.') == std::string::npos || k.rfind(engine + ".", 0) == 0) << k;
    }
    EXPECT_EQ(found, fields) << engine;
  }
  AnalysisOptions o;
  EXPECT_EQ(Value(RunRecordMeta(o), "bgsub.threshold"), "45");
  EXPECT_EQ(Value(RunRecordMeta(o), "bgsub.straight_ratio"), "0.3");
}

TEST(RunRecord, ReadingTheRecordBackGivesTheSameRun) {
  AnalysisOptions o;
  o.inputs = {"v.avi"};
  o.engine.kind = EngineKind::kLk;
  o.background_path = "my bg%.png";  // a space and a percent sign survive the meta line
  o.start = 12;
  o.shoulder_px = cv::Point2d(100.25, 80.125);
  o.elbow_px = cv::Point2d(101, 120.5);
  o.wrist_px = cv::Point2d(99.1, 160.3);
  o.roi = cv::Rect(10, 20, 200, 150);
  o.engine.lk.max_corners = 123;
  o.engine.lk.quality_level = 0.0123456789;
  o.engine.lk.side = LkArmSide::kLeft;
  o.engine.lk.use_bar = false;
  o.engine.lk.initial_upper_deg = -45.5;
  o.model_dir = "/opt/models";
  o.auto_calibrate = true;
  o.calibrate_side = PoseSide::kLeft;
  AngleMeta meta = {{"engine", "lk"}, {"source", "v.avi"}, {"start", "12"}};
  for (auto& kv : RunRecordMeta(o)) meta.push_back(kv);
  // Through the text of a header line, as a file stores it.
  const std::string line = FormatMetaLine(meta);
  AngleMeta parsed;
  std::istringstream in(std::string(kAngleFileMagic) + "\n" + line + "\n" +
                        "frame\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\tupper_cx\t"
                        "upper_cy\tfore_cx\tfore_cy\n");
  AngleFile file;
  ASSERT_TRUE(ParseAngleFile(in, "old.tsv", &file).ok());
  AnalysisOptions back;
  back.inputs = {"new.avi"};
  const Status st = RunFromMeta(file.meta, "old.tsv", &back);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(back.inputs, std::vector<std::string>{"new.avi"});  // the video is the caller's
  EXPECT_EQ(back.engine.kind, EngineKind::kLk);
  EXPECT_EQ(back.background_path, "my bg%.png");
  EXPECT_EQ(back.start, 12);
  EXPECT_EQ(*back.shoulder_px, *o.shoulder_px);
  EXPECT_EQ(*back.elbow_px, *o.elbow_px);
  EXPECT_EQ(*back.wrist_px, *o.wrist_px);
  EXPECT_EQ(*back.roi, *o.roi);
  EXPECT_EQ(back.model_dir, "/opt/models");
  EXPECT_TRUE(back.auto_calibrate);
  EXPECT_EQ(back.calibrate_side, PoseSide::kLeft);
  EXPECT_EQ(back.background_frames, 0);
  EXPECT_TRUE(back.arm_length_path.empty());
  // Every setting, to the last bit.
  EXPECT_EQ(EngineOptionValues(back.engine), EngineOptionValues(o.engine));
  EXPECT_EQ(back.engine.lk.quality_level, o.engine.lk.quality_level);
}

TEST(RunRecord, AnOldHeaderWithOnlyChangedSettingsKeepsTheDefaults) {
  AnalysisOptions back;
  const Status st = RunFromMeta(
      {{"engine", "bgsub"}, {"threshold", "45"}, {"bgsub.closing_size", "3"}}, "old.tsv", &back);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(back.engine.bgsub.closing_size, 3);
  EXPECT_EQ(back.engine.bgsub.threshold, 45);
  EXPECT_EQ(back.engine.bgsub.straight_ratio, BgsubOptions().straight_ratio);
}

TEST(RunRecord, BadRecordsNameTheFileAndTheKey) {
  struct Case {
    AngleMeta meta;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {{{"source", "v.avi"}}, "old.tsv: the header records no engine"},
      {{{"engine", "warp"}}, "engine=warp"},
      {{{"engine", "bgsub"}, {"lk.max_corners", "100"}}, "lk.max_corners=100"},
      {{{"engine", "bgsub"}, {"bgsub.threshold", "999"}}, "bgsub.threshold '999'"},
      {{{"engine", "bgsub"}, {"bgsub.nope", "1"}}, "'bgsub.nope' is no bgsub parameter"},
      {{{"engine", "lk"}, {"shoulder", "1;2"}}, "shoulder=1;2"},
      {{{"engine", "lk"}, {"roi", "1,2,3"}}, "roi=1,2,3"},
      {{{"engine", "lk"}, {"start", "-4"}}, "start=-4"},
  };
  for (const Case& c : cases) {
    AnalysisOptions o;
    const Status st = RunFromMeta(c.meta, "old.tsv", &o);
    ASSERT_FALSE(st.ok()) << c.expect;
    EXPECT_NE(st.message().find("old.tsv: "), std::string::npos) << st.message();
    EXPECT_NE(st.message().find(c.expect), std::string::npos) << st.message();
  }
}

TEST(RunRecord, APathTypedRelativeIsRecordedAbsoluteAsWell) {
  AnalysisOptions o;
  o.engine.kind = EngineKind::kPose;
  o.background_path = "bg.png";
  o.arm_length_path = "/data/arm.png";
  o.model_dir = "../models";
  const AngleMeta meta = RunRecordMeta(o);
  const std::string here = std::filesystem::current_path().string();
  EXPECT_EQ(Value(meta, "background"), "bg.png");
  EXPECT_EQ(Value(meta, "background_abs"), here + "/bg.png");
  EXPECT_EQ(Value(meta, "arm_length"), "/data/arm.png");
  EXPECT_EQ(Value(meta, "arm_length_abs"), "<absent>");  // typed absolute: once is enough
  EXPECT_EQ(Value(meta, "model_dir"), "../models");
  EXPECT_EQ(Value(meta, "model_dir_abs"),
            std::filesystem::path(here).parent_path().string() + "/models");
  // The folder is model_dir: model= is the pose engine's own key (the network it runs).
  EXPECT_EQ(Value(meta, "model"), "<absent>");
  AnalysisOptions back;
  AngleMeta with_engine = meta;
  with_engine.emplace_back("engine", "pose");
  ASSERT_TRUE(RunFromMeta(with_engine, "old.tsv", &back).ok());
  EXPECT_EQ(back.model_dir, "../models");
  EXPECT_EQ(back.background_path, "bg.png");
}

// The header analyze writes, as far as a test can make it without a video: what the pipeline
// adds, the engine's description and the run record.
AngleMeta HeaderOf(const AnalysisOptions& o) {
  AngleMeta meta = {{"engine", EngineName(o.engine.kind)},
                    {"source", "v.avi"},
                    {"fps", "30"},
                    {"width", "160"},
                    {"height", "120"},
                    {"start", "0"}};
  for (auto& kv : Engine::Create(o.engine)->Describe()) meta.push_back(kv);
  for (auto& kv : RunRecordMeta(o)) meta.push_back(kv);
  return meta;
}

TEST(RunRecordKeys, EveryKeyAHeaderHoldsIsKnownAndOnce) {
  for (EngineKind kind :
       {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kMarker, EngineKind::kPose}) {
    AnalysisOptions o;
    o.engine.kind = kind;
    o.background_path = "bg.png";
    o.arm_length_path = "arm.png";
    o.reference_path = "ref.png";
    o.model_dir = "models";
    o.background_frames = 10;
    o.shoulder_px = cv::Point2d(1, 2);
    o.elbow_px = cv::Point2d(1, 3);
    o.wrist_px = cv::Point2d(1, 4);
    o.auto_calibrate = true;
    o.calibrate_side = PoseSide::kLeft;
    o.roi = cv::Rect(0, 0, 10, 10);
    AngleMeta meta = HeaderOf(o);
    meta.emplace_back("complete", "no");
    meta.emplace_back("incomplete", "the video ended early");
    const Status st = CheckRunRecordKeys(meta, "a.tsv", 2);
    EXPECT_TRUE(st.ok()) << EngineName(kind) << ": " << st.message();
  }
}

// What a begun engine adds to its description is known too: the marker engine's calibration
// (alpha_deg, e_radii), and camera_pitch_deg when a tilted camera's views are levelled (a rig
// tilted 6.4 degrees; the key had made --params-from refuse such a file).
TEST(RunRecordKeys, ABegunMarkerEnginesDescriptionIsKnown) {
  synth::MarkerRigOptions rig_options;
  rig_options.set = "medium";
  rig_options.seed = 503;
  rig_options.views = 1;
  const synth::MarkerRigRenderer rig(rig_options);
  AnalysisOptions o;
  o.engine.kind = EngineKind::kMarker;
  o.engine.marker.fov_deg = rig.rig().fov_deg;
  o.reference_path = "ref.png";
  const std::unique_ptr<Engine> engine = Engine::Create(o.engine);
  EngineContext context;
  context.reference = rig.Reference();
  context.frame_size = context.reference.size();
  ASSERT_TRUE(engine->Begin(context).ok());
  AngleMeta meta = {{"engine", "marker"}, {"source", "views"}, {"fps", "0"},
                    {"width", "320"},     {"height", "240"},   {"start", "0"}};
  for (auto& kv : engine->Describe()) meta.push_back(kv);
  for (auto& kv : RunRecordMeta(o)) meta.push_back(kv);
  EXPECT_NE(Value(meta, "camera_pitch_deg"), "<absent>");
  const Status st = CheckRunRecordKeys(meta, "a.tsv", 2);
  EXPECT_TRUE(st.ok()) << st.message();
}

TEST(RunRecordKeys, ARepeatedOrUnknownKeyIsRefusedWithTheLine) {
  struct Case {
    AngleMeta meta;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {{{"engine", "lk"}, {"start", "30"}, {"start", "200"}},
       "old.tsv:2: the key start appears twice (start=30 and start=200)"},
      {{{"engine", "lk"}, {"lk.window_px", "15"}, {"lk.window_px", "15"}},
       "old.tsv:2: the key lk.window_px appears twice"},
      {{{"engine", "lk"}, {"engine", "lk"}}, "old.tsv:2: the key engine appears twice"},
      {{{"engine", "lk"}, {"colour", "red"}}, "old.tsv:2: unknown key colour=red"},
      {{{"engine", "lk"}, {"shoulder_abs", "/a"}}, "old.tsv:2: unknown key shoulder_abs=/a"},
      {{{"engine", "lk"}, {"bgsub.threshold", "45"}},
       "old.tsv:2: unknown key bgsub.threshold=45 (not a setting of the recorded engine lk)"},
      {{{"engine", "lk"}, {"lk.nope", "1"}}, "old.tsv:2: unknown key lk.nope=1 (no lk setting"},
      // A long value is quoted by its start only, on one line.
      {{{"engine", "lk"}, {"x", std::string(5000, 'v') + "\n"}},
       "old.tsv:2: unknown key x=vvvvvvvvvv"},
  };
  for (const Case& c : cases) {
    const Status st = CheckRunRecordKeys(c.meta, "old.tsv", 2);
    ASSERT_FALSE(st.ok()) << c.expect;
    EXPECT_EQ(st.message().rfind(c.expect, 0), 0u) << st.message().substr(0, 300);
    EXPECT_LT(st.message().size(), 300u);
    EXPECT_EQ(st.message().find('\n'), std::string::npos);
  }
}

// A value the run cannot take is quoted by its start only, on one line, whatever its key.
TEST(RunRecord, ALongBadValueIsQuotedByItsStart) {
  const std::string huge = std::string(5000, '7') + "\nx";
  for (const std::string key : {"lk.window_px", "start", "shoulder", "roi", "calibrate_side"}) {
    AnalysisOptions o;
    const Status st = RunFromMeta({{"engine", "lk"}, {key, huge}}, "old.tsv", &o);
    ASSERT_FALSE(st.ok()) << key;
    EXPECT_EQ(st.message().rfind("old.tsv: " + key + "=7777", 0), 0u)
        << st.message().substr(0, 200);
    EXPECT_LT(st.message().size(), 300u) << key;
    EXPECT_EQ(st.message().find('\n'), std::string::npos) << key;
  }
}

TEST(RunRecordKeys, OlderHeadersStillPass) {
  // Before model_dir, a pose run given --model wrote model= twice: the network, then the folder.
  AngleMeta pose = {{"engine", "pose"}, {"model", "movenet-lightning-v4"}, {"model", "/m"}};
  ASSERT_TRUE(CheckRunRecordKeys(pose, "old.tsv", 2).ok());
  AnalysisOptions o;
  ASSERT_TRUE(RunFromMeta(pose, "old.tsv", &o).ok());
  EXPECT_EQ(o.model_dir, "/m");
  // Without --model, model= named only the network: no folder.
  AnalysisOptions plain;
  ASSERT_TRUE(
      RunFromMeta({{"engine", "pose"}, {"model", "movenet-lightning-v4"}}, "old.tsv", &plain).ok());
  EXPECT_EQ(plain.model_dir, "");
  // Removed settings are no unknown keys (they are skipped and named once).
  ASSERT_TRUE(
      CheckRunRecordKeys({{"engine", "bgsub"}, {"bgsub.reject_shadow", "false"}}, "old.tsv", 2)
          .ok());
}

}  // namespace
}  // namespace armmimic
