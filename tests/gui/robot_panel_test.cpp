// The robot side: plan from the analysis, see limit violations before anything moves, export
// the .val, and send to the built-in simulated controller over a pseudo-terminal.
#include <QApplication>
#include <QDockWidget>
#include <QFileInfo>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>

#include "analysis_job.h"
#include "armmimic/robot/val_program.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "robot_plan.h"
#include "robot_preview.h"
#include "sim_controller.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class RobotPanelTest : public GuiTest {
 protected:
  void Analyze(MainWindow& w) {
    ShowAndAnalyze(w);
    ASSERT_TRUE(w.robotPanel()->plan().loaded()) << w.log()->text().toStdString();
  }
};

TEST_F(RobotPanelTest, PlansExportsAndSendsToTheSimulatedController) {
  MainWindow w;
  Analyze(w);
  gui::RobotPanel* panel = w.robotPanel();
  ASSERT_TRUE(panel->plan().planned()) << w.log()->text().toStdString();
  const auto& keys = panel->plan().trajectory().keyframes;
  ASSERT_GE(keys.size(), 2u);

  const QString val = QString::fromStdString(tmp_.file("plan.val"));
  ASSERT_TRUE(panel->exportVal(val));
  // The same program `armmimic-cli plan` makes from the analysis' angle file with no flags.
  const test::CliResult cli =
      test::RunCli({"-q", "plan", panel->plan().angle_path(), "-o", tmp_.file("cli.val")});
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_EQ(test::ReadFile(val.toStdString()), test::ReadFile(tmp_.file("cli.val")));
  robot::ValProgram program;
  ASSERT_TRUE(robot::ReadValProgram(val.toStdString(), &program).ok());
  EXPECT_GE(program.lines.size(), keys.size());

  ASSERT_TRUE(panel->startSimulator(0.01)) << w.log()->text().toStdString();
  ASSERT_TRUE(panel->connectTo(panel->simulator()->devicePath())) << w.log()->text().toStdString();
  bool finished = false, ok = false;
  QObject::connect(panel, &gui::RobotPanel::sendFinished, [&](bool success) {
    finished = true;
    ok = success;
  });
  ASSERT_TRUE(panel->sendPlan(true)) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 60000));
  EXPECT_TRUE(ok) << w.log()->text().toStdString() << panel->replyLog().toStdString();
  EXPECT_EQ(panel->link()->acknowledged(), static_cast<int>(program.lines.size()));
  EXPECT_EQ(panel->simulator()->movesExecuted(), static_cast<int>(keys.size()));
  // The controller ends where the plan ends.
  ASSERT_TRUE(WaitUntil(
      [&] {
        const robot::JointArray j = panel->simulator()->joints();
        for (int k = 0; k < robot::kJoints; ++k) {
          if (std::abs(j[k] - keys.back().joint_deg[k]) > 0.02) return false;
        }
        return true;
      },
      5000));
  EXPECT_FALSE(panel->replyLog().isEmpty());
}

TEST_F(RobotPanelTest, PauseHoldsTheSendAndAbortStopsIt) {
  MainWindow w;
  Analyze(w);
  gui::RobotPanel* panel = w.robotPanel();
  ASSERT_TRUE(panel->plan().planned()) << w.log()->text().toStdString();
  ASSERT_TRUE(panel->startSimulator(1.0)) << w.log()->text().toStdString();  // real-time moves
  ASSERT_TRUE(panel->connectTo(panel->simulator()->devicePath())) << w.log()->text().toStdString();
  bool finished = false, ok = true;
  QObject::connect(panel, &gui::RobotPanel::sendFinished, [&](bool success) {
    finished = true;
    ok = success;
  });
  auto* pause = panel->findChild<QPushButton*>("pauseButton");
  auto* abort = panel->findChild<QPushButton*>("abortButton");
  ASSERT_TRUE(pause && abort);
  EXPECT_FALSE(pause->isEnabled());
  ASSERT_TRUE(panel->sendPlan(true)) << w.log()->text().toStdString();
  ASSERT_TRUE(pause->isEnabled());
  ASSERT_TRUE(WaitUntil([&] { return panel->link()->acknowledged() >= 2 || finished; }, 20000));
  ASSERT_FALSE(finished) << w.log()->text().toStdString();
  pause->click();
  EXPECT_TRUE(panel->link()->isPaused());
  // While paused nothing is acknowledged, however long the controller takes.
  const int acked = panel->link()->acknowledged();
  QTest::qWait(600);
  EXPECT_EQ(panel->link()->acknowledged(), acked);
  EXPECT_FALSE(finished);
  abort->click();
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 5000));
  EXPECT_FALSE(ok);
  // Said as what happened and how far it got, not raised as a fault.
  const int acked_at_end = panel->link()->acknowledged();
  EXPECT_NE(w.log()->text().indexOf(QRegularExpression("aborted by the operator after \\d+ of "
                                                       "\\d+ lines")),
            -1)
      << w.log()->text().toStdString();
  EXPECT_NE(w.log()->text().indexOf(QString("after %1 of").arg(acked_at_end)), -1)
      << w.log()->text().toStdString();
  EXPECT_EQ(w.log()->errorCount(), 0) << w.log()->text().toStdString();
  EXPECT_LT(panel->simulator()->movesExecuted(),
            static_cast<int>(panel->plan().trajectory().keyframes.size()));
  EXPECT_FALSE(panel->link()->isSending());
  EXPECT_FALSE(pause->isEnabled());
  EXPECT_FALSE(panel->replyLog().isEmpty());
}

TEST_F(RobotPanelTest, ViolationsAreShownBeforeAnythingMoves) {
  MainWindow w;
  Analyze(w);
  gui::RobotPanel* panel = w.robotPanel();
  robot::PlannerOptions o = panel->plannerOptions();
  // A J2 range the swinging arm leaves: the plan is refused and the preview shows it red.
  o.limits.min_deg[1] = -30;
  panel->setPlannerOptions(o);
  EXPECT_FALSE(panel->plan().planned());
  const auto bad = panel->plan().Violations(panel->plannerOptions());
  ASSERT_FALSE(bad.empty());
  panel->setVideoFrame(bad.front().frame);
  EXPECT_TRUE(panel->preview()->violatingJoints().contains(1));
  // The refusal is noted (not raised as an error) while planning, and is the error on sending.
  EXPECT_EQ(w.log()->errorCount(), 0) << w.log()->text().toStdString();
  EXPECT_NE(w.log()->text().indexOf("Robot plan not made"), -1) << w.log()->text().toStdString();
  EXPECT_FALSE(panel->sendPlan(true));
  EXPECT_EQ(w.log()->errorCount(), 1);
  EXPECT_NE(w.log()->text().indexOf("Nothing to send: the plan was refused: "), -1)
      << w.log()->text().toStdString();
  // Named by the video analysed, not by the temporary angle file behind the plan.
  EXPECT_NE(w.log()->text().indexOf("the analysis of scene.avi: "), -1)
      << w.log()->text().toStdString();
  EXPECT_EQ(w.log()->text().indexOf(QString::fromStdString(panel->plan().angle_path())), -1)
      << w.log()->text().toStdString();
  // Nothing was sent, nothing connected.
  EXPECT_FALSE(panel->link()->isSending());
}

TEST_F(RobotPanelTest, ALimitThatIsNotANumberIsPutBack) {
  MainWindow w;
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  Analyze(w);
  gui::RobotPanel* panel = w.robotPanel();
  ASSERT_TRUE(panel->plan().planned()) << w.log()->text().toStdString();
  auto* table = panel->findChild<QTableWidget*>("limitsTable");
  ASSERT_NE(table, nullptr);
  w.findChild<QDockWidget*>("robotDock")->raise();
  panel->findChild<QTabWidget*>("robotTabs")->setCurrentIndex(0);  // Plan
  ASSERT_TRUE(WaitUntil([&] { return table->isVisible(); }, 2000));
  // Type into the J2 max cell as the operator does: double-click, type, Return.
  auto type_into = [&](int row, int column, const QString& text) {
    QTableWidgetItem* item = table->item(row, column);
    table->scrollToItem(item);
    table->setCurrentItem(item);
    table->editItem(item);
    auto* editor = qobject_cast<QLineEdit*>(QApplication::focusWidget());
    ASSERT_NE(editor, nullptr);
    ASSERT_TRUE(table->isAncestorOf(editor));
    editor->selectAll();
    QTest::keyClicks(editor, text);
    QTest::keyClick(editor, Qt::Key_Return);
    QTest::qWait(20);  // the delegate commits on the next turn of the event loop
  };
  type_into(1, 1, "abc");
  // Read as 0 before: J2 max 0 refused the plan with a message about frames, not the typing.
  EXPECT_EQ(table->item(1, 1)->text(), "20");
  EXPECT_EQ(panel->plannerOptions().limits.max_deg[1], 20);
  EXPECT_TRUE(panel->plan().planned());
  EXPECT_NE(w.log()->text().indexOf("'abc' is not a number; J2 max ° stays 20"), -1)
      << w.log()->text().toStdString();
  type_into(1, 1, "15");
  EXPECT_EQ(panel->plannerOptions().limits.max_deg[1], 15);
}

TEST_F(RobotPanelTest, PreviewCaptionHasItsOwnRow) {
  gui::RobotPreview preview;
  preview.setPose({0, -45, -30, 0, 0, 0}, "frame 170 (mapped, unfiltered)");
  preview.show();
  for (const QSize size : {QSize(240, 140), QSize(396, 170), QSize(400, 320)}) {
    SCOPED_TRACE(size.width());
    preview.resize(size);
    // The caption sat on the top view's circle; now the views end above it.
    EXPECT_GT(preview.drawingArea().height(), 50);
    EXPECT_LE(preview.drawingArea().bottom(), preview.captionArea().top());
    EXPECT_LE(preview.captionArea().bottom(), preview.valuesArea().top());
    EXPECT_LE(preview.valuesArea().bottom(), preview.height());
  }
}

}  // namespace
}  // namespace armmimic::test
