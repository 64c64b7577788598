// The pose network against TensorFlow.js running the same model (reference keypoints made by
// scripts/pose-parity.sh), and the pose engine on generated scenes: known angles, a scene with
// nobody in it. Compiled in only when the model is there (tests/engines/CMakeLists.txt); the
// real-clip parity only when the clip is. Inferences are kept to a few dozen (sanitizer runs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "armmimic/core/angles.h"
#include "armmimic/core/video_source.h"
#include "armmimic/engines/engine.h"
#include "armmimic/engines/pose.h"
#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

#ifdef ARMMIMIC_HAVE_POSE_MODEL

namespace armmimic {
namespace {

struct Reference {
  std::string name;  // "synth_110", "video_8"
  int frame = 0;
  PoseKeypoints k;  // in input pixels (0..192)
};

std::vector<Reference> ReadReferences(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::vector<Reference> refs;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Reference r;
    fields >> r.name;
    r.frame = std::stoi(r.name.substr(r.name.find('_') + 1));
    for (int i = 0; i < kPoseKeypointCount; ++i) {
      double y, x, s;
      fields >> y >> x >> s;
      r.k.px[i] = {x * PoseNetwork::kInputSize, y * PoseNetwork::kInputSize};
      r.k.score[i] = s;
    }
    EXPECT_TRUE(fields) << path << ": " << r.name;
    refs.push_back(r);
  }
  return refs;
}

// The four arm directions (left upper, left fore, right upper, right fore).
std::vector<double> ArmDirections(const PoseKeypoints& k) {
  return {DirectionDeg(k.px[kLeftShoulder], k.px[kLeftElbow]),
          DirectionDeg(k.px[kLeftElbow], k.px[kLeftWrist]),
          DirectionDeg(k.px[kRightShoulder], k.px[kRightElbow]),
          DirectionDeg(k.px[kRightElbow], k.px[kRightWrist])};
}

double Quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * (v.size() - 1))];
}

std::unique_ptr<PoseNetwork> LoadNetwork() {
  Status st;
  auto net = PoseNetwork::Load("", &st);
  EXPECT_TRUE(net) << st.message();
  return net;
}

// Runs the network on each reference's input (made by `frame_of`) and checks the arm directions.
void CheckParity(const std::vector<Reference>& refs,
                 const std::function<cv::Mat(int frame)>& frame_of) {
  ASSERT_FALSE(refs.empty());
  auto net = LoadNetwork();
  ASSERT_TRUE(net);
  std::vector<double> errors;
  for (const Reference& r : refs) {
    const cv::Mat bgr = frame_of(r.frame);
    const PoseKeypoints k = net->RunInput(PoseNetwork::MakeInput(bgr, WholeImageCrop(bgr.size())));
    const auto mine = ArmDirections(k), theirs = ArmDirections(r.k);
    for (std::size_t i = 0; i < mine.size(); ++i) {
      errors.push_back(std::abs(AngleDiff(mine[i], theirs[i])));
    }
  }
  std::printf(
      "arm directions against TensorFlow.js: median %.2f, p90 %.2f, max %.2f degrees (%zu)\n",
      Quantile(errors, 0.5), Quantile(errors, 0.9), Quantile(errors, 1.0), errors.size());
  EXPECT_LE(Quantile(errors, 0.5), 1.0);
  EXPECT_LE(Quantile(errors, 0.9), 3.0);
}

TEST(PoseParityTest, AGeneratedSceneAgreesWithTensorFlowJs) {
  synth::ArmSceneOptions o;
  o.seed = 1;
  synth::ArmSceneRenderer scene(o);
  CheckParity(ReadReferences(test::SourcePath("tests/engines/data/pose_parity_synth.tsv")),
              [&](int frame) { return scene.Render(frame); });
}

#ifdef ARMMIMIC_REAL_DIR
TEST(PoseParityTest, TheRealClipAgreesWithTensorFlowJs) {
  Status st;
  auto video = VideoSource::Open(std::string(ARMMIMIC_REAL_DIR) + "/pose_squats.mp4", &st);
  ASSERT_TRUE(video) << st.message();
  CheckParity(ReadReferences(test::SourcePath("tests/engines/data/pose_parity_real.tsv")),
              [&](int frame) {
                Frame f;
                EXPECT_TRUE(video->Seek(frame).ok());
                EXPECT_TRUE(video->Read(&f, &st)) << st.message();
                return f.image;
              });
}
#endif

std::unique_ptr<Engine> StartPose(const cv::Size& size, PoseSide side) {
  EngineOptions o;
  o.kind = EngineKind::kPose;
  o.pose.side = side;
  auto engine = Engine::Create(o);
  EngineContext context;
  context.frame_size = size;
  context.fps = 30;
  const Status st = engine->Begin(context);
  EXPECT_TRUE(st.ok()) << st.message();
  return engine;
}

TEST(PoseEngineTest, ASceneWithNobodyGivesLostRows) {
  synth::ArmSceneOptions o;
  synth::ArmSceneRenderer scene(o);
  auto engine = StartPose(o.size, PoseSide::kAuto);
  for (int i = 0; i < 3; ++i) {  // the empty-room frames before the person walks in
    Frame f;
    f.index = i;
    f.image = scene.Render(i);
    const ArmMeasurement m = engine->Process(f);
    EXPECT_EQ(m.phase, MeasurementPhase::kLost) << "frame " << i << ": " << m.note;
    EXPECT_TRUE(m.row());
    EXPECT_LT(m.confidence, 0.4);
  }
}

// The generated person (moving arm on screen right: the person's own left), every 8th frame of
// the motion: directions within a few degrees of the truth, every row ok, none confidently wrong.
TEST(PoseEngineTest, FindsTheGeneratedArmsKnownDirections) {
  synth::ArmSceneOptions o;
  synth::ArmSceneRenderer scene(o);
  auto engine = StartPose(o.size, PoseSide::kLeft);
  std::vector<double> errors;
  int ok = 0, rows = 0;
  for (int i = o.first_motion_frame(); i < o.frame_count(); i += 8) {
    Frame f;
    f.index = i;
    synth::ArmTruth truth;
    f.image = scene.Render(i, &truth);
    const ArmMeasurement m = engine->Process(f);
    ++rows;
    if (m.phase != MeasurementPhase::kOk) continue;
    ++ok;
    errors.push_back(std::abs(AngleDiff(m.upper_deg, truth.upper_deg)));
    errors.push_back(std::abs(AngleDiff(m.fore_deg, truth.fore_deg)));
    EXPECT_GE(m.confidence, 0.4);
  }
  ASSERT_FALSE(errors.empty());
  std::printf("generated arm: %d of %d rows ok, median %.1f, max %.1f degrees\n", ok, rows,
              Quantile(errors, 0.5), Quantile(errors, 1.0));
  EXPECT_GE(ok, rows * 8 / 10);
  EXPECT_LE(Quantile(errors, 0.5), 5.0);
  EXPECT_LE(Quantile(errors, 1.0), 15.0);  // no ok row confidently wrong
}

// --auto-calibrate's joints on the generated person's start frame, against the truth.
TEST(PoseEngineTest, AutoCalibrateFindsTheGeneratedArmsJoints) {
  test::TempDir dir;
  synth::ArmSceneOptions o;
  o.motion_frames = 2;
  ASSERT_TRUE(synth::WriteArmScene(o, dir.path(), nullptr).ok());
  synth::ArmSceneRenderer scene(o);
  synth::ArmTruth truth;
  scene.Render(o.first_motion_frame(), &truth);
  PoseArm arm;
  PoseSide side = PoseSide::kAuto;
  const Status st = DetectArmJoints({dir.file("scene.avi")}, o.first_motion_frame(),
                                    PoseSide::kLeft, "", PoseOptions(), &arm, &side);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(side, PoseSide::kLeft);
  const double upper = cv::norm(truth.elbow_px - truth.shoulder_px);
  EXPECT_LT(cv::norm(arm.shoulder - truth.shoulder_px), 0.25 * upper);
  EXPECT_LT(cv::norm(arm.elbow - truth.elbow_px), 0.25 * upper);
  EXPECT_LT(cv::norm(arm.wrist - truth.wrist_px), 0.25 * upper);
}

}  // namespace
}  // namespace armmimic

#endif  // ARMMIMIC_HAVE_POSE_MODEL
