// armmimic-screenshot-tour: walks the workflow of docs/user-guide.md in the real application
// window and saves a screenshot of the whole screen after each step. Run it under an X server
// (scripts/screenshots.sh uses xvfb-run):  armmimic-screenshot-tour OUTDIR SAMPLE_DIR [REAL_DIR]
// REAL_DIR holds the real clip pose_squats.mp4 (not part of the project) for the walkthrough.
// Length: main is the tour's script, one step after another as the user guide tells it.
#include <cstdio>
#include <functional>

#include <QApplication>
#include <QChart>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QInputDialog>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>

#include "analysis_job.h"
#include "angle_panel.h"
#include "angle_plot.h"
#include "app_actions.h"
#include "arm_view_3d.h"
#include "armmimic/synth/marker_scene.h"
#include "armmimic/synth/random_arm_scene.h"
#include "csv_export_dialog.h"
#include "engine_settings_panel.h"
#include "main_window.h"
#include "mimic_controller.h"
#include "mimic_panel.h"
#include "result_store.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "sim_controller.h"
#include "video_player.h"
#include "video_view.h"

namespace {

QString g_out;

void Shot(const QString& name) {
  QTest::qWait(300);  // let the window settle and repaint
  const QPixmap screen = QGuiApplication::primaryScreen()->grabWindow(0);
  const QString path = QDir(g_out).filePath(name + ".png");
  if (!screen.save(path)) std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
  std::printf("%s\n", qPrintable(path));
}

// The window as it is drawn right now, without turning the event loop: for a state that the
// next queued events would end (the analysis running, its progress bar in the status bar).
void ShotOfWindowNow(QWidget* window, const QString& name) {
  const QString path = QDir(g_out).filePath(name + ".png");
  if (!window->grab().save(path)) std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
  std::printf("%s\n", qPrintable(path));
}

bool Wait(const std::function<bool()>& done, int ms = 60000) { return QTest::qWaitFor(done, ms); }

// Runs `open` (which shows a modal dialog of type D), takes the shot `name` of the dialog and
// closes it with `finish`.
template <typename D>
void ShotOfDialog(const QString& name, const std::function<void()>& open,
                  const std::function<void(D*)>& finish) {
  QTimer poll;
  QObject::connect(&poll, &QTimer::timeout, [&] {
    auto* dialog = qobject_cast<D*>(QApplication::activeModalWidget());
    if (!dialog) return;
    poll.stop();
    Shot(name);
    finish(dialog);
  });
  poll.start(50);
  open();
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: armmimic-screenshot-tour OUTDIR SAMPLE_DIR [REAL_CLIP_DIR]\n");
    return 2;
  }
  g_out = QString::fromLocal8Bit(argv[1]);
  // The sample scene copied to a folder of the tour's own: a send writes its plan and journal
  // beside the video, which would otherwise stay in the sample folder (and an aborted send's
  // journal would turn the next tour's first confirmation into the question whether to resume).
  QTemporaryDir sample_copy;
  const QDir sample(sample_copy.path());
  for (const char* name : {"scene.avi", "background.png", "armlength.png"}) {
    if (!QFile::copy(QDir(QString::fromLocal8Bit(argv[2])).filePath(name), sample.filePath(name))) {
      std::fprintf(stderr, "cannot copy %s from %s\n", name, argv[2]);
      return 1;
    }
  }
  QDir().mkpath(g_out);
  QTemporaryDir settings_dir;
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings_dir.path());
  QApplication::setOrganizationName("armmimic-tour");
  QApplication::setApplicationName("armmimic");
  using armmimic::gui::MainWindow;

  MainWindow w;
  w.setGeometry(QGuiApplication::primaryScreen()->availableGeometry());
  w.show();
  QTest::qWait(200);
  w.resizeDocks({w.findChild<QDockWidget*>("plotDock")}, {300}, Qt::Vertical);
  Shot("01-start");

  w.openInputs({sample.filePath("scene.avi")});
  if (!Wait([&] { return w.player()->isOpen() && !w.view()->image().isNull(); })) return 1;
  w.player()->seek(70);
  Wait([&] { return w.view()->frameIndex() == 70; });
  Shot("02-opened");

  armmimic::AnalysisOptions o = w.settingsPanel()->options();
  o.engine.kind = armmimic::EngineKind::kBgsub;
  o.background_path = sample.filePath("background.png").toStdString();
  o.arm_length_path = sample.filePath("armlength.png").toStdString();
  o.start = 45;
  w.settingsPanel()->setOptions(o);
  Shot("03-settings");

  // Every other parameter: the engine's folded "Advanced" section (here the LK engine's).
  auto* engine_combo = w.settingsPanel()->findChild<QComboBox*>("engineCombo");
  engine_combo->setCurrentIndex(int(armmimic::EngineKind::kLk));
  QToolButton* advanced = w.settingsPanel()->advancedToggle(armmimic::EngineKind::kLk);
  advanced->setChecked(true);
  QTest::qWait(100);
  if (auto* scroll = w.findChild<QScrollArea*>("analysisScroll")) {
    // The engine's main parameters at the top, the advanced ones below.
    scroll->verticalScrollBar()->setValue(advanced->mapTo(scroll->widget(), QPoint()).y() - 160);
  }
  Shot("03b-advanced");
  advanced->setChecked(false);
  engine_combo->setCurrentIndex(int(armmimic::EngineKind::kBgsub));
  if (auto* scroll = w.findChild<QScrollArea*>("analysisScroll")) {
    scroll->verticalScrollBar()->setValue(0);
  }

  // Half way through the run: the rows so far in the plot (what the window's 40 ms redraw
  // shows next), the phase and the progress bar in the status bar.
  bool mid_shot = false;
  armmimic::gui::ResultStore rows_so_far;
  QObject::connect(w.job(), &armmimic::gui::AnalysisJob::measured,
                   [&](const armmimic::ArmMeasurement& m) { rows_so_far.add(m); });
  QObject::connect(w.job(), &armmimic::gui::AnalysisJob::progress, [&](int done, int total) {
    // Waiting here would let the queued progress and the end of the run through first.
    if (!mid_shot && total > 0 && done > total / 2) {
      mid_shot = true;
      w.plot()->setResults(rows_so_far);
      QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
      ShotOfWindowNow(&w, "04-analysing");
    }
  });
  w.startAnalysis();
  if (!Wait([&] { return !w.job()->isRunning(); }, 300000)) return 1;
  w.player()->seek(170);
  Wait([&] { return w.view()->frameIndex() == 170; });
  Shot("05-overlay");

  // The plot zoomed to the motion with a drag of the right button, and read under the mouse.
  armmimic::gui::AnglePlot* plot = w.plot();
  plot->zoomTo(95, 235, -120, 100);
  plot->setCursorFrame(170);
  QTest::mouseMove(
      plot->viewport(),
      plot->mapFromScene(plot->chart()->mapToScene(plot->chart()->mapToPosition(QPointF(150, 0)))));
  Shot("05b-plot-zoom");
  ShotOfDialog<armmimic::gui::CsvExportDialog>(
      "05c-csv-export", [&] { w.actions()->exportCsv->trigger(); },
      [](armmimic::gui::CsvExportDialog* d) { d->reject(); });
  plot->resetZoom();

  w.actions()->ovContour->setChecked(true);
  w.settingsPanel()->setRoi(cv::Rect(120, 20, 190, 200));
  w.actions()->toolRoi->trigger();
  Shot("06-roi");
  w.actions()->ovContour->setChecked(false);
  w.settingsPanel()->setRoi(std::nullopt);
  w.actions()->toolPan->trigger();

  w.findChild<QDockWidget*>("robotDock")->raise();
  armmimic::gui::RobotPanel* robot = w.robotPanel();
  // The 3-D view large: the Robot panel floated beside the window, the plan's wrist path drawn.
  auto* robot_dock = w.findChild<QDockWidget*>("robotDock");
  robot_dock->setFloating(true);
  robot_dock->setGeometry(820, 60, 760, 900);
  w.findChild<QDockWidget*>("analysisDock")->raise();  // behind it, the window as it was
  w.player()->seek(205);
  Wait([&] { return w.view()->frameIndex() == 205; });
  Shot("07d-robot-3d");
  // A J3 limit the pose breaks: the forearm turns red, and the plan report says which frames.
  armmimic::robot::PlannerOptions tight = robot->plannerOptions();
  tight.limits.max_deg[2] = -80;
  robot->setPlannerOptions(tight);
  Shot("07e-robot-3d-limit");
  robot->resetPlannerDefaults();
  robot_dock->setFloating(false);
  robot_dock->raise();

  // The plan's pose at this frame (before a controller is connected, whose pose it would show).
  robot->findChild<QTabWidget*>("robotTabs")->setCurrentIndex(0);
  Shot("07b-plan");
  robot->findChild<QPushButton*>("compactButton")->setChecked(true);
  Shot("07c-compact");
  robot->findChild<QPushButton*>("compactButton")->setChecked(false);

  robot->findChild<QTabWidget*>("robotTabs")->setCurrentIndex(1);
  robot->startSimulator(0.05);
  robot->connectTo(robot->simulator()->devicePath());
  Shot("07-robot");

  QTimer::singleShot(800, [&] {
    Shot("08-confirm");
    for (QWidget* top : QApplication::topLevelWidgets()) {
      if (auto* box = qobject_cast<QMessageBox*>(top)) {
        for (QAbstractButton* b : box->buttons()) {
          if (box->buttonRole(b) == QMessageBox::AcceptRole) b->click();
        }
      }
    }
  });
  bool sent = false;
  QObject::connect(robot, &armmimic::gui::RobotPanel::sendFinished, [&](bool) { sent = true; });
  robot->sendPlan(false);
  Wait([&] { return sent; }, 300000);
  w.player()->seek(200);
  if (auto* scroll = robot->findChild<QScrollArea*>("controllerScroll")) {
    scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum());  // the replies
  }
  Shot("09-sent");

  // A send stopped part way (aborted after a few moves, at real-time speed): sending again asks
  // whether to resume from the journal or start over.
  robot->link()->disconnectPort();
  robot->startSimulator(1.0);
  robot->connectTo(robot->simulator()->devicePath());
  sent = false;
  if (robot->sendPlan(true)) {
    Wait([&] { return robot->link()->acknowledged() >= 5 || sent; }, 60000);
    robot->link()->abort();
    Wait([&] { return sent; }, 60000);
    ShotOfDialog<QMessageBox>(
        "08b-resume", [&] { robot->sendPlan(false); },
        [](QMessageBox* box) { box->button(QMessageBox::Cancel)->click(); });
    // Resume…: the confirmation covers what is left, and the pose the arm must stand in.
    ShotOfDialog<QMessageBox>(
        "08c-resume-confirm", [&] { robot->resumeSend(false); },
        [](QMessageBox* box) { box->button(QMessageBox::Cancel)->click(); });
  }
  robot->link()->disconnectPort();
  robot->startSimulator(0.05);
  robot->connectTo(robot->simulator()->devicePath());

  // Mimic live (docs/live.md): the sample video paced at its frame rate, the robot following.
  w.findChild<QDockWidget*>("mimicDock")->raise();
  w.resizeDocks({w.findChild<QDockWidget*>("mimicDock")}, {760}, Qt::Horizontal);
  w.resizeDocks({w.findChild<QDockWidget*>("plotDock")}, {200}, Qt::Vertical);
  armmimic::gui::MimicPanel* mimic = w.mimicPanel();
  mimic->findChild<QCheckBox*>("mimicConfirm")->setChecked(true);
  int mimic_commands = 0;
  QObject::connect(mimic->controller(), &armmimic::gui::MimicController::commandWritten,
                   [&](const armmimic::robot::JointArray&) { ++mimic_commands; });
  if (mimic->startMimicking()) {
    Wait([&] { return mimic_commands >= 8; }, 60000);
    Shot("13-mimic-live");
    mimic->stopMimicking();
    Wait([&] { return !mimic->controller()->running(); }, 60000);
  }
  w.findChild<QDockWidget*>("robotDock")->raise();

  // File > Capture from camera: a camera number or a stream URL. With no camera 7 attached,
  // the failure is one line in Messages, not a dialog.
  QTimer camera_dialog;
  QObject::connect(&camera_dialog, &QTimer::timeout, [&] {
    auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
    if (!dialog) return;
    camera_dialog.stop();
    dialog->setTextValue("7");
    Shot("10-camera");
    dialog->accept();
  });
  camera_dialog.start(50);
  w.actions()->camera->trigger();
  Wait([&] { return !w.player()->isOpen(); }, 20000);
  QTest::qWait(500);
  Shot("11-camera-missing");

  // The marker engine on a folder of views of the 2-DOF joint: markers and candidate boxes.
  QTemporaryDir marker_dir;
  armmimic::synth::MarkerSceneOptions marker;
  marker.seed = 3;
  marker.views = 12;
  marker.background = "room";
  marker.clutter = 2;
  const std::string marker_path = marker_dir.path().toStdString();
  if (!armmimic::synth::WriteMarkerScene(marker, marker_path, {}).ok()) return 1;
  w.findChild<QDockWidget*>("analysisDock")->raise();
  w.findChild<QDockWidget*>("plotDock")->raise();
  w.openInputs({marker_dir.filePath("views")});
  if (!Wait([&] { return w.player()->isOpen() && !w.view()->image().isNull(); })) return 1;
  armmimic::AnalysisOptions m = w.settingsPanel()->options();
  m.engine.kind = armmimic::EngineKind::kMarker;
  m.reference_path = marker_path + "/reference.png";
  w.settingsPanel()->setOptions(m);
  w.startAnalysis();
  if (!Wait([&] { return !w.job()->isRunning(); }, 300000)) return 1;
  w.player()->seek(4);
  Wait([&] { return w.view()->frameIndex() == 4 && w.view()->measurement().has_value(); });
  Shot("12-marker");

  // The hybrid engine in the thesis protocol on a drawn person the calibration takes (a tuning
  // seed; the sample's room is one it refuses): Calibrate from standstill shows the joints the
  // run would start from as handles on the last standstill frame, to accept or drag.
  QTemporaryDir hybrid_dir;
  armmimic::synth::RandomArmSceneOptions hybrid_scene;
  hybrid_scene.seed = 1000;
  if (!armmimic::synth::WriteRandomArmScene(hybrid_scene, hybrid_dir.path().toStdString(), {})
           .ok()) {
    return 1;
  }
  const armmimic::synth::RandomArmScene hybrid_truth(hybrid_scene);
  w.openInputs({hybrid_dir.filePath("scene.avi")});
  if (!Wait([&] { return w.player()->isOpen() && !w.view()->image().isNull(); })) return 1;
  armmimic::AnalysisOptions h = w.settingsPanel()->options();
  h.engine.kind = armmimic::EngineKind::kHybrid;
  h.background_path = hybrid_dir.filePath("background.png").toStdString();
  h.arm_length_path = hybrid_dir.filePath("armlength.png").toStdString();
  h.start = hybrid_truth.background_frames();
  h.engine.lk.standstill_frames = hybrid_truth.standstill_frames();
  w.settingsPanel()->setOptions(h);
  auto* calibrate = w.settingsPanel()->findChild<QPushButton*>("standstillCalibrate");
  if (auto* scroll = w.findChild<QScrollArea*>("analysisScroll")) {
    scroll->ensureWidgetVisible(calibrate, 0, 200);
  }
  w.findChild<QDockWidget*>("logDock")->raise();  // the estimate, in words
  calibrate->click();
  Wait([&] { return w.view()->frameIndex() == hybrid_truth.first_motion_frame() - 1; });
  w.view()->zoomToFit();
  Shot("03c-hybrid-calibrate");
  w.settingsPanel()->findChild<QPushButton*>("acceptEstimate")->click();
  w.startAnalysis();  // its rows are the results the window asks about when it closes
  if (!Wait([&] { return !w.job()->isRunning(); }, 300000)) return 1;

  // A real clip (a person doing squats, 720x1280 at 5 fps) through the pose engine, planned and
  // sent to the simulated controller, when its folder is given.
  if (argc == 4) {
    // A copy in a folder of its own: the plan, the journal and the session are written beside it.
    QTemporaryDir real_session;
    const QDir walk(real_session.path());
    const QString clip = walk.filePath("squats.mp4");
    if (!QFile::copy(QDir(QString::fromLocal8Bit(argv[3])).filePath("pose_squats.mp4"), clip)) {
      return 1;
    }
    w.findChild<QDockWidget*>("analysisDock")->raise();
    w.openInputs({clip});
    if (!Wait([&] { return w.player()->isOpen() && !w.view()->image().isNull(); })) return 1;
    armmimic::AnalysisOptions p = w.settingsPanel()->options();
    p.engine.kind = armmimic::EngineKind::kPose;
    p.start = 0;
    w.settingsPanel()->setOptions(p);
    Shot("14-real-pose-settings");  // the background's fields greyed: the network needs none
    w.startAnalysis();
    if (!Wait([&] { return !w.job()->isRunning(); }, 300000)) return 1;
    w.player()->seek(30);
    Wait([&] { return w.view()->frameIndex() == 30; });
    Shot("15-real-pose-overlay");  // the skeleton, its scores apart, the status in words
    // Saved as a session: the plan and its journal go beside it.
    w.saveSession(walk.filePath("squats.armmimic"));
    w.findChild<QDockWidget*>("robotDock")->raise();
    robot->findChild<QTabWidget*>("robotTabs")->setCurrentIndex(0);
    // At 5 fps the default 3 Hz low-pass is refused (above half the frame rate, said at its
    // field): 2 Hz; and the clip's lost second and a half is bridged.
    armmimic::robot::PlannerOptions slow = robot->plannerOptions();
    slow.cutoff_hz = 2.0;
    slow.max_gap_s = 2.0;
    robot->setPlannerOptions(slow);
    if (auto* scroll = robot->findChild<QScrollArea*>("planScroll")) {
      scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum());  // the report
    }
    Shot("16-real-plan");
    robot->link()->disconnectPort();
    robot->simulator()->stop();
    robot->findChild<QTabWidget*>("robotTabs")->setCurrentIndex(1);
    robot->findChild<QPushButton*>("simButton")->click();  // starts and connects
    ShotOfDialog<QMessageBox>(
        "17-real-confirm", [&] { robot->findChild<QPushButton*>("sendButton")->click(); },
        [](QMessageBox* box) {
          for (QAbstractButton* b : box->buttons()) {
            if (box->buttonRole(b) == QMessageBox::AcceptRole) b->click();
          }
        });
    sent = false;
    Wait([&] { return sent || !robot->link()->isSending(); }, 300000);
    w.findChild<QDockWidget*>("logDock")->raise();
    Shot("18-real-sent");  // Messages name squats.val and its journal
    // Quitting while the clip is analysed again asks first.
    w.findChild<QDockWidget*>("plotDock")->raise();
    w.startAnalysis();
    Wait([&] { return w.results().rows() >= 10 || !w.job()->isRunning(); }, 60000);
    if (w.job()->isRunning()) {
      ShotOfDialog<QMessageBox>(
          "19-quit-analysing", [&] { w.close(); },
          [](QMessageBox* box) { box->button(QMessageBox::Cancel)->click(); });
    }
    w.job()->cancel();
    Wait([&] { return !w.job()->isRunning(); }, 60000);
    // The same clip through BlazePose: the arm in 3-D, drawn in green beside the robot, which
    // turns its waist by the arm's azimuth (the arms come forwards in the squat at frame 30).
    p.engine.pose.network = armmimic::PoseNetworkKind::kBlazePose;
    p.engine.pose.side = armmimic::PoseSide::kLeft;
    w.settingsPanel()->setOptions(p);
    w.startAnalysis();
    if (!Wait([&] { return !w.job()->isRunning(); }, 300000)) return 1;
    robot->setPlannerOptions(slow);
    robot->link()->disconnectPort();  // the view shows the plan's pose, not a controller's
    robot->simulator()->stop();
    w.findChild<QDockWidget*>("analysisDock")->raise();
    auto* robot_dock_3d = w.findChild<QDockWidget*>("robotDock");
    robot_dock_3d->setFloating(true);
    robot_dock_3d->setGeometry(820, 60, 760, 900);
    robot->findChild<QTabWidget*>("robotTabs")->setCurrentIndex(0);
    w.player()->seek(30);
    Wait([&] { return w.view()->frameIndex() == 30; });
    Shot("20-real-blazepose-3d");
    robot_dock_3d->setFloating(false);
    // Both arms from one pass of the network: the overlay draws both, and the arm picked on the
    // angle panel (here the right) is the one the plot, the overlay's angles and the robot follow.
    p.engine.pose.network = armmimic::PoseNetworkKind::kMoveNet;
    p.engine.pose.side = armmimic::PoseSide::kBoth;
    w.settingsPanel()->setOptions(p);
    w.startAnalysis();
    if (!Wait([&] { return !w.job()->isRunning(); }, 300000)) return 1;
    w.findChild<QDockWidget*>("plotDock")->raise();
    w.findChild<QComboBox*>("armPick")->setCurrentIndex(1);
    w.player()->seek(30);
    Wait([&] { return w.view()->frameIndex() == 30; });
    Shot("21-real-both-arms");
  }
  // Closing with results in no exported file asks first.
  ShotOfDialog<QMessageBox>(
      "13-quit-unsaved", [&] { w.close(); },
      [](QMessageBox* box) { box->button(QMessageBox::Discard)->click(); });
  return 0;
}
