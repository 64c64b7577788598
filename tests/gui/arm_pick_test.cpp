// Both arms in the window (the pose engine's side both): the analysis writes an angle file per
// arm, the overlay draws both arms, and the arm picked on the angle panel is the one the plot,
// the overlay's angles and the robot's plan follow. Needs the pose model.
#include <QComboBox>
#include <QFileInfo>
#include <QImage>
#include <QTest>

#include "analysis_job.h"
#include "angle_panel.h"
#include "angle_plot.h"
#include "armmimic/core/angle_file.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_panel.h"
#include "robot_plan.h"
#include "video_player.h"
#include "video_view.h"

#ifdef ARMMIMIC_HAVE_POSE_MODEL

namespace armmimic::test {
namespace {

using gui::MainWindow;

class ArmPickTest : public GuiTest {
 protected:
  // Opens the arm scene and analyses its motion with the pose engine, side both.
  void AnalyzeBothArms(MainWindow& w) {
    ShowAndOpen(w);
    if (HasFatalFailure()) return;
    AnalysisOptions o;
    o.engine.kind = EngineKind::kPose;
    o.engine.pose.side = PoseSide::kBoth;
    o.start = scenes().background_frames + scenes().standstill_frames;
    w.settingsPanel()->setOptions(o);
    ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
    ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
    ASSERT_EQ(w.job()->resultPaths().size(), 2) << w.log()->text().toStdString();
  }

  static int OkRows(const QString& path) {
    AngleFile f;
    EXPECT_TRUE(ReadAngleFile(path.toStdString(), &f).ok()) << path.toStdString();
    int ok = 0;
    for (const AngleRow& row : f.rows) ok += row.ok() ? 1 : 0;
    return ok;
  }

  // The overlay's elbow dot (red) at `px` in the frame rendered with its overlay.
  static bool ElbowDrawnAt(const QImage& image, const cv::Point2d& px) {
    const QColor c = image.pixelColor(static_cast<int>(px.x), static_cast<int>(px.y));
    return c.red() > 200 && c.green() < 110 && c.blue() < 110;
  }
};

TEST_F(ArmPickTest, ThePickedArmIsTheOneThePlotTheTextsAndTheRobotFollow) {
  MainWindow w;
  AnalyzeBothArms(w);
  const QStringList files = w.job()->resultPaths();
  EXPECT_TRUE(QFileInfo(files[0]).fileName().endsWith(".left.tsv")) << files[0].toStdString();
  EXPECT_TRUE(QFileInfo(files[1]).fileName().endsWith(".right.tsv")) << files[1].toStdString();
  EXPECT_EQ(w.results().arms(), 2);
  auto* pick = w.anglePanel()->findChild<QComboBox*>("armPick");
  ASSERT_NE(pick, nullptr);
  EXPECT_FALSE(pick->isHidden());
  EXPECT_EQ(w.anglePanel()->arm(), 0);

  // The left arm first: the plot's curve is the left file's, and so is the robot's plan.
  EXPECT_EQ(w.plot()->pointCount(), OkRows(files[0]));
  EXPECT_EQ(w.robotPanel()->plan().angles().Meta("pose.side"), "left");

  // A frame both arms were measured in: the overlay draws each arm's elbow.
  int frame = -1;
  for (const auto& [index, m] : w.results().all()) {
    if (m.Arm(0).phase == MeasurementPhase::kOk && m.Arm(1).phase == MeasurementPhase::kOk) {
      frame = index;
      break;
    }
  }
  ASSERT_GE(frame, 0);
  w.player()->seek(frame);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == frame; }));
  const ArmMeasurement m = *w.results().at(frame);
  const QImage drawn = w.view()->renderWithOverlay();
  EXPECT_TRUE(ElbowDrawnAt(drawn, *m.Arm(0).elbow_px));
  EXPECT_TRUE(ElbowDrawnAt(drawn, *m.Arm(1).elbow_px));
  const QString left_texts = w.view()->overlayTexts().orientation;

  // The operator picks the right arm on the angle panel, with the keyboard.
  pick->setFocus();
  QTest::keyClick(pick, Qt::Key_Down);
  ASSERT_EQ(w.anglePanel()->arm(), 1);
  EXPECT_EQ(w.plot()->pointCount(), OkRows(files[1]));
  EXPECT_EQ(w.robotPanel()->plan().angles().Meta("pose.side"), "right");
  const gui::OverlayTexts right = gui::MakeOverlayTexts(&m.Arm(1), frame, w.player()->frameCount());
  EXPECT_EQ(w.view()->overlayTexts().orientation, right.orientation);
  EXPECT_NE(w.view()->overlayTexts().orientation, left_texts);

  // Back to the left arm.
  QTest::keyClick(pick, Qt::Key_Up);
  EXPECT_EQ(w.anglePanel()->arm(), 0);
  EXPECT_EQ(w.robotPanel()->plan().angles().Meta("pose.side"), "left");
  EXPECT_EQ(w.view()->overlayTexts().orientation, left_texts);
}

// With Arm set to both, Mimic live follows the arm picked on the angle panel: its angle file is
// that arm's.
TEST_F(ArmPickTest, MimicLiveFollowsThePickedArm) {
  MainWindow w;
  AnalyzeBothArms(w);
  w.anglePanel()->setArm(1);
  AngleFile f;
  ASSERT_NO_FATAL_FAILURE(RunMimicToEnd(w, &f));
  EXPECT_EQ(f.Meta("pose.side"), "right");
}

// A session keeps both arms' results: opened again, the picker and the robot follow either arm.
TEST_F(ArmPickTest, ASessionKeepsBothArms) {
  const QString session = QString::fromStdString(tmp_.file("both.armmimic"));
  int left_ok = 0, right_ok = 0;
  {
    MainWindow w;
    AnalyzeBothArms(w);
    left_ok = OkRows(w.job()->resultPaths()[0]);
    right_ok = OkRows(w.job()->resultPaths()[1]);
    ASSERT_TRUE(w.saveSession(session)) << w.log()->text().toStdString();
  }
  MainWindow w;
  w.resize(1200, 800);
  w.show();
  ASSERT_TRUE(w.openSession(session)) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && w.results().size() > 0; }));
  EXPECT_EQ(w.results().arms(), 2);
  ASSERT_EQ(w.job()->resultPaths().size(), 2);
  EXPECT_EQ(w.anglePanel()->arm(), 0);
  EXPECT_EQ(w.plot()->pointCount(), left_ok);
  EXPECT_EQ(w.robotPanel()->plan().angles().Meta("pose.side"), "left");
  w.anglePanel()->setArm(1);
  EXPECT_EQ(w.plot()->pointCount(), right_ok);
  EXPECT_EQ(w.robotPanel()->plan().angles().Meta("pose.side"), "right");
}

// Exporting a result of both arms writes a file per arm beside the name chosen.
TEST_F(ArmPickTest, ExportWritesAFilePerArm) {
  MainWindow w;
  AnalyzeBothArms(w);
  const QString target = QString::fromStdString(tmp_.file("both.tsv"));
  EXPECT_EQ(w.job()->exportResult(target), QString());
  AngleFile left, right;
  ASSERT_TRUE(ReadAngleFile(tmp_.file("both.left.tsv"), &left).ok());
  ASSERT_TRUE(ReadAngleFile(tmp_.file("both.right.tsv"), &right).ok());
  EXPECT_EQ(left.Meta("pose.side"), "left");
  EXPECT_EQ(right.Meta("pose.side"), "right");
  EXPECT_EQ(left.rows.size(), right.rows.size());
  EXPECT_FALSE(QFileInfo::exists(target));
}

}  // namespace
}  // namespace armmimic::test

#endif  // ARMMIMIC_HAVE_POSE_MODEL
