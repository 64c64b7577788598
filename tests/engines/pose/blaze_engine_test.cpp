// The pose engine with BlazePose (--network blazepose): the network against TensorFlow.js on the
// same crops (reference landmarks made by scripts/pose-parity.sh), a scene with nobody in it
// gives lost rows, and on the real clip the 3-D arm directions and elbow angles are measured
// against MediaPipe's own world landmarks (pose_squats.world.tsv). Compiled in only when both
// models are there (tests/engines/CMakeLists.txt); the real-clip test only when the clip is.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "armmimic/core/angles.h"
#include "armmimic/core/video_source.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/arm_scene.h"
#include "armmimic/synth/robustness_stats.h"
#include "pose/blazepose.h"
#include "start_pose.h"
#include "test_util.h"

#if defined(ARMMIMIC_HAVE_POSE_MODEL) && defined(ARMMIMIC_HAVE_BLAZEPOSE_MODEL)

namespace armmimic {
namespace {

std::unique_ptr<Engine> StartBlazePose(const cv::Size& size, PoseSide side) {
  PoseOptions pose;
  pose.network = PoseNetworkKind::kBlazePose;
  return test::StartPose(size, side, pose);
}

TEST(BlazePoseEngineTest, ASceneWithNobodyGivesLostRows) {
  synth::ArmSceneOptions o;
  synth::ArmSceneRenderer scene(o);
  auto engine = StartBlazePose(o.size, PoseSide::kLeft);
  for (int i = 0; i < 3; ++i) {  // the empty-room frames before the person walks in
    Frame f;
    f.index = i;
    f.image = scene.Render(i);
    const ArmMeasurement m = engine->Process(f);
    EXPECT_EQ(m.phase, MeasurementPhase::kLost) << "frame " << i << ": " << m.note;
    EXPECT_TRUE(std::isnan(m.upper_az_deg));
  }
}

#ifdef ARMMIMIC_REAL_DIR
// pose_squats.world.tsv by frame: each column's value by its name ("right_elbow_x", ...).
std::map<int, std::map<std::string, double>> ReadWorldReference(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::map<int, std::map<std::string, double>> ref;
  std::vector<std::string> names;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    if (line.rfind("frame", 0) == 0) {
      for (std::string n; fields >> n;) names.push_back(n);
      continue;
    }
    std::map<std::string, double> row;
    for (const std::string& n : names) fields >> row[n];
    EXPECT_TRUE(fields) << path << ": " << line.substr(0, 20);
    ref[static_cast<int>(row["frame"])] = row;
  }
  return ref;
}

cv::Vec3d Joint(const std::map<std::string, double>& row, const std::string& name) {
  return {row.at(name + "_x"), row.at(name + "_y"), row.at(name + "_z")};
}

// The unit direction of an azimuth and elevation (the angle file's 3-D columns).
cv::Vec3d FromAzimuthElevation(double az_deg, double el_deg) {
  const double az = RadFromDeg(az_deg), el = RadFromDeg(el_deg);
  return {std::cos(el) * std::cos(az), -std::sin(el), -std::cos(el) * std::sin(az)};
}

double AngleBetweenDeg(const cv::Vec3d& a, const cv::Vec3d& b) {
  return DegFromRad(std::atan2(cv::norm(a.cross(b)), a.dot(b)));
}

// The same inputs (each frame's crop as the engine places it afresh) through TensorFlow.js and
// through cv::dnn: the world landmarks within 1 cm and the arm's 3-D directions within 1 degree
// at the median, the 2-D landmarks within a pixel of the 256x256 input.
TEST(BlazePoseParityTest, TheRealClipAgreesWithTensorFlowJs) {
  std::ifstream in(test::SourcePath("tests/engines/data/blazepose_parity_real.tsv"));
  ASSERT_TRUE(in);
  Status st;
  auto video = VideoSource::Open(std::string(ARMMIMIC_REAL_DIR) + "/pose_squats.mp4", &st);
  ASSERT_TRUE(video) << st.message();
  auto movenet = PoseNetwork::Load("", &st);
  ASSERT_TRUE(movenet) << st.message();
  auto blaze = internal::BlazePoseNetwork::Load("", &st);
  ASSERT_TRUE(blaze) << st.message();
  std::vector<double> world_cm, direction_deg, px;
  std::string line;
  int frames = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name;
    double flag;
    fields >> name >> flag;
    std::array<cv::Point2d, internal::kBlazeBodyCount> ref_px;
    std::array<cv::Vec3d, internal::kBlazeBodyCount> ref_world;
    for (int i = 0; i < internal::kBlazeBodyCount; ++i) {
      fields >> ref_px[i].x >> ref_px[i].y >> ref_world[i][0] >> ref_world[i][1] >> ref_world[i][2];
    }
    ASSERT_TRUE(fields) << name;
    Frame f;
    ASSERT_TRUE(video->Seek(std::stoi(name.substr(name.find('_') + 1))).ok());
    ASSERT_TRUE(video->Read(&f, &st)) << st.message();
    internal::BlazeCrop crop;
    ASSERT_TRUE(internal::SeedCrop(movenet.get(), blaze.get(), f.image, 0.2, &crop)) << name;
    const internal::BlazeLandmarks b =
        blaze->RunInput(internal::BlazePoseNetwork::MakeInput(f.image, crop));
    EXPECT_NEAR(b.poseflag, flag, 0.01) << name;
    for (int i = 0; i < internal::kBlazeBodyCount; ++i) {
      world_cm.push_back(100 * cv::norm(b.world[i] - ref_world[i]));
      px.push_back(cv::norm(b.px[i] - ref_px[i]));
    }
    const int arm[2][3] = {
        {internal::kBlazeLeftShoulder, internal::kBlazeLeftElbow, internal::kBlazeLeftWrist},
        {internal::kBlazeRightShoulder, internal::kBlazeRightElbow, internal::kBlazeRightWrist}};
    for (const auto& j : arm) {
      for (int k = 0; k < 2; ++k) {
        direction_deg.push_back(AngleBetweenDeg(b.world[j[k + 1]] - b.world[j[k]],
                                                ref_world[j[k + 1]] - ref_world[j[k]]));
      }
    }
    ++frames;
  }
  ASSERT_GE(frames, 10);
  std::printf(
      "BlazePose parity, %d frames: world landmarks median %.2f cm (max %.2f), arm directions "
      "median %.2f degrees (max %.2f), 2-D landmarks median %.2f px (max %.2f)\n",
      frames, synth::Quantile(world_cm, 0.5), synth::Quantile(world_cm, 1.0),
      synth::Quantile(direction_deg, 0.5), synth::Quantile(direction_deg, 1.0),
      synth::Quantile(px, 0.5), synth::Quantile(px, 1.0));
  EXPECT_LE(synth::Quantile(world_cm, 0.5), 1.0);
  EXPECT_LE(synth::Quantile(direction_deg, 0.5), 1.0);
  EXPECT_LE(synth::Quantile(px, 0.5), 1.0);
}

// Both arms over the whole clip: the 3-D direction errors of the ok rows' segments against
// MediaPipe's world landmarks, the coverage, the elbow angle's error and how steady the
// forearm-to-upper-arm length ratio is. The bounds are the goals (docs/pose.md; measured: median
// 7.9, p90 13.5 degrees, coverage 80.0 % (104 of 130 rows), elbow median 6.4 degrees, ratio cv
// 9.4 %), but for the coverage: the goal of 80 % is met by no more than a row, so the test allows
// two rows fewer (0.78) for floating-point differences between builds (the sanitizer build).
TEST(BlazePoseEngineTest, MeasuresTheRealClipsArmsIn3dAgainstMediaPipe) {
  const std::string dir = ARMMIMIC_REAL_DIR;
  const auto ref = ReadWorldReference(dir + "/pose_squats.world.tsv");
  std::vector<double> errors, elbow_errors, ratios;
  int rows = 0, ok = 0;
  for (PoseSide side : {PoseSide::kLeft, PoseSide::kRight}) {
    const std::string s = side == PoseSide::kLeft ? "left_" : "right_";
    Status st;
    auto video = VideoSource::Open(dir + "/pose_squats.mp4", &st);
    ASSERT_TRUE(video) << st.message();
    auto engine = StartBlazePose(video->info().size, side);
    Frame f;
    while (video->Read(&f, &st)) {
      const ArmMeasurement m = engine->Process(f);
      ++rows;
      if (m.phase != MeasurementPhase::kOk) continue;
      ++ok;
      const auto& r = ref.at(f.index);
      const cv::Vec3d sh = Joint(r, s + "shoulder"), el = Joint(r, s + "elbow"),
                      wr = Joint(r, s + "wrist");
      errors.push_back(
          AngleBetweenDeg(FromAzimuthElevation(m.upper_az_deg, m.upper_el_deg), el - sh));
      errors.push_back(
          AngleBetweenDeg(FromAzimuthElevation(m.fore_az_deg, m.fore_el_deg), wr - el));
      elbow_errors.push_back(std::abs(m.elbow_deg - JointAngleDeg(sh, el, wr)));
      ratios.push_back(cv::norm(m.arm_world_m[2] - m.arm_world_m[1]) /
                       cv::norm(m.arm_world_m[1] - m.arm_world_m[0]));
    }
    ASSERT_TRUE(st.ok()) << st.message();
  }
  ASSERT_FALSE(errors.empty());
  const double coverage = static_cast<double>(ok) / rows;
  double mean = 0, spread = 0;
  for (double r : ratios) mean += r / ratios.size();
  for (double r : ratios) spread += (r - mean) * (r - mean) / ratios.size();
  const double ratio_cv = std::sqrt(spread) / mean;
  std::printf(
      "real clip in 3-D, both arms: direction median %.1f, p90 %.1f degrees, coverage %.1f %%; "
      "elbow median %.1f, p90 %.1f degrees; forearm/upper arm length ratio %.2f, cv %.1f %%\n",
      synth::Quantile(errors, 0.5), synth::Quantile(errors, 0.9), 100 * coverage,
      synth::Quantile(elbow_errors, 0.5), synth::Quantile(elbow_errors, 0.9), mean, 100 * ratio_cv);
  EXPECT_LE(synth::Quantile(errors, 0.5), 8.0);
  EXPECT_LE(synth::Quantile(errors, 0.9), 18.0);
  EXPECT_GE(coverage, 0.78);
  EXPECT_LE(synth::Quantile(elbow_errors, 0.5), 9.0);
  EXPECT_LE(ratio_cv, 0.15);
}
#endif

}  // namespace
}  // namespace armmimic

#endif
