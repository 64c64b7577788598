// The robot panel's Controller tab against the CLI's `send`: port settings, the controller
// profile, the confirmation before anything moves, and resume from the journal after a dropped
// link, all over a real pseudo-terminal to the built-in simulated controller.
#include <cmath>

#include <termios.h>

#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTabWidget>
#include <QTest>

#include "armmimic/robot/journal.h"
#include "armmimic/serial/serial_link.h"
#include "controller_settings.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "robot_plan.h"
#include "sim_controller.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class RobotSendTest : public GuiTest {
 protected:
  // Analyses the arm scene, starts the simulated controller (`time_scale` 1: real time) and
  // shows the Controller tab.
  void Prepare(MainWindow& w, double time_scale) {
    ShowAndAnalyze(w);
    panel_ = w.robotPanel();
    ASSERT_TRUE(panel_->plan().planned()) << w.log()->text().toStdString();
    w.findChild<QDockWidget*>("robotDock")->raise();
    panel_->findChild<QTabWidget*>("robotTabs")->setCurrentIndex(1);
    ASSERT_TRUE(panel_->startSimulator(time_scale)) << w.log()->text().toStdString();
  }
  void Connect(MainWindow& w) {
    ASSERT_TRUE(panel_->connectTo(panel_->simulator()->devicePath()))
        << w.log()->text().toStdString();
  }
  QPushButton* Button(const char* name) { return panel_->findChild<QPushButton*>(name); }
  QComboBox* Combo(const char* name) { return panel_->findChild<QComboBox*>(name); }
  static void Pick(QComboBox* combo, const QVariant& data) {
    const int i = combo->findData(data);
    ASSERT_GE(i, 0) << combo->objectName().toStdString();
    combo->setCurrentIndex(i);
  }
  // Clicks `button` and answers the confirmation with "Move the robot"; returns its text.
  QString ClickAndConfirm(QPushButton* button) {
    QString text;
    const bool asked =
        AnswerModal<QMessageBox>([&] { button->click(); },
                                 [&](QMessageBox* box) {
                                   text = box->text() + "\n" + box->informativeText();
                                   for (QAbstractButton* b : box->buttons()) {
                                     if (box->buttonRole(b) == QMessageBox::AcceptRole) b->click();
                                   }
                                 });
    EXPECT_TRUE(asked);
    return text;
  }
  bool JointsNear(const robot::JointArray& a, const robot::JointArray& b, double tol) {
    for (int k = 0; k < robot::kJoints; ++k) {
      if (std::abs(a[k] - b[k]) > tol) return false;
    }
    return true;
  }
  gui::RobotPanel* panel_ = nullptr;
};

TEST_F(RobotSendTest, PortSettingsReachThePort) {
  MainWindow w;
  Prepare(w, 0.05);
  // A pseudo-terminal always carries 8 bits without parity, so 7E reaches the port and is
  // refused there, naming the setting; nothing is connected.
  Pick(Combo("dataBitsCombo"), 7);
  Pick(Combo("parityCombo"), QChar('E'));
  Button("connectButton")->click();
  EXPECT_FALSE(panel_->link()->isConnected());
  // In the panel's words: its label, not the CLI's flag.
  EXPECT_NE(w.log()->text().indexOf("Data bits: "), -1) << w.log()->text().toStdString();
  EXPECT_NE(w.log()->text().indexOf("refused the data bits 7"), -1)
      << w.log()->text().toStdString();

  Pick(Combo("dataBitsCombo"), 8);
  Pick(Combo("parityCombo"), QChar('N'));
  Pick(Combo("baudCombo"), 19200);
  Pick(Combo("stopBitsCombo"), 2);
  Pick(Combo("flowCombo"), int(serial::FlowControl::kXonXoff));
  Button("connectButton")->click();
  ASSERT_TRUE(panel_->link()->isConnected()) << w.log()->text().toStdString();
  const serial::PortSettings& p = panel_->link()->portSettings();
  EXPECT_EQ(p.port, panel_->simulator()->devicePath().toStdString());
  EXPECT_EQ(p.baud, 19200);
  EXPECT_EQ(p.data_bits, 8);
  EXPECT_EQ(p.parity, 'N');
  EXPECT_EQ(p.stop_bits, 2);
  EXPECT_EQ(p.flow, serial::FlowControl::kXonXoff);
  // What the device itself holds now (the terminal's settings, read back from the kernel).
  termios t{};
  ASSERT_EQ(tcgetattr(static_cast<int>(panel_->link()->serialLink()->native_handle()), &t), 0);
  EXPECT_EQ(cfgetospeed(&t), static_cast<speed_t>(B19200));
  EXPECT_TRUE(t.c_cflag & CSTOPB);
  EXPECT_TRUE(t.c_iflag & IXON);
  EXPECT_FALSE(t.c_cflag & CRTSCTS);
  // While connected the port's settings are fixed; disconnected they can change again.
  EXPECT_FALSE(Combo("stopBitsCombo")->isEnabled());
  Button("connectButton")->click();
  EXPECT_FALSE(panel_->link()->isConnected());
  EXPECT_TRUE(Combo("stopBitsCombo")->isEnabled());
}

TEST_F(RobotSendTest, TheProfilePickedChangesWhatIsSent) {
  MainWindow w;
  Prepare(w, 0.01);
  Connect(w);
  const std::string profile = tmp_.file("upload.profile");
  WriteFile(profile, "name = upload-test\nmode = program\nprogram_name = GUIPROF\n");
  // Open… picks the file; the picker then shows it.
  const bool asked = AnswerModal<QFileDialog>([&] { Button("profileButton")->click(); },
                                              [&](QFileDialog* d) {
                                                // The path typed into the file name field, then
                                                // Return.
                                                auto* edit =
                                                    d->findChild<QLineEdit*>("fileNameEdit");
                                                if (edit) {
                                                  edit->setText(QString::fromStdString(profile));
                                                  QTest::keyClick(edit, Qt::Key_Return);
                                                }
                                                if (d->isVisible()) d->reject();  // never left open
                                              });
  ASSERT_TRUE(asked);
  EXPECT_EQ(Combo("profileCombo")->currentText(), "upload.profile");
  EXPECT_EQ(panel_->controllerSettings()->sendSettings().profile_path, profile);
  bool finished = false, ok = false;
  QObject::connect(panel_, &gui::RobotPanel::sendFinished, [&](bool success) {
    finished = true;
    ok = success;
  });
  ASSERT_TRUE(panel_->sendPlan(true)) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 60000));
  ASSERT_TRUE(ok) << w.log()->text().toStdString() << panel_->replyLog().toStdString();
  // The program was uploaded and run, as the profile says, and every move ran once.
  EXPECT_NE(panel_->replyLog().indexOf("EDIT GUIPROF"), -1) << panel_->replyLog().toStdString();
  EXPECT_NE(panel_->replyLog().indexOf("EXECUTE GUIPROF"), -1) << panel_->replyLog().toStdString();
  const auto& keys = panel_->plan().trajectory().keyframes;
  EXPECT_EQ(panel_->simulator()->movesExecuted(), static_cast<int>(keys.size()));

  // The built-in profile streams DO MOVE lines instead.
  QTest::keyClick(Combo("profileCombo"), Qt::Key_Home);  // the first entry: built in
  EXPECT_EQ(Combo("profileCombo")->currentIndex(), 0);
  EXPECT_TRUE(panel_->controllerSettings()->sendSettings().profile_path.empty());
  ASSERT_TRUE(panel_->exportVal(QString::fromStdString(tmp_.file("stream.val"))));
  const std::string stream = ReadFile(tmp_.file("stream.val"));
  EXPECT_NE(stream.find("DO MOVE #PPOINT("), std::string::npos);
  EXPECT_EQ(stream.find("EDIT"), std::string::npos);

  // A profile with a bad line is named with its line, and the choice stays as it was.
  WriteFile(tmp_.file("bad.profile"), "name = bad\nmode = sideways\n");
  EXPECT_FALSE(panel_->controllerSettings()->setProfileFile(
      QString::fromStdString(tmp_.file("bad.profile"))));
  EXPECT_NE(w.log()->text().indexOf("bad.profile:2"), -1) << w.log()->text().toStdString();
  EXPECT_EQ(Combo("profileCombo")->currentIndex(), 0);
}

TEST_F(RobotSendTest, TheConfirmationShowsDurationStartPoseAndRanges) {
  MainWindow w;
  Prepare(w, 0.01);
  Connect(w);
  QString text;
  const bool asked = AnswerModal<QMessageBox>([&] { Button("sendButton")->click(); },
                                              [&](QMessageBox* box) {
                                                text = box->text() + "\n" + box->informativeText();
                                                box->button(QMessageBox::Cancel)->click();
                                              });
  ASSERT_TRUE(asked);
  const robot::Trajectory& t = panel_->plan().trajectory();
  const double duration = t.duration_s();  // the first keyframe is at 0
  EXPECT_NE(text.indexOf(QString("about %1 s").arg(duration, 0, 'f', 1)), -1) << text.toStdString();
  const robot::JointArray& first = t.keyframes.front().joint_deg;
  EXPECT_NE(text.indexOf(QString("Start pose (the first target): J1 %1 J2 %2")
                             .arg(std::round(first[0] * 10) / 10 + 0.0, 0, 'f', 1)
                             .arg(std::round(first[1] * 10) / 10 + 0.0, 0, 'f', 1)),
            -1)
      << text.toStdString();
  for (const char* limits :
       {"(limits -160 .. 160)", "(limits -200 .. 20)", "(limits -225 .. 45)"}) {
    EXPECT_NE(text.indexOf(limits), -1) << text.toStdString();
  }
  // Cancel moves nothing.
  QTest::qWait(200);
  EXPECT_EQ(panel_->simulator()->movesExecuted(), 0);
  EXPECT_FALSE(panel_->link()->isSending());
}

TEST_F(RobotSendTest, ADroppedSendResumesFromTheJournalToTheSameFinalPose) {
  MainWindow w;
  Prepare(w, 0.3);  // moves slow enough for the link to drop mid-send
  Connect(w);
  const auto& keys = panel_->plan().trajectory().keyframes;
  ASSERT_GE(keys.size(), 5u);
  bool finished = false, ok = false;
  QObject::connect(panel_, &gui::RobotPanel::sendFinished, [&](bool success) {
    finished = true;
    ok = success;
  });
  ClickAndConfirm(Button("sendButton"));
  ASSERT_TRUE(WaitUntil([&] { return panel_->link()->acknowledged() >= 3 || finished; }, 20000));
  ASSERT_FALSE(finished) << w.log()->text().toStdString();
  Button("connectButton")->click();  // the link drops: Disconnect mid-send
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 5000));
  EXPECT_FALSE(ok);
  EXPECT_NE(w.log()->text().indexOf("Resume continues"), -1) << w.log()->text().toStdString();
  EXPECT_LT(panel_->simulator()->movesExecuted(), static_cast<int>(keys.size()));

  // Send from the top with the journal unfinished is refused, naming the choice.
  Button("connectButton")->click();
  ASSERT_TRUE(panel_->link()->isConnected()) << w.log()->text().toStdString();
  EXPECT_FALSE(panel_->sendPlan(true));
  EXPECT_NE(w.log()->text().indexOf("stopped after"), -1) << w.log()->text().toStdString();

  finished = false;
  const QString confirm = ClickAndConfirm(Button("resumeButton"));
  // The plan was written beside the video before the send, and is named as that file.
  EXPECT_NE(confirm.indexOf("resuming at scene.val:"), -1) << confirm.toStdString();
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 60000)) << w.log()->text().toStdString();
  ASSERT_TRUE(ok) << w.log()->text().toStdString() << panel_->replyLog().toStdString();
  // The move in flight when the link dropped was settled by asking the arm.
  EXPECT_NE(w.log()->text().indexOf("WHERE shows the arm"), -1) << w.log()->text().toStdString();
  // Every planned move ran exactly once, and the arm ends at the plan's last pose.
  EXPECT_EQ(panel_->simulator()->movesExecuted(), static_cast<int>(keys.size()))
      << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil(
      [&] { return JointsNear(panel_->simulator()->joints(), keys.back().joint_deg, 0.02); },
      5000));
  const robot::JointArray resumed_end = panel_->simulator()->joints();

  // The same plan sent without interruption to a fresh controller ends at the same pose.
  panel_->link()->disconnectPort();
  ASSERT_TRUE(panel_->startSimulator(0.01));
  Connect(w);
  finished = false;
  ASSERT_TRUE(panel_->sendPlan(true)) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 60000));
  ASSERT_TRUE(ok) << w.log()->text().toStdString();
  EXPECT_TRUE(WaitUntil(
      [&] { return JointsNear(panel_->simulator()->joints(), resumed_end, 0.02); }, 5000));
}

TEST_F(RobotSendTest, ResumeRefusesAJournalOfAnotherProgramOrNone) {
  MainWindow w;
  Prepare(w, 0.01);
  Connect(w);
  Button("resumeButton")->click();
  EXPECT_NE(w.log()->text().indexOf("there is no journal"), -1) << w.log()->text().toStdString();
  // A journal beside the plan's file (VIDEO.val), left by a send of other lines.
  const std::string journal = robot::SendJournal::PathFor(panel_->planFile().toStdString());
  {
    robot::SendJournal j;
    ASSERT_TRUE(j.Open(journal,
                       robot::SendJournal::Hash({"SPEED 10", "DO MOVE #PPOINT(0,-90,0,0,0,0)"}), 2,
                       "other.val", false)
                    .ok());
    ASSERT_TRUE(j.Sent(1, 1).ok());
  }
  Button("resumeButton")->click();
  EXPECT_NE(w.log()->text().indexOf("belongs to a different program"), -1)
      << w.log()->text().toStdString();
  EXPECT_NE(w.log()->text().indexOf(QString::fromStdString(journal)), -1);
  QTest::qWait(200);
  EXPECT_EQ(panel_->simulator()->movesExecuted(), 0);
  EXPECT_FALSE(panel_->link()->isSending());
}

}  // namespace
}  // namespace armmimic::test
