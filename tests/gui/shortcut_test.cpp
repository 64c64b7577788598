// The keyboard as an operator uses it: the one-key shortcuts yield to the widget with the focus
// when it uses the key (Space on a focused Send button presses it), Esc stops a send wherever
// the focus is, and quitting asks first while sending or with results in no saved file.
#include <memory>

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>

#include "app_actions.h"
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

class ShortcutTest : public GuiTest {
 protected:
  static void Activate(MainWindow& w) {
    QApplication::setActiveWindow(&w);
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
  }
  // Connects the Robot panel to the simulated controller; `time_scale` 1 moves in real time.
  static void Connect(MainWindow& w, double time_scale) {
    gui::RobotPanel* panel = w.robotPanel();
    w.findChild<QDockWidget*>("robotDock")->raise();
    panel->findChild<QTabWidget*>("robotTabs")->setCurrentIndex(1);
    ASSERT_TRUE(panel->startSimulator(time_scale)) << w.log()->text().toStdString();
    ASSERT_TRUE(panel->connectTo(panel->simulator()->devicePath()))
        << w.log()->text().toStdString();
  }
};

TEST_F(ShortcutTest, SpaceOnAFocusedSendButtonPressesIt) {
  MainWindow w;
  ShowAndAnalyze(w);
  Connect(w, 0.01);
  auto* send = w.robotPanel()->findChild<QPushButton*>("sendButton");
  ASSERT_TRUE(send->isEnabled());
  Activate(w);
  send->setFocus();
  ASSERT_TRUE(send->hasFocus());
  const int frame = w.view()->frameIndex();
  // Space presses the button, which asks before anything moves; the video does not play.
  const bool asked = AnswerModal<QMessageBox>([&] { QTest::keyClick(send, Qt::Key_Space); },
                                              [](QMessageBox* box) { box->reject(); });
  EXPECT_TRUE(asked);
  EXPECT_FALSE(w.player()->isPlaying());
  EXPECT_EQ(w.view()->frameIndex(), frame);
  EXPECT_FALSE(w.robotPanel()->link()->isSending());  // the question was answered "Cancel"
}

TEST_F(ShortcutTest, FocusedWidgetsKeepTheirKeysAndTheVideoGetsTheRest) {
  MainWindow w;
  ShowAndAnalyze(w);
  Activate(w);
  w.player()->seek(30);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 30; }));
  gui::RobotPanel* panel = w.robotPanel();
  w.findChild<QDockWidget*>("robotDock")->raise();

  // Space ticks a focused checkbox.
  auto* mirror = panel->findChild<QCheckBox*>("mirror");
  mirror->setFocus();
  QTest::keyClick(mirror, Qt::Key_Space);
  EXPECT_TRUE(mirror->isChecked());
  EXPECT_FALSE(w.player()->isPlaying());

  // The arrows move in a focused table, letters start editing its cell.
  auto* limits = panel->findChild<QTableWidget*>("limitsTable");
  limits->setFocus();
  limits->setCurrentCell(0, 0);
  QTest::keyClick(limits, Qt::Key_Right);
  QTest::keyClick(limits, Qt::Key_Down);
  EXPECT_EQ(limits->currentColumn(), 1);
  EXPECT_EQ(limits->currentRow(), 1);
  EXPECT_EQ(w.view()->frameIndex(), 30);

  // Down chooses the next item of a focused combo box; "h" there is no tool change.
  w.findChild<QDockWidget*>("analysisDock")->raise();
  auto* engine = w.settingsPanel()->findChild<QComboBox*>("engineCombo");
  engine->setFocus();
  const int engine_index = engine->currentIndex();
  QTest::keyClick(engine, Qt::Key_Down);
  EXPECT_EQ(engine->currentIndex(), engine_index + 1);
  w.actions()->toolRoi->trigger();
  QTest::keyClick(engine, Qt::Key_H);
  EXPECT_TRUE(w.actions()->toolRoi->isChecked());
  QTest::keyClick(engine, Qt::Key_End);
  EXPECT_EQ(w.view()->frameIndex(), 30);

  // Arrows on a focused push button are not the button's: they step the video.
  auto* rescan = panel->findChild<QPushButton*>("rescanButton");
  rescan->setFocus();
  QTest::keyClick(rescan, Qt::Key_Right);
  EXPECT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 31; }));

  // With the video focused every shortcut acts.
  w.view()->setFocus();
  QTest::keyClick(w.view(), Qt::Key_H);
  EXPECT_TRUE(w.actions()->toolPan->isChecked());
  QTest::keyClick(w.view(), Qt::Key_Left);
  EXPECT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 30; }));
  QTest::keyClick(w.view(), Qt::Key_Space);
  EXPECT_TRUE(w.player()->isPlaying());
  QTest::keyClick(w.view(), Qt::Key_Space);
  EXPECT_FALSE(w.player()->isPlaying());
}

TEST_F(ShortcutTest, EscStopsASendWhereverTheFocusIs) {
  MainWindow w;
  ShowAndAnalyze(w);
  Connect(w, 1.0);  // moves in real time: the send is still running when Esc comes
  Activate(w);
  gui::RobotPanel* panel = w.robotPanel();
  bool finished = false;
  QObject::connect(panel, &gui::RobotPanel::sendFinished, [&](bool) { finished = true; });
  ASSERT_TRUE(panel->sendPlan(true)) << w.log()->text().toStdString();
  EXPECT_TRUE(w.actions()->cancel->isEnabled());
  ASSERT_TRUE(WaitUntil([&] { return panel->link()->acknowledged() >= 2 || finished; }, 20000));
  ASSERT_FALSE(finished);
  // The focus in a text field, as when typing a port name.
  w.findChild<QDockWidget*>("analysisDock")->raise();
  auto* text = w.settingsPanel()->findChild<QLineEdit*>("backgroundPath");
  text->setFocus();
  QTest::keyClick(text, Qt::Key_Escape);
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 5000));
  EXPECT_TRUE(panel->link()->wasAborted());
  EXPECT_FALSE(w.actions()->cancel->isEnabled());
  EXPECT_LT(panel->simulator()->movesExecuted(),
            static_cast<int>(panel->plan().trajectory().keyframes.size()));
}

TEST_F(ShortcutTest, QuittingAsksFirstWithUnsavedResults) {
  MainWindow w;
  ShowAndAnalyze(w);
  EXPECT_TRUE(w.hasUnsavedResults());
  QString asked;
  auto answer = [&](QMessageBox::StandardButton b) {
    return [&asked, b](QMessageBox* box) {
      asked = box->objectName();
      box->button(b)->click();
    };
  };
  EXPECT_TRUE(AnswerModal<QMessageBox>([&] { w.close(); }, answer(QMessageBox::Cancel)));
  EXPECT_EQ(asked, "quitUnsaved");
  EXPECT_TRUE(w.isVisible());
  // Exported, the results are safe: no question.
  ASSERT_TRUE(w.exportAngles(QString::fromStdString(tmp_.file("angles.tsv"))));
  EXPECT_FALSE(w.hasUnsavedResults());
  asked.clear();
  EXPECT_FALSE(AnswerModal<QMessageBox>([&] { w.close(); }, answer(QMessageBox::Cancel)));
  EXPECT_FALSE(w.isVisible());
}

TEST_F(ShortcutTest, QuittingWhileSendingAsksAndAbortsTheSend) {
  MainWindow w;
  ShowAndAnalyze(w);
  ASSERT_TRUE(w.exportAngles(QString::fromStdString(tmp_.file("angles.tsv"))));
  Connect(w, 1.0);
  gui::RobotPanel* panel = w.robotPanel();
  bool finished = false;
  QObject::connect(panel, &gui::RobotPanel::sendFinished, [&](bool) { finished = true; });
  ASSERT_TRUE(panel->sendPlan(true));
  auto click = [](const QString& text) {
    return [text](QMessageBox* box) {
      for (QAbstractButton* b : box->buttons()) {
        if (b->text() == text || (text.isEmpty() && box->buttonRole(b) == QMessageBox::RejectRole))
          b->click();
      }
    };
  };
  EXPECT_TRUE(AnswerModal<QMessageBox>([&] { w.close(); }, click(QString())));
  EXPECT_TRUE(w.isVisible());
  EXPECT_TRUE(panel->link()->isSending());
  EXPECT_TRUE(AnswerModal<QMessageBox>([&] { w.close(); }, click("Abort and quit")));
  EXPECT_FALSE(w.isVisible());
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 5000));
  EXPECT_TRUE(panel->link()->wasAborted());
}

TEST_F(ShortcutTest, AWindowDestroyedDuringASendStopsItCleanly) {
  auto w = std::make_unique<MainWindow>();
  ShowAndAnalyze(*w);
  Connect(*w, 1.0);
  ASSERT_TRUE(w->robotPanel()->sendPlan(true));
  ASSERT_TRUE(WaitUntil([&] { return w->robotPanel()->link()->acknowledged() >= 1; }, 20000));
  w.reset();  // what a crash-free shutdown needs, without the question of closeEvent
  QTest::qWait(50);
}

}  // namespace
}  // namespace armmimic::test
