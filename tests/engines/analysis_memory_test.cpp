// The analysis pipeline on frames in memory (AnalysisOptions::open_source) gives exactly the rows
// it gives on the video file those frames were decoded from.
#include <memory>

#include <gtest/gtest.h>

#include "armmimic/engines/analysis.h"
#include "armmimic/synth/random_arm_scene.h"
#include "test_util.h"

namespace armmimic {
namespace {

std::vector<AngleRow> Rows(const AnalysisOptions& o) {
  std::vector<AngleRow> rows;
  AnalysisCallbacks cb;
  cb.on_measurement = [&rows](const Frame&, const ArmMeasurement& m) {
    if (m.row()) rows.push_back(m.ToRow());
  };
  AnalysisSummary summary;
  const Status st = RunAnalysis(o, cb, &summary);
  EXPECT_TRUE(st.ok()) << st.message();
  return rows;
}

TEST(AnalysisInMemory, RowsEqualThoseFromTheVideoFile) {
  test::TempDir dir;
  synth::RandomArmSceneOptions so;
  so.seed = 4242;  // not in the tuning or held-out ranges
  so.tier = synth::SceneTier::kEasy;
  so.size = {160, 120};
  ASSERT_TRUE(synth::WriteRandomArmScene(so, dir.path(), nullptr).ok());
  const synth::RandomArmScene scene(so);
  Status st;
  auto video = VideoSource::Open(dir.file("scene.avi"), &st);
  ASSERT_TRUE(video) << st.message();
  auto frames = std::make_shared<std::vector<cv::Mat>>();
  Frame f;
  while (video->Read(&f, &st)) frames->push_back(f.image.clone());
  ASSERT_EQ(static_cast<int>(frames->size()), scene.frame_count());
  const double fps = video->info().fps;

  for (EngineKind kind : {EngineKind::kBgsub, EngineKind::kLk}) {
    AnalysisOptions file;
    file.inputs = {dir.file("scene.avi")};
    file.engine.kind = kind;
    file.background_frames = scene.background_frames();
    file.start = scene.background_frames();
    file.engine.bgsub.standstill_frames = scene.standstill_frames();
    file.engine.lk.standstill_frames = scene.standstill_frames();
    if (kind == EngineKind::kBgsub) file.arm_length_path = dir.file("armlength.png");
    AnalysisOptions memory = file;
    memory.open_source = [frames, fps](Status* status) {
      return VideoSource::FromFrames(frames, fps, "memory", status);
    };
    const std::vector<AngleRow> a = Rows(file), b = Rows(memory);
    ASSERT_EQ(a.size(), b.size()) << EngineName(kind);
    ASSERT_EQ(static_cast<int>(a.size()), scene.motion_frames()) << EngineName(kind);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].frame, b[i].frame);
      EXPECT_EQ(a[i].status, b[i].status) << EngineName(kind) << " frame " << a[i].frame;
      if (a[i].ok()) {
        EXPECT_DOUBLE_EQ(a[i].upper_deg, b[i].upper_deg) << a[i].frame;
        EXPECT_DOUBLE_EQ(a[i].fore_deg, b[i].fore_deg) << a[i].frame;
      }
    }
  }
}

}  // namespace
}  // namespace armmimic
