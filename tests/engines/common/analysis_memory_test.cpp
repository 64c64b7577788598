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

// A scene written as a video, and its frames decoded into memory.
struct DecodedScene {
  test::TempDir dir;
  synth::RandomArmSceneOptions options;
  std::shared_ptr<std::vector<cv::Mat>> frames = std::make_shared<std::vector<cv::Mat>>();
  double fps = 0;

  DecodedScene() {
    options.seed = 4242;  // not in the tuning or held-out ranges
    options.tier = synth::SceneTier::kEasy;
    options.size = {160, 120};
    EXPECT_TRUE(synth::WriteRandomArmScene(options, dir.path(), nullptr).ok());
    Status st;
    auto video = VideoSource::Open(dir.file("scene.avi"), &st);
    EXPECT_TRUE(video) << st.message();
    if (!video) return;
    Frame f;
    while (video->Read(&f, &st)) frames->push_back(f.image.clone());
    fps = video->info().fps;
  }
  // `o` reading the frames from memory instead of the file.
  AnalysisOptions InMemory(AnalysisOptions o) const {
    auto held = frames;
    const double rate = fps;
    o.open_source = [held, rate](Status* status) {
      return VideoSource::FromFrames(held, rate, "memory", status);
    };
    return o;
  }
};

void ExpectSameRows(const std::vector<AngleRow>& a, const std::vector<AngleRow>& b,
                    const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].frame, b[i].frame) << what;
    EXPECT_EQ(a[i].status, b[i].status) << what << " frame " << a[i].frame;
    if (a[i].ok()) {
      EXPECT_DOUBLE_EQ(a[i].upper_deg, b[i].upper_deg) << what << " frame " << a[i].frame;
      EXPECT_DOUBLE_EQ(a[i].fore_deg, b[i].fore_deg) << what << " frame " << a[i].frame;
    }
  }
}

TEST(AnalysisInMemory, RowsEqualThoseFromTheVideoFile) {
  const DecodedScene d;
  const synth::RandomArmScene scene(d.options);
  ASSERT_EQ(static_cast<int>(d.frames->size()), scene.frame_count());

  for (EngineKind kind : {EngineKind::kBgsub, EngineKind::kLk}) {
    AnalysisOptions file;
    file.inputs = {d.dir.file("scene.avi")};
    file.engine.kind = kind;
    file.background_frames = scene.background_frames();
    file.start = scene.background_frames();
    file.engine.bgsub.standstill_frames = scene.standstill_frames();
    file.engine.lk.standstill_frames = scene.standstill_frames();
    if (kind == EngineKind::kBgsub) file.arm_length_path = d.dir.file("armlength.png");
    const std::vector<AngleRow> rows = Rows(file);
    EXPECT_EQ(static_cast<int>(rows.size()), scene.motion_frames()) << EngineName(kind);
    ExpectSameRows(rows, Rows(d.InMemory(file)), EngineName(kind));
  }
}

#ifdef ARMMIMIC_HAVE_POSE_MODEL
// The pose network's steps before the engine starts (the joints of --auto-calibrate, the pose
// engine's choice of arm) read the frames from memory too.
TEST(AnalysisInMemory, PoseStepsReadTheFramesFromMemory) {
  const DecodedScene d;
  const synth::RandomArmScene scene(d.options);
  const int start = scene.frame_count() - 12;  // a few frames: the network is slow
  AnalysisOptions lk;
  lk.inputs = {d.dir.file("scene.avi")};
  lk.engine.kind = EngineKind::kLk;
  lk.auto_calibrate = true;
  lk.start = start;
  ExpectSameRows(Rows(lk), Rows(d.InMemory(lk)), "lk --auto-calibrate");
  AnalysisOptions pose;
  pose.inputs = {d.dir.file("scene.avi")};
  pose.engine.kind = EngineKind::kPose;
  pose.start = start;
  ExpectSameRows(Rows(pose), Rows(d.InMemory(pose)), "pose, the arm chosen by the network");
}
#endif

}  // namespace
}  // namespace armmimic
