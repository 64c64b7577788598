// Plans and journals that outlive the window: a send writes its plan beside the session (or the
// video) and keeps the journal beside it, so a new window, as after a restart, finds the
// interrupted send when it opens the session or the plan, and Resume… says what is left. Esc
// aborts a send right after its confirmation, without a click on the window first.
// Length: the journal test walks one story (send, abort, new window, reopen, resume summary)
// whose steps depend on each other.
#include <QApplication>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QTest>

#include "analysis_job.h"
#include "armmimic/robot/journal.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "robot_plan.h"
#include "sim_controller.h"
#include "video_player.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;
using gui::RobotPanel;

class PlanJournalTest : public GuiTest {
 protected:
  static QPushButton* Button(RobotPanel* panel, const char* name) {
    return panel->findChild<QPushButton*>(name);
  }
  // Clicks `button` and answers the question it asks with the button of `role`; returns the
  // question's object name and text.
  static QString ClickAndAnswer(QPushButton* button, QMessageBox::ButtonRole role,
                                QString* name = nullptr) {
    QString text;
    const bool asked = AnswerModal<QMessageBox>([&] { button->click(); },
                                                [&](QMessageBox* box) {
                                                  if (name) *name = box->objectName();
                                                  text =
                                                      box->text() + "\n" + box->informativeText();
                                                  for (QAbstractButton* b : box->buttons()) {
                                                    if (box->buttonRole(b) == role) b->click();
                                                  }
                                                });
    EXPECT_TRUE(asked);
    return text;
  }
  // Esc as the operator presses it: to whatever window is active, at its focused widget.
  static void PressEsc() {
    QWidget* active = QApplication::activeWindow();
    ASSERT_NE(active, nullptr) << "no window has the focus after the confirmation";
    QTest::keyClick(active, Qt::Key_Escape);
  }
  static void Connect(RobotPanel* panel, double time_scale) {
    ASSERT_TRUE(panel->startSimulator(time_scale));
    ASSERT_TRUE(panel->connectTo(panel->simulator()->devicePath()));
  }
};

TEST_F(PlanJournalTest, EscAbortsASendRightAfterTheConfirmation) {
  MainWindow w;
  ShowAndAnalyze(w);
  RobotPanel* panel = w.robotPanel();
  Connect(panel, 1.0);  // real time: the send is still running when Esc comes
  QApplication::setActiveWindow(&w);
  ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
  bool finished = false;
  QObject::connect(panel, &RobotPanel::sendFinished, [&](bool) { finished = true; });
  ClickAndAnswer(Button(panel, "sendButton"), QMessageBox::AcceptRole);
  ASSERT_TRUE(panel->link()->isSending()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return QApplication::activeWindow() == &w; }, 2000));
  PressEsc();
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 5000));
  EXPECT_TRUE(panel->link()->wasAborted());
  EXPECT_LT(panel->simulator()->movesExecuted(),
            static_cast<int>(panel->plan().trajectory().keyframes.size()));
}

TEST_F(PlanJournalTest, TheJournalBesideThePlanOutlivesTheWindowAndResumeSaysWhatIsLeft) {
  const QString session = QString::fromStdString(tmp_.file("walk.armmimic"));
  const QString val = QString::fromStdString(tmp_.file("walk.val"));
  const std::string journal = robot::SendJournal::PathFor(val.toStdString());
  // The controller outlives the application, as a robot's does: both windows connect to it.
  gui::SimController controller;
  QString error;
  ASSERT_TRUE(controller.start(0.3, robot::JointLimits(), &error)) << error.toStdString();
  {
    MainWindow w;
    ShowAndAnalyze(w);
    ASSERT_TRUE(w.saveSession(session)) << w.log()->text().toStdString();
    RobotPanel* panel = w.robotPanel();
    EXPECT_EQ(panel->planFile(), val);
    ASSERT_TRUE(panel->connectTo(controller.devicePath())) << w.log()->text().toStdString();
    QApplication::setActiveWindow(&w);
    bool finished = false;
    QObject::connect(panel, &RobotPanel::sendFinished, [&](bool) { finished = true; });
    ClickAndAnswer(Button(panel, "sendButton"), QMessageBox::AcceptRole);
    ASSERT_TRUE(WaitUntil([&] { return panel->link()->acknowledged() >= 3 || finished; }, 20000));
    ASSERT_FALSE(finished) << w.log()->text().toStdString();
    PressEsc();
    ASSERT_TRUE(WaitUntil([&] { return finished; }, 5000));
    // The plan and its journal lie beside the session, and the messages name them.
    EXPECT_TRUE(QFileInfo::exists(val));
    EXPECT_TRUE(QFileInfo::exists(QString::fromStdString(journal)));
    EXPECT_NE(w.log()->text().indexOf(val), -1) << w.log()->text().toStdString();
    EXPECT_EQ(w.log()->text().indexOf("plan.val"), -1) << w.log()->text().toStdString();
  }
  robot::JournalState state;
  ASSERT_TRUE(robot::SendJournal::Read(journal, &state).ok());
  ASSERT_TRUE(state.exists);
  EXPECT_FALSE(state.done);

  // The plan itself, opened in a fresh window, offers the resume too.
  {
    MainWindow w;
    w.show();
    ASSERT_TRUE(w.robotPanel()->setValProgram(val)) << w.log()->text().toStdString();
    EXPECT_TRUE(w.robotPanel()->resumeOffered()) << w.log()->text().toStdString();
  }

  // A new window, as after a restart: opening the session offers Resume….
  MainWindow w;
  w.resize(1200, 800);
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  ASSERT_TRUE(w.openSession(session)) << w.log()->text().toStdString();
  RobotPanel* panel = w.robotPanel();
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && panel->plan().planned(); }));
  EXPECT_TRUE(panel->resumeOffered()) << w.log()->text().toStdString();
  EXPECT_NE(w.log()->text().indexOf(QString::fromStdString(journal)), -1)
      << w.log()->text().toStdString();
  ASSERT_TRUE(panel->connectTo(controller.devicePath())) << w.log()->text().toStdString();
  bool finished = false, ok = false;
  QObject::connect(panel, &RobotPanel::sendFinished, [&](bool success) {
    finished = true;
    ok = success;
  });
  // The confirmation covers what is left: how many lines, how long, and where the arm must be.
  const QString confirm = ClickAndAnswer(Button(panel, "resumeButton"), QMessageBox::AcceptRole);
  const QRegularExpressionMatch m =
      QRegularExpression("Resume at walk\\.val:\\d+: send the (\\d+) of (\\d+) lines still to send")
          .match(confirm);
  ASSERT_TRUE(m.hasMatch()) << confirm.toStdString();
  EXPECT_EQ(m.captured(1).toInt(), m.captured(2).toInt() - state.acknowledged);
  EXPECT_NE(confirm.indexOf("The arm must stand where the acknowledged lines left it: J1"), -1)
      << confirm.toStdString();
  EXPECT_NE(confirm.indexOf(" s, resuming at walk.val:"), -1) << confirm.toStdString();
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 60000)) << w.log()->text().toStdString();
  EXPECT_TRUE(ok) << w.log()->text().toStdString();
  ASSERT_TRUE(robot::SendJournal::Read(journal, &state).ok());
  EXPECT_TRUE(state.done);

  // Another plan is not written over the file without asking; Cancel leaves it as it was.
  QFile before(val);
  ASSERT_TRUE(before.open(QIODevice::ReadOnly));
  const QByteArray old_text = before.readAll();
  panel->findChild<QDoubleSpinBox*>("cutoff")->setValue(
      panel->findChild<QDoubleSpinBox*>("cutoff")->value() + 1.0);
  QString asked;
  ClickAndAnswer(Button(panel, "sendButton"), QMessageBox::RejectRole, &asked);
  EXPECT_EQ(asked, "replacePlan");
  QFile after(val);
  ASSERT_TRUE(after.open(QIODevice::ReadOnly));
  EXPECT_EQ(after.readAll(), old_text);
  EXPECT_FALSE(panel->link()->isSending());
}

}  // namespace
}  // namespace armmimic::test
