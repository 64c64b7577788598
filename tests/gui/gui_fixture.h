// Shared set-up of the GUI tests: one QApplication (offscreen), settings in a temporary folder
// under a test organisation, and small synthetic scenes rendered once with known angles.
#pragma once

#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <QString>
#include <QWidget>

class QWidget;

#include "armmimic/core/angle_file.h"
#include "armmimic/engines/analysis.h"
#include "test_util.h"

namespace armmimic::gui {
class MainWindow;
}

namespace armmimic::test {

struct GuiScenes {
  std::string arm_dir;     // scene.avi, background.png, armlength.png, truth.tsv
  std::string marker_dir;  // reference.png, views/, truth.tsv
  int background_frames = 10;
  int standstill_frames = 20;
  int motion_frames = 40;
  std::string video() const { return arm_dir + "/scene.avi"; }
  std::string background() const { return arm_dir + "/background.png"; }
  std::string arm_length() const { return arm_dir + "/armlength.png"; }
  // The arm scene's thesis protocol for bgsub: its background and arm-length images, the start
  // after the empty frames and the standstill's length.
  AnalysisOptions BgsubProtocol() const {
    AnalysisOptions o;
    o.engine.kind = EngineKind::kBgsub;
    o.background_path = background();
    o.arm_length_path = arm_length();
    o.start = background_frames;
    o.engine.bgsub.standstill_frames = standstill_frames;
    return o;
  }
};

class GuiTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite();
  void SetUp() override;
  void TearDown() override;
  static const GuiScenes& scenes();
  // Pumps the event loop until `done` or the timeout; returns `done()`.
  static bool WaitUntil(const std::function<bool()>& done, int timeout_ms = 20000);
  // One notch of the mouse wheel (down for negative `delta`) over the middle of `w`, delivered
  // as the window system does: to `w`, and on to its parents when `w` ignores it.
  static void Wheel(QWidget* w, int delta = 120);
  // Shows `w` (1200 x 800) and opens the arm scene, waiting for its first frame; fails the test
  // when either does not happen.
  static void ShowAndOpen(gui::MainWindow& w);
  // ShowAndOpen, then analyses the scene with bgsub in the thesis protocol; fails the test when
  // any step does not happen.
  static void ShowAndAnalyze(gui::MainWindow& w);
  // Starts the emulator (time scale 0.05) and connects the robot panel to it, confirms and
  // starts Mimic live with the Analysis tab's settings, waits for it to finish and reads its
  // angle file into `angles`; fails the test when any step does not happen.
  static void RunMimicToEnd(gui::MainWindow& w, AngleFile* angles);
  // Runs `action` while a modal dialog of class `D` it opens is answered by `answer` (called
  // with the dialog once it shows). Returns whether the dialog showed.
  template <typename D>
  static bool AnswerModal(const std::function<void()>& action,
                          const std::function<void(D*)>& answer);

  TempDir tmp_;

 private:
  static bool AnswerModalWidget(const std::function<void()>& action,
                                const std::function<bool(QWidget*)>& answer);
};

template <typename D>
bool GuiTest::AnswerModal(const std::function<void()>& action,
                          const std::function<void(D*)>& answer) {
  return AnswerModalWidget(action, [&](QWidget* w) {
    D* d = qobject_cast<D*>(w);
    if (d) answer(d);
    return d != nullptr;
  });
}

}  // namespace armmimic::test
