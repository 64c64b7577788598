#include "gui_fixture.h"

#include <filesystem>
#include <memory>
#include <utility>

#include <QApplication>
#include <QCheckBox>
#include <QPushButton>
#include <QSettings>
#include <QTest>
#include <QTimer>
#include <QWheelEvent>
#include <QWidget>

#include "analysis_job.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/synth/arm_scene.h"
#include "armmimic/synth/marker_scene.h"
#include "engine_settings_panel.h"
#include "log_view.h"
#include "main_window.h"
#include "mimic_controller.h"
#include "mimic_panel.h"
#include "robot_panel.h"
#include "sim_controller.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

// Shared by every GUI test in the run; the folder is a SharedTempDir, removed after the last test.
std::unique_ptr<GuiScenes> g_scenes;

// QSettings of the user scope (the application's own and Qt's) go to `dir`.
void SettingsIn(const std::string& dir) {
  for (QSettings::Format format : {QSettings::NativeFormat, QSettings::IniFormat}) {
    QSettings::setPath(format, QSettings::UserScope, QString::fromStdString(dir));
  }
}

// What Qt, Mesa and the application would keep in the user's home (settings, Qt's and Mesa's
// shader caches) goes to folders the tests own: the XDG base folders point into a SharedTempDir,
// for this process and the programs it starts. Without a runtime folder Qt would make
// $TMPDIR/runtime-$USER and leave it behind, so the tests give it one too (mode 0700, as Qt
// requires).
void KeepOutOfHome() {
  namespace fs = std::filesystem;
  const TempDir& home = SharedTempDir("gui-home");
  for (const auto& [var, sub] : {std::pair<const char*, const char*>{"XDG_CONFIG_HOME", "config"},
                                 {"XDG_CACHE_HOME", "cache"},
                                 {"XDG_DATA_HOME", "data"},
                                 {"XDG_STATE_HOME", "state"}}) {
    fs::create_directories(home.file(sub));
    qputenv(var, QByteArray::fromStdString(home.file(sub)));
  }
  if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
    fs::create_directories(home.file("runtime"));
    fs::permissions(home.file("runtime"), fs::perms::owner_all);
    qputenv("XDG_RUNTIME_DIR", QByteArray::fromStdString(home.file("runtime")));
  }
}

void EnsureApplication() {
  if (QApplication::instance()) return;
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  KeepOutOfHome();
  static int argc = 1;
  static char name[] = "gui_tests";
  static char* argv[] = {name, nullptr};
  new QApplication(argc, argv);  // lives for the whole test run
  QApplication::setOrganizationName("armmimic-tests");
  QApplication::setApplicationName("gui_tests");
  // Never the user's settings, not even between tests (SetUp gives each test its own).
  SettingsIn(SharedTempDir("gui-settings").path());
}

}  // namespace

void GuiTest::SetUpTestSuite() {
  EnsureApplication();
  if (g_scenes) return;
  const TempDir& dir = SharedTempDir("gui-scenes");
  auto scenes = std::make_unique<GuiScenes>();
  scenes->arm_dir = dir.file("arm");
  scenes->marker_dir = dir.file("marker");
  synth::ArmSceneOptions arm;
  arm.seed = 7;
  arm.background_frames = scenes->background_frames;
  arm.standstill_frames = scenes->standstill_frames;
  arm.motion_frames = scenes->motion_frames;
  arm.motion = synth::ArmMotion::kSwing;
  Status st = synth::WriteArmScene(arm, scenes->arm_dir, {});
  ASSERT_TRUE(st.ok()) << st.message();
  synth::MarkerSceneOptions marker;
  marker.seed = 3;
  marker.views = 6;
  st = synth::WriteMarkerScene(marker, scenes->marker_dir, {});
  ASSERT_TRUE(st.ok()) << st.message();
  g_scenes = std::move(scenes);
}

void GuiTest::SetUp() {
  // Never touch the user's settings: a fresh settings folder for every test.
  SettingsIn(tmp_.file("settings"));
  QSettings().clear();
}

void GuiTest::TearDown() {
  // The test's folder goes with it: nothing may write settings there afterwards.
  SettingsIn(SharedTempDir("gui-settings").path());
  // A send writes its plan and journal beside the shared scene's video: the next test starts
  // without them.
  for (const char* name : {"scene.val", "scene.val.journal"}) {
    if (g_scenes) std::filesystem::remove(std::filesystem::path(g_scenes->arm_dir) / name);
  }
}

const GuiScenes& GuiTest::scenes() { return *g_scenes; }

bool GuiTest::WaitUntil(const std::function<bool()>& done, int timeout_ms) {
  return QTest::qWaitFor(done, timeout_ms);
}

void GuiTest::Wheel(QWidget* w, int delta) {
  // Qt propagates only the window system's wheel events, so the walk up the parents is done
  // here: each widget gets the event until one accepts it.
  const QPoint spot = w->mapToGlobal(w->rect().center());
  for (QWidget* target = w; target;
       target = target->isWindow() ? nullptr : target->parentWidget()) {
    QWheelEvent event(QPointF(target->mapFromGlobal(spot)), QPointF(spot), QPoint(),
                      QPoint(0, delta), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(target, &event);
    if (event.isAccepted()) return;
  }
}

void GuiTest::RunMimicToEnd(gui::MainWindow& w, AngleFile* angles) {
  gui::RobotPanel* robot = w.robotPanel();
  ASSERT_TRUE(robot->startSimulator(0.05)) << w.log()->text().toStdString();
  ASSERT_TRUE(robot->connectTo(robot->simulator()->devicePath())) << w.log()->text().toStdString();
  gui::MimicPanel* panel = w.mimicPanel();
  auto* confirm = panel->findChild<QCheckBox*>("mimicConfirm");
  auto* start = panel->findChild<QPushButton*>("mimicStart");
  ASSERT_NE(confirm, nullptr);
  ASSERT_NE(start, nullptr);
  ASSERT_TRUE(WaitUntil([&] { return !panel->shownSettings().isEmpty(); }));
  QTest::mouseClick(confirm, Qt::LeftButton, {}, QPoint(4, confirm->height() / 2));
  ASSERT_TRUE(start->isEnabled());
  bool finished = false;
  QObject::connect(panel->controller(), &gui::MimicController::finished,
                   [&](bool, const QString&) { finished = true; });
  QTest::mouseClick(start, Qt::LeftButton);
  ASSERT_TRUE(panel->controller()->running()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return finished; }, 60000)) << w.log()->text().toStdString();
  const Status st = ReadAngleFile(panel->controller()->anglesPath().toStdString(), angles);
  ASSERT_TRUE(st.ok()) << st.message();
}

void GuiTest::ShowAndOpen(gui::MainWindow& w) {
  w.resize(1200, 800);
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  w.openInputs({QString::fromStdString(scenes().video())});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && !w.view()->image().isNull(); }))
      << w.log()->text().toStdString();
}

void GuiTest::ShowAndAnalyze(gui::MainWindow& w) {
  ShowAndOpen(w);
  if (HasFatalFailure()) return;
  w.settingsPanel()->setOptions(scenes().BgsubProtocol());
  ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
  ASSERT_FALSE(w.job()->resultPath().isEmpty()) << w.log()->text().toStdString();
}

bool GuiTest::AnswerModalWidget(const std::function<void()>& action,
                                const std::function<bool(QWidget*)>& answer) {
  bool shown = false;
  QTimer poll;
  QObject::connect(&poll, &QTimer::timeout, [&] {
    QWidget* modal = QApplication::activeModalWidget();
    if (modal && !shown && answer(modal)) shown = true;
  });
  poll.start(20);
  action();
  poll.stop();
  return shown;
}

}  // namespace armmimic::test
