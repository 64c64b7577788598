// The smaller things an operator trips over: the status bar after an analysis, the per-frame
// status in words, keypoint scores that do not overlap, fields the engine does not read greyed,
// and the 3-D view following the simulated controller's connection.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFontMetricsF>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QTest>
#include <QToolButton>

#include "analysis_job.h"
#include "arm_view_3d.h"
#include "engine_settings_panel.h"
#include "field_error.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "score_labels.h"
#include "sim_controller.h"
#include "status_line.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class OperatorDetailsTest : public GuiTest {};

TEST_F(OperatorDetailsTest, TheStatusBarAndTheFrameStatusSpeakOfTheAnalysisJustDone) {
  MainWindow w;
  w.resize(1200, 800);
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  const GuiScenes& s = scenes();
  w.openInputs({QString::fromStdString(s.video())});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
  w.player()->seek(45);  // in the motion
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 45; }));
  EXPECT_NE(w.statusLine()->frameText().indexOf("not analysed"), -1)
      << w.statusLine()->frameText().toStdString();
  w.settingsPanel()->setOptions(s.BgsubProtocol());
  ASSERT_TRUE(w.startAnalysis());
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
  // Without stepping a frame: the status bar already reads this frame's result.
  const QString status = w.statusLine()->frameText();
  EXPECT_EQ(status.indexOf("not analysed"), -1) << status.toStdString();
  // In words, with the confidence: "ok: both segments fit; confidence 0.92".
  const QString state = w.view()->overlayTexts().state;
  EXPECT_TRUE(state.startsWith("ok: ")) << state.toStdString();
  EXPECT_NE(state.indexOf("fit"), -1) << state.toStdString();
  EXPECT_TRUE(QRegularExpression("; confidence [01]\\.\\d\\d$").match(state).hasMatch())
      << state.toStdString();
  EXPECT_EQ(state.indexOf(" u "), -1) << state.toStdString();
  EXPECT_NE(status.indexOf(state), -1) << status.toStdString();
}

TEST_F(OperatorDetailsTest, KeypointScoresNeverOverlap) {
  // The face's five keypoints a few pixels apart, as in a person far from the camera, and two
  // arm joints on top of each other.
  const std::vector<QPointF> dots = {{100, 50}, {103, 48}, {97, 48},  {106, 50},
                                     {94, 50},  {120, 90}, {121, 91}, {80, 90}};
  const std::vector<double> scores = {0.41, 0.5, 0.51, 0.3, 0.35, 0.92, 0.88, 0.7};
  QFont font;
  font.setPointSizeF(5.0);
  const QFontMetricsF metrics(font);
  const auto labels = gui::PlaceScoreLabels(dots, scores, metrics, 1.0);
  ASSERT_EQ(labels.size(), dots.size());
  std::vector<QRectF> placed;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (!labels[i]) continue;
    EXPECT_EQ(labels[i]->text, QString::number(scores[i], 'f', 2));
    for (const QRectF& r : placed) EXPECT_FALSE(r.intersects(labels[i]->rect)) << i;
    for (const QPointF& d : dots) EXPECT_FALSE(labels[i]->rect.contains(d)) << i;
    placed.push_back(labels[i]->rect);
  }
  // The best-scored keypoints are labelled; the lone one always.
  EXPECT_TRUE(labels[5].has_value());
  EXPECT_TRUE(labels[7].has_value());
  EXPECT_GE(placed.size(), 5u);
}

TEST_F(OperatorDetailsTest, EveryFieldTheEngineDoesNotReadIsGreyed) {
  MainWindow w;
  w.show();
  auto* engine = w.settingsPanel()->findChild<QComboBox*>("engineCombo");
  auto* background = w.settingsPanel()->findChild<QLineEdit*>("backgroundPath");
  ASSERT_NE(background, nullptr);
  QToolButton* browse = background->parentWidget()->findChild<QToolButton*>();
  ASSERT_NE(browse, nullptr);
  auto* mode = w.settingsPanel()->findChild<QComboBox*>("backgroundMode");
  mode->setCurrentIndex(0);  // a background image
  engine->setCurrentIndex(engine->findData(int(EngineKind::kBgsub)));
  EXPECT_TRUE(background->isEnabled());
  EXPECT_TRUE(browse->isEnabled());
  engine->setCurrentIndex(engine->findData(int(EngineKind::kPose)));
  EXPECT_FALSE(mode->isEnabled());
  EXPECT_FALSE(background->isEnabled());
  EXPECT_FALSE(browse->isEnabled());
  EXPECT_FALSE(w.settingsPanel()->findChild<QLineEdit*>("armLengthPath")->isEnabled());
}

TEST_F(OperatorDetailsTest, TheThreeDViewFollowsTheSimulatedControllersConnection) {
  MainWindow w;
  ShowAndAnalyze(w);
  gui::RobotPanel* panel = w.robotPanel();
  auto* sim = panel->findChild<QPushButton*>("simButton");
  sim->click();  // starts and connects
  ASSERT_TRUE(WaitUntil([&] { return panel->link()->isConnected(); }, 5000));
  EXPECT_TRUE(panel->findChild<QPushButton*>("sendButton")->isEnabled());
  ASSERT_TRUE(
      WaitUntil([&] { return panel->view3d()->caption() == "simulated controller"; }, 5000));
  sim->click();  // stops
  EXPECT_FALSE(panel->simulator()->isRunning());
  EXPECT_FALSE(panel->link()->isConnected());
  QTest::qWait(150);  // a poll would have come by now
  EXPECT_NE(panel->view3d()->caption(), "simulated controller");
  EXPECT_TRUE(panel->view3d()->caption().startsWith("frame") ||
              panel->view3d()->caption().startsWith("plan"))
      << panel->view3d()->caption().toStdString();
}

TEST_F(OperatorDetailsTest, ARefusedPlanIsToldInThePanelsWordsAtItsField) {
  MainWindow w;
  ShowAndAnalyze(w);
  gui::RobotPanel* panel = w.robotPanel();
  ASSERT_TRUE(panel->plan().planned());
  // 29 Hz on a 30 fps video: above half the frame rate, refused by the planner (its key
  // planner.cutoff_hz), which the panel words with the field's label.
  auto* cutoff = panel->findChild<QDoubleSpinBox*>("cutoff");
  ASSERT_NE(cutoff, nullptr);
  cutoff->setValue(29);
  ASSERT_FALSE(panel->plan().planned()) << w.log()->text().toStdString();
  const QString label = gui::FieldLabel(cutoff);
  EXPECT_NE(w.log()->text().indexOf("Robot plan not made: " + label + ": "), -1)
      << w.log()->text().toStdString();
  EXPECT_EQ(w.log()->text().indexOf("--cutoff"), -1) << w.log()->text().toStdString();
  EXPECT_FALSE(gui::HasFieldError(cutoff));  // planning on its own frames nothing
  EXPECT_FALSE(panel->sendPlan(true));       // the operator asks: the field is framed
  EXPECT_TRUE(gui::HasFieldError(cutoff));
  EXPECT_NE(w.log()->text().indexOf("the plan was refused: " + label), -1)
      << w.log()->text().toStdString();
}

}  // namespace
}  // namespace armmimic::test
