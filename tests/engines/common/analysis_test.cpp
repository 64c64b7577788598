// The analysis pipeline: option checks that name the flag, the background mean, frame indices
// with --start, cancelling (rows so far kept, complete=no) and streaming to an angle file.
#include "armmimic/engines/analysis.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/core/image_io.h"
#include "test_util.h"

namespace armmimic {
namespace {

cv::Mat Wall() { return cv::Mat(cv::Size(160, 120), CV_8UC3, cv::Scalar(190, 200, 205)); }

cv::Mat Person(double arm_deg) {
  cv::Mat img = Wall();
  const cv::Scalar shirt(140, 60, 30);
  cv::rectangle(img, cv::Rect(60, 45, 28, 75), shirt, cv::FILLED);
  cv::circle(img, cv::Point(74, 31), 8, cv::Scalar(120, 150, 200), cv::FILLED);
  const cv::Point2d s(95, 50);
  cv::line(img, s, s + DirectionVector(arm_deg) * 45, shirt, 7);
  return img;
}

// A folder of numbered frames: `empty` wall frames, `still` hanging-arm frames, then the arm at
// 0, 10, 20 ... degrees; plus armlength.png and bg.png.
struct Scene {
  test::TempDir dir;
  int empty = 4, still = 3, moving = 6;
  Scene() {
    int n = 0;
    auto put = [&](const cv::Mat& img) {
      char name[32];
      std::snprintf(name, sizeof(name), "/frames/f%03d.png", n++);
      EXPECT_TRUE(WriteImageAtomically(dir.path() + name, img).ok());
    };
    EXPECT_EQ(std::system(("mkdir -p '" + dir.path() + "/frames'").c_str()), 0);
    for (int i = 0; i < empty; ++i) put(Wall());
    for (int i = 0; i < still; ++i) put(Person(-90));
    for (int i = 0; i < moving; ++i) put(Person(10.0 * i));
    EXPECT_TRUE(WriteImageAtomically(dir.file("armlength.png"), Person(0)).ok());
    EXPECT_TRUE(WriteImageAtomically(dir.file("bg.png"), Wall()).ok());
  }
  AnalysisOptions Options() const {
    AnalysisOptions o;
    o.inputs = {dir.path() + "/frames"};
    o.engine.kind = EngineKind::kBgsub;
    o.engine.bgsub.standstill_frames = still;
    o.background_frames = empty;
    o.arm_length_path = dir.file("armlength.png");
    o.start = empty;
    return o;
  }
};

TEST(Analysis, CheckNamesTheSetting) {
  AnalysisOptions o;
  o.inputs = {"x.avi"};
  EXPECT_EQ(o.Check().key(), "analysis.arm_length");
  EXPECT_NE(o.Check().message().find("arm-length image"), std::string::npos);
  o.arm_length_path = "arm.png";
  EXPECT_EQ(o.Check().key(), "analysis.background_frames");
  EXPECT_NE(o.Check().message().find("background frames"), std::string::npos);
  o.background_frames = 45;
  EXPECT_TRUE(o.Check().ok()) << o.Check().message();
  o.background_path = "bg.png";
  EXPECT_NE(o.Check().message().find("exactly one"), std::string::npos);
  o.background_path.clear();
  o.start = -1;
  EXPECT_EQ(o.Check().key(), "analysis.start");
  EXPECT_NE(o.Check().message().find("start frame"), std::string::npos);
  o.start = 0;
  o.engine.bgsub.threshold = 300;
  EXPECT_EQ(o.Check().key(), "bgsub.threshold");
  AnalysisOptions lk;
  lk.inputs = {"x.avi"};
  lk.engine.kind = EngineKind::kLk;
  EXPECT_EQ(lk.Check().key(), "analysis.shoulder");
  EXPECT_NE(lk.Check().message().find("shoulder"), std::string::npos);
  lk.shoulder_px = cv::Point2d(10, 10);
  EXPECT_TRUE(lk.Check().ok());
  AnalysisOptions marker;
  marker.inputs = {"a.png"};
  marker.engine.kind = EngineKind::kMarker;
  EXPECT_EQ(marker.Check().key(), "analysis.reference");
  AnalysisOptions none;
  EXPECT_FALSE(none.Check().ok());
}

TEST(Analysis, EstimateBackgroundIsTheMeanAndNamesAShortInput) {
  test::TempDir dir;
  for (int i = 0; i < 3; ++i) {
    const cv::Mat img(cv::Size(8, 6), CV_8UC3, cv::Scalar::all(10 + 10 * i));
    EXPECT_TRUE(WriteImageAtomically(dir.file("f" + std::to_string(i) + ".png"), img).ok());
  }
  cv::Mat bg;
  ASSERT_TRUE(EstimateBackground({dir.path()}, 0, 3, &bg).ok());
  ASSERT_EQ(bg.type(), CV_8UC3);
  EXPECT_EQ(bg.at<cv::Vec3b>(2, 2), cv::Vec3b(20, 20, 20));
  ASSERT_TRUE(EstimateBackground({dir.path()}, 1, 2, &bg).ok());
  EXPECT_EQ(bg.at<cv::Vec3b>(0, 0), cv::Vec3b(25, 25, 25));
  const Status st = EstimateBackground({dir.path()}, 0, 45, &bg);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find(dir.path()), std::string::npos) << st.message();
  EXPECT_FALSE(EstimateBackground({dir.file("missing.avi")}, 0, 3, &bg).ok());
}

TEST(Analysis, RowsStartAfterTheStandstillWithFileFrameIndices) {
  Scene scene;
  std::vector<ArmMeasurement> rows;
  int setup = 0;
  AnalysisCallbacks cb;
  cb.on_measurement = [&](const Frame&, const ArmMeasurement& m) {
    if (m.row()) {
      rows.push_back(m);
    } else {
      ++setup;
    }
  };
  AnalysisSummary summary;
  const Status st = RunAnalysis(scene.Options(), cb, &summary);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(setup, scene.still);
  ASSERT_EQ(static_cast<int>(rows.size()), scene.moving);
  EXPECT_EQ(summary.frames, scene.moving);
  EXPECT_EQ(summary.ok + summary.lost, summary.frames);
  for (int i = 0; i < scene.moving; ++i) {
    EXPECT_EQ(rows[static_cast<size_t>(i)].frame, scene.empty + scene.still + i);
    if (i > 0) {  // the arm at 0 degrees is the arm-length pose; check the raised ones
      EXPECT_EQ(rows[static_cast<size_t>(i)].phase, MeasurementPhase::kOk);
      const ArmMeasurement& m = rows[static_cast<size_t>(i)];
      // The upper arm is 20 px long and 7 px thick here: a few degrees are a pixel at the elbow.
      EXPECT_NEAR(AngleDiff(m.upper_deg, 10.0 * i), 0, 7)
          << "row " << i << ", shoulder " << m.shoulder_px.value_or(cv::Point2d()) << ", fore "
          << m.fore_deg << ": " << m.note;
    }
  }
  bool has_threshold = false;
  for (const auto& kv : summary.meta) has_threshold |= kv.first == "threshold";
  EXPECT_TRUE(has_threshold);
}

TEST(Analysis, CancelKeepsTheRowsInAFileMarkedIncomplete) {
  Scene scene;
  std::atomic<bool> cancel{false};
  AnalysisCallbacks cb;
  cb.cancel = &cancel;
  int rows = 0;
  cb.on_measurement = [&](const Frame&, const ArmMeasurement& m) {
    if (m.row() && ++rows == 2) cancel = true;
  };
  const std::string out = scene.dir.file("angles.tsv");
  AnalysisSummary summary;
  const Status st = AnalyzeToFile(scene.Options(), out, cb, &summary);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_TRUE(summary.cancelled);
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(out, &f).ok());
  EXPECT_FALSE(f.complete);
  EXPECT_EQ(f.rows.size(), 2u);
  EXPECT_EQ(f.Meta("engine"), "bgsub");
  EXPECT_EQ(f.Meta("start"), std::to_string(scene.empty));
}

TEST(Analysis, SizeMismatchNamesBothFiles) {
  Scene scene;
  AnalysisOptions o = scene.Options();
  o.background_frames = 0;
  const std::string small = scene.dir.file("small.png");
  ASSERT_TRUE(WriteImageAtomically(small, cv::Mat(cv::Size(4, 4), CV_8UC3)).ok());
  o.background_path = small;
  AnalysisSummary summary;
  const Status st = RunAnalysis(o, {}, &summary);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("small.png"), std::string::npos) << st.message();
  EXPECT_EQ(st.key(), "analysis.background");
  EXPECT_NE(st.message().find("background image"), std::string::npos) << st.message();
  EXPECT_NE(st.message().find("160x120"), std::string::npos) << st.message();
}

}  // namespace
}  // namespace armmimic
