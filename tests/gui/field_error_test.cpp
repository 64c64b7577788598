// Typed errors in the GUI: an error the library keys by its setting frames that setting's field,
// names it by its label (never by a command-line flag), and the frame goes when the field changes.
// The robot panel words the serial layer's refusals with its own labels.
#include <QApplication>
#include <QComboBox>
#include <QGroupBox>
#include <QLineEdit>
#include <QTest>

#include <opencv2/core.hpp>

#include "analysis_job.h"
#include "armmimic/core/image_io.h"
#include "engine_settings_panel.h"
#include "field_error.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_panel.h"
#include "sim_controller.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class FieldErrorTest : public GuiTest {};

TEST_F(FieldErrorTest, ABgsubRunWithoutAnArmLengthImageFramesThatField) {
  MainWindow w;
  ShowAndOpen(w);
  AnalysisOptions o = scenes().BgsubProtocol();
  o.arm_length_path.clear();
  w.settingsPanel()->setOptions(o);
  auto* arm = w.settingsPanel()->findChild<QLineEdit*>("armLengthPath");
  ASSERT_NE(arm, nullptr);
  EXPECT_FALSE(gui::HasFieldError(arm));

  EXPECT_FALSE(w.startAnalysis());
  EXPECT_TRUE(gui::HasFieldError(arm));
  EXPECT_EQ(w.focusWidget(), arm);
  EXPECT_TRUE(arm->styleSheet().contains("#d03b2f")) << arm->styleSheet().toStdString();
  const QString log = w.log()->text();
  EXPECT_TRUE(log.contains("Arm-length image: the bgsub engine needs an arm-length image"))
      << log.toStdString();
  EXPECT_FALSE(log.contains("--arm-length")) << log.toStdString();
  // No other field is framed.
  for (QWidget* field : w.settingsPanel()->findChildren<QWidget*>()) {
    if (field != arm) {
      EXPECT_FALSE(gui::HasFieldError(field)) << field->objectName().toStdString();
    }
  }

  // Typing in the field takes the frame away.
  QTest::keyClicks(arm, "a");
  EXPECT_FALSE(gui::HasFieldError(arm));
  EXPECT_FALSE(arm->styleSheet().contains("#d03b2f"));
}

TEST_F(FieldErrorTest, AnLkRunWithNeitherBackgroundNorShoulderFramesTheShoulderBox) {
  MainWindow w;
  ShowAndOpen(w);
  AnalysisOptions o;
  o.engine.kind = EngineKind::kLk;
  w.settingsPanel()->setOptions(o);  // no background, no shoulder
  auto* box = w.settingsPanel()->findChild<QGroupBox*>("shoulderBox");
  ASSERT_NE(box, nullptr);

  EXPECT_FALSE(w.startAnalysis());
  EXPECT_TRUE(gui::HasFieldError(box));
  const QString log = w.log()->text();
  EXPECT_TRUE(log.contains("Fixed shoulder: the lk engine needs a background image"))
      << log.toStdString();
  EXPECT_FALSE(log.contains("--shoulder")) << log.toStdString();
  box->setChecked(true);  // ticking the box is the change that takes the frame away
  EXPECT_FALSE(gui::HasFieldError(box));
}

TEST_F(FieldErrorTest, AnArmLengthImageOfTheWrongSizeFramesThatFieldAfterTheRun) {
  MainWindow w;
  ShowAndOpen(w);
  const std::string small = tmp_.file("small.png");
  ASSERT_TRUE(WriteImageAtomically(small, cv::Mat(10, 10, CV_8UC3, cv::Scalar::all(0))).ok());
  AnalysisOptions o = scenes().BgsubProtocol();
  o.arm_length_path = small;
  w.settingsPanel()->setOptions(o);
  auto* arm = w.settingsPanel()->findChild<QLineEdit*>("armLengthPath");
  ASSERT_NE(arm, nullptr);

  // The options check out; the size is found by the run on the worker thread.
  ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
  EXPECT_TRUE(gui::HasFieldError(arm));
  const QString log = w.log()->text();
  EXPECT_TRUE(log.contains("Arm-length image: the arm-length image " +
                           QString::fromStdString(small) + " is 10x10"))
      << log.toStdString();
  EXPECT_FALSE(log.contains("--arm-length")) << log.toStdString();
}

TEST_F(FieldErrorTest, TheRobotPanelNamesARefusedPortSettingByItsLabel) {
  MainWindow w;
  gui::RobotPanel* panel = w.robotPanel();
  ASSERT_TRUE(panel->startSimulator(0.01)) << w.log()->text().toStdString();
  auto* parity = panel->findChild<QComboBox*>("parityCombo");
  ASSERT_NE(parity, nullptr);
  const int even = parity->findData(QChar('E'));
  ASSERT_GE(even, 0);
  parity->setCurrentIndex(even);  // a pseudo-terminal has no parity bit: the port refuses it
  QString error;
  QObject::connect(panel, &gui::RobotPanel::errorOccurred,
                   [&](const QString& text) { error = text; });

  EXPECT_FALSE(panel->connectTo(panel->simulator()->devicePath()));
  EXPECT_TRUE(
      error.startsWith("Parity: " + panel->simulator()->devicePath() + " refused the parity E"))
      << error.toStdString();
  EXPECT_FALSE(error.contains("--")) << error.toStdString();
}

}  // namespace
}  // namespace armmimic::test
