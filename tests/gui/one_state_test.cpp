// One state on screen and in the Robot panel: a failed start changes nothing the panel would
// send, a run in progress leaves nothing to send until its plan is made, and quitting during an
// analysis asks first and keeps the rows so far as an incomplete angle file.
#include <QAction>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTest>

#include "analysis_job.h"
#include "angle_plot.h"
#include "app_actions.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/synth/arm_scene.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "sim_controller.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class OneStateTest : public GuiTest {
 protected:
  static QPushButton* Button(MainWindow& w, const char* name) {
    return w.robotPanel()->findChild<QPushButton*>(name);
  }
  // What the Robot panel would send: its .val text with the built-in profile.
  static std::string PlanText(MainWindow& w) {
    std::string text;
    EXPECT_TRUE(w.robotPanel()->plan().ValText(w.robotPanel()->profile(), &text).ok());
    return text;
  }
};

TEST_F(OneStateTest, AFailedStartKeepsTheAnglesOverlayPlotAndPlan) {
  MainWindow w;
  ShowAndAnalyze(w);
  gui::RobotPanel* panel = w.robotPanel();
  ASSERT_TRUE(panel->plan().planned()) << w.log()->text().toStdString();
  Button(w, "simButton")->click();
  ASSERT_TRUE(panel->simulator()->isRunning()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return panel->link()->isConnected(); }, 5000))
      << "Start simulated controller connects";
  ASSERT_TRUE(Button(w, "sendButton")->isEnabled());
  w.player()->seek(40);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 40; }));
  const QString overlay_before = w.view()->overlayTexts().orientation;
  ASSERT_FALSE(overlay_before.isEmpty());
  const std::string plan_before = PlanText(w);
  const QString result_before = w.job()->resultPath();
  const int points_before = w.plot()->pointCount();
  const int rows_before = w.results().rows();
  ASSERT_GT(points_before, 0);

  // The arm-length image set to a missing file in its field, then F5.
  auto* arm_length = w.settingsPanel()->findChild<QLineEdit*>("armLengthPath");
  ASSERT_NE(arm_length, nullptr);
  arm_length->setText(QString::fromStdString(tmp_.file("no-arm.png")));
  w.activateWindow();
  QTest::keyClick(&w, Qt::Key_F5);
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 30000));
  EXPECT_NE(w.log()->text().indexOf("no-arm.png"), -1) << w.log()->text().toStdString();

  EXPECT_EQ(w.plot()->pointCount(), points_before);
  EXPECT_EQ(w.results().rows(), rows_before);
  EXPECT_EQ(w.job()->resultPath(), result_before);
  ASSERT_TRUE(panel->plan().planned());
  EXPECT_EQ(PlanText(w), plan_before);
  EXPECT_TRUE(Button(w, "sendButton")->isEnabled());
  EXPECT_EQ(w.view()->overlayTexts().orientation, overlay_before) << "the overlay still shows";

  // A run that starts: nothing may be sent until the plan of its angles is made.
  arm_length->setText(QString::fromStdString(scenes().arm_length()));
  ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
  EXPECT_FALSE(Button(w, "sendButton")->isEnabled());
  EXPECT_FALSE(panel->sendPlan(true));
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
  EXPECT_NE(w.job()->resultPath(), result_before);
  EXPECT_EQ(panel->plan().angle_path(), w.job()->resultPath().toStdString());
  EXPECT_TRUE(Button(w, "sendButton")->isEnabled());
}

TEST_F(OneStateTest, QuittingDuringAnAnalysisAsksAndKeepsTheRowsAsIncomplete) {
  // A scene long enough for the analysis to be running when the question is answered.
  synth::ArmSceneOptions o;
  o.seed = 11;
  o.background_frames = 10;
  o.standstill_frames = 20;
  o.motion_frames = 3000;
  o.motion = synth::ArmMotion::kSwing;
  const std::string dir = tmp_.file("long");
  ASSERT_TRUE(synth::WriteArmScene(o, dir, {}).ok());
  MainWindow w;
  w.resize(1000, 700);
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  w.openInputs({QString::fromStdString(dir + "/scene.avi")});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
  AnalysisOptions a;
  a.engine.kind = EngineKind::kBgsub;
  a.background_path = dir + "/background.png";
  a.arm_length_path = dir + "/armlength.png";
  a.start = o.background_frames;
  a.engine.bgsub.standstill_frames = o.standstill_frames;
  w.settingsPanel()->setOptions(a);
  ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return w.results().rows() > 50; }, 30000));

  QString asked, details;
  auto click = [&](const QString& text) {
    return [&asked, &details, text](QMessageBox* box) {
      asked = box->objectName();
      details = box->informativeText();
      for (QAbstractButton* b : box->buttons()) {
        if (b->text() == text || (text.isEmpty() && box->buttonRole(b) == QMessageBox::RejectRole))
          b->click();
      }
    };
  };
  // Ctrl+Q asks; Cancel goes on analysing.
  EXPECT_TRUE(AnswerModal<QMessageBox>([&] { w.actions()->quit->trigger(); }, click(QString())));
  EXPECT_EQ(asked, "quitDuringAnalysis");
  EXPECT_TRUE(w.isVisible());
  EXPECT_TRUE(w.job()->isRunning());
  // Quit anyway: the rows so far go beside the video, marked incomplete.
  const std::string kept = dir + "/scene-incomplete.tsv";
  EXPECT_NE(details.indexOf(QString::fromStdString(kept)), -1) << details.toStdString();
  EXPECT_TRUE(AnswerModal<QMessageBox>([&] { w.actions()->quit->trigger(); },
                                       click("Keep the rows and quit")));
  EXPECT_FALSE(w.isVisible());
  EXPECT_FALSE(w.job()->isRunning());
  AngleFile file;
  ASSERT_TRUE(ReadAngleFile(kept, &file).ok()) << kept;
  EXPECT_FALSE(file.complete);
  EXPECT_GT(file.rows.size(), 50u);
  EXPECT_LT(file.rows.size(), static_cast<size_t>(o.standstill_frames + o.motion_frames));
}

}  // namespace
}  // namespace armmimic::test
