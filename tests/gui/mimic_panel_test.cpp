// The "Mimic live" mode driven through its widgets against the built-in simulated controller
// (a pseudo-terminal in this process): nothing moves before the operator confirms the mapping
// and limits, the preview follows the planned targets, the dead-man holds the robot, and the
// Stop button's application-wide shortcut stops the run with the journal at the last move.
#include <QApplication>
#include <QCheckBox>
#include <QLabel>
#include <QPushButton>
#include <QTest>

#include "armmimic/robot/live_log.h"
#include "armmimic/sim/pty_server.h"
#include "armmimic/synth/arm_scene.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "mimic_controller.h"
#include "mimic_panel.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "robot_preview.h"
#include "sim_controller.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;
using gui::MimicPanel;

// The shared scene has 40 frames of motion; the dead-man test needs time to hold and then move:
// 8 s of swinging arm at 240x180, rendered once.
GuiScenes LongScene() {
  bool created = false;
  GuiScenes g;
  g.arm_dir = SharedTempDir("gui-long-scene", &created).file("long");
  g.motion_frames = 240;
  if (created) {
    synth::ArmSceneOptions o;
    o.seed = 9;
    o.size = {240, 180};
    o.background_frames = g.background_frames;
    o.standstill_frames = g.standstill_frames;
    o.motion_frames = g.motion_frames;
    o.motion = synth::ArmMotion::kSwing;
    const Status st = synth::WriteArmScene(o, g.arm_dir, {});
    EXPECT_TRUE(st.ok()) << st.message();
  }
  return g;
}

class MimicPanelTest : public GuiTest {
 protected:
  // Opens the scene with the bgsub protocol set and connects the simulated controller.
  void Prepare(MainWindow& w, double time_scale, const GuiScenes& s) {
    w.openInputs({QString::fromStdString(s.video())});
    ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
    w.settingsPanel()->setOptions(s.BgsubProtocol());
    gui::RobotPanel* robot = w.robotPanel();
    ASSERT_TRUE(robot->startSimulator(time_scale)) << w.log()->text().toStdString();
    ASSERT_TRUE(robot->connectTo(robot->simulator()->devicePath()))
        << w.log()->text().toStdString();
  }
  template <typename T>
  static T* Child(QWidget* parent, const char* name) {
    T* c = parent->findChild<T*>(name);
    EXPECT_NE(c, nullptr) << name;
    return c;
  }
};

TEST_F(MimicPanelTest, NothingMovesUntilTheOperatorConfirmsThenThePreviewFollowsThePlan) {
  MainWindow w;
  w.show();
  Prepare(w, 0.05, scenes());
  MimicPanel* panel = w.mimicPanel();
  auto* start = Child<QPushButton>(panel, "mimicStart");
  auto* confirm = Child<QCheckBox>(panel, "mimicConfirm");
  ASSERT_TRUE(WaitUntil([&] { return !panel->shownSettings().isEmpty(); }));
  EXPECT_TRUE(panel->shownSettings().contains("J2 [-200, 20]"))
      << panel->shownSettings().toStdString();
  // Unconfirmed: the button is disabled, and starting anyway is refused with a message.
  EXPECT_FALSE(start->isEnabled());
  EXPECT_FALSE(panel->startMimicking());
  EXPECT_TRUE(w.log()->text().contains("confirm the mapping"));
  EXPECT_EQ(w.robotPanel()->simulator()->movesExecuted(), 0);

  QTest::mouseClick(confirm, Qt::LeftButton, {}, QPoint(4, confirm->height() / 2));
  ASSERT_TRUE(confirm->isChecked());
  ASSERT_TRUE(start->isEnabled());
  QTest::mouseClick(start, Qt::LeftButton);
  ASSERT_TRUE(panel->controller()->running()) << w.log()->text().toStdString();
  bool finished = false, ok = false;
  QObject::connect(panel->controller(), &gui::MimicController::finished,
                   [&](bool success, const QString&) {
                     finished = true;
                     ok = success;
                   });
  // The preview shows the planner's targets, not the raw angles.
  robot::JointArray last_planned{};
  int planned = 0;
  QObject::connect(panel->controller(), &gui::MimicController::planned,
                   [&](bool has, const robot::JointArray& t, const QString&) {
                     if (!has) return;
                     last_planned = t;
                     ++planned;
                   });
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 60000)) << w.log()->text().toStdString();
  EXPECT_TRUE(ok) << w.log()->text().toStdString();
  EXPECT_GT(planned, 10);
  EXPECT_EQ(panel->preview()->pose(), last_planned);
  EXPECT_FALSE(panel->view()->image().isNull()) << "the live overlay showed no frame";
  const int moves = w.robotPanel()->simulator()->movesExecuted();
  EXPECT_GT(moves, 0);
  // The journal records every move the controller ran, and the latency is shown.
  const std::string journal =
      ReadFile(robot::LiveJournal::PathFor(panel->controller()->anglesPath().toStdString()));
  EXPECT_NE(journal.find("\nend\nlast-ack "), std::string::npos) << journal;
  EXPECT_TRUE(Child<QLabel>(panel, "mimicLatency")->text().contains("p95"));
}

TEST_F(MimicPanelTest, TheDeadManHoldsTheRobotAndTheStopShortcutStopsIt) {
  MainWindow w;
  w.show();
  Prepare(w, 0.02, LongScene());
  MimicPanel* panel = w.mimicPanel();
  auto* confirm = Child<QCheckBox>(panel, "mimicConfirm");
  auto* deadman = Child<QCheckBox>(panel, "mimicDeadman");
  auto* hold = Child<QPushButton>(panel, "mimicHold");
  auto* stop = Child<QPushButton>(panel, "mimicStop");
  ASSERT_TRUE(WaitUntil([&] { return !panel->shownSettings().isEmpty(); }));
  confirm->setChecked(true);
  deadman->setChecked(true);
  ASSERT_TRUE(panel->startMimicking()) << w.log()->text().toStdString();
  EXPECT_TRUE(stop->isEnabled());
  int holding = 0, frames = 0;
  QObject::connect(panel->controller(), &gui::MimicController::planned,
                   [&](bool, const robot::JointArray&, const QString& why) {
                     ++frames;
                     holding += why == "held by the operator";
                   });
  // Released: frames are planned, and the robot gets no move at all.
  ASSERT_TRUE(WaitUntil([&] { return frames >= 8; }, 30000)) << w.log()->text().toStdString();
  EXPECT_EQ(holding, frames);
  EXPECT_EQ(w.robotPanel()->simulator()->movesExecuted(), 0);
  // Held (the mouse on the button): the robot moves.
  QTest::mousePress(hold, Qt::LeftButton);
  ASSERT_TRUE(WaitUntil([&] { return w.robotPanel()->simulator()->movesExecuted() > 0; }, 30000))
      << w.log()->text().toStdString();
  QTest::mouseRelease(hold, Qt::LeftButton);
  // The Stop shortcut works with the focus anywhere in the window.
  w.robotPanel()->setFocus();
  bool finished = false;
  QObject::connect(panel->controller(), &gui::MimicController::finished,
                   [&](bool, const QString&) { finished = true; });
  QTest::keyClick(&w, Qt::Key_F12);
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 30000));
  EXPECT_FALSE(panel->controller()->running());
  EXPECT_TRUE(w.log()->text().contains("stopped by the operator")) << w.log()->text().toStdString();
  const std::string journal =
      ReadFile(robot::LiveJournal::PathFor(panel->controller()->anglesPath().toStdString()));
  EXPECT_NE(journal.find("\nstop stopped by the operator\nlast-ack "), std::string::npos)
      << journal;
}

TEST_F(MimicPanelTest, ChangingTheLimitsClearsTheConfirmation) {
  MainWindow w;
  w.show();
  MimicPanel* panel = w.mimicPanel();
  auto* confirm = Child<QCheckBox>(panel, "mimicConfirm");
  ASSERT_TRUE(WaitUntil([&] { return !panel->shownSettings().isEmpty(); }));
  confirm->setChecked(true);
  robot::PlannerOptions o = w.robotPanel()->plannerOptions();
  o.limits.max_deg[0] = 90;
  w.robotPanel()->setPlannerOptions(o);
  ASSERT_TRUE(WaitUntil([&] { return panel->shownSettings().contains("J1 [-160, 90]"); }));
  EXPECT_FALSE(confirm->isChecked());
  EXPECT_FALSE(Child<QPushButton>(panel, "mimicStart")->isEnabled());
}

TEST_F(MimicPanelTest, ClosingTheWindowMidRunStopsTheRobot) {
  // A controller outside the window, so what reaches it can be read after the window is gone.
  sim::EmulatorOptions eo;
  eo.time_scale = 0.05;
  sim::PtyServer server(eo);
  ASSERT_TRUE(server.Start(tmp_.file("puma")).ok());
  {
    MainWindow w;
    w.show();
    const GuiScenes& s = LongScene();
    w.openInputs({QString::fromStdString(s.video())});
    ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
    w.settingsPanel()->setOptions(s.BgsubProtocol());
    ASSERT_TRUE(w.robotPanel()->connectTo(QString::fromStdString(tmp_.file("puma"))));
    MimicPanel* panel = w.mimicPanel();
    ASSERT_TRUE(WaitUntil([&] { return !panel->shownSettings().isEmpty(); }));
    Child<QCheckBox>(panel, "mimicConfirm")->setChecked(true);
    ASSERT_TRUE(panel->startMimicking()) << w.log()->text().toStdString();
    ASSERT_TRUE(WaitUntil([&] { return server.log().size() >= 2; }, 30000))
        << w.log()->text().toStdString();
  }  // the window closes while the robot follows
  const std::size_t moves = server.log().size();
  QTest::qWait(500);
  EXPECT_EQ(server.log().size(), moves) << "a move reached the robot after the window closed";
  server.Stop();
}

}  // namespace
}  // namespace armmimic::test
