// The main window: docks, menus and the wiring between the panels; each task is its own widget.
// Length: wireActions connects every menu action to its handler in one list.
#include "main_window.h"

#include <cmath>

#include <QApplication>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>

#include "analysis_job.h"
#include "angle_panel.h"
#include "angle_plot.h"
#include "app_actions.h"
#include "engine_settings_panel.h"
#include "focus_return.h"
#include "icons.h"
#include "log_view.h"
#include "mimic_controller.h"
#include "mimic_panel.h"
#include "playback_bar.h"
#include "prompts.h"
#include "recent_files.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "session_inputs.h"
#include "shortcut_guard.h"
#include "status_line.h"
#include "ui_main_window.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::gui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      ui_(std::make_unique<Ui::MainWindowForm>()),
      actions_(new AppActions(this)),
      player_(new VideoPlayer(this)),
      job_(new AnalysisJob(this)) {
  ui_->setupUi(this);  // the central view and the docks: ui/main_window.ui
  view_ = ui_->videoView;
  bar_ = ui_->playbackBar;
  settings_ = ui_->engineSettings;
  angles_ = ui_->anglePanel;
  plot_ = angles_->plot();
  log_ = ui_->logView;
  robot_ = ui_->robotPanel;
  mimic_ = ui_->mimicPanel;  // the live view scrolls, never making the dock column taller
  status_ = new StatusLine(statusBar());
  log_dock_ = ui_->logDock;
  setWindowIcon(MakeIcon(IconKind::kApp));
  // A tall panel scrolls instead of pushing the window taller.
  ui_->analysisScroll->setMinimumWidth(settings_->sizeHint().width() + 24);
  bar_->addActions(
      {actions_->first, actions_->stepBack, actions_->play, actions_->stepForward, actions_->last});

  const QList<QAction*> toggles = {
      ui_->analysisDock->toggleViewAction(), ui_->plotDock->toggleViewAction(),
      ui_->robotDock->toggleViewAction(), ui_->mimicDock->toggleViewAction(),
      ui_->logDock->toggleViewAction()};
  tabifyDockWidget(ui_->plotDock, ui_->logDock);
  tabifyDockWidget(ui_->analysisDock, ui_->robotDock);
  tabifyDockWidget(ui_->robotDock, ui_->mimicDock);
  ui_->analysisDock->raise();
  resizeDocks({ui_->plotDock}, {260}, Qt::Vertical);
  ui_->plotDock->raise();
  actions_->populate(this, toggles);
  recent_ = new RecentFiles(actions_->recentMenu(), this);
  connect(recent_, &RecentFiles::openRequested, this,
          [this](const QString& p) { openInputs({p}); });
  GuardShortcuts(this);
  ReturnFocusAfterDialogs(this);  // Esc aborts a send the confirmation has just started

  throttle_.setSingleShot(true);
  throttle_.setInterval(40);
  connect(&throttle_, &QTimer::timeout, this, &MainWindow::refreshViews);
  wireActions();
  wireFileActions();
  wireAnalysis();
  wireMimic();
  wireCalibration();
  robot_->setInputFiles([this] { return sessionInputs(); });
  robot_->setPlanFile([this] { return planFilePath(); });
  restoreSettings();
  updateStatus();
}

MainWindow::~MainWindow() {
  job_->cancel();
  // The Robot panel is deleted with its dock, after this window's members and the objects it
  // talks to: a send it aborts on the way out must report to nobody.
  robot_->disconnect();
}

void MainWindow::wireActions() {
  AppActions* a = actions_;
  connect(a->open, &QAction::triggered, this,
          [this] { openInputs(AskInputs(this, RecentFiles::lastDir())); });
  connect(a->openFolder, &QAction::triggered, this, [this] {
    const QString folder = AskImageFolder(this, RecentFiles::lastDir());
    if (!folder.isEmpty()) openInputs({folder});
  });
  connect(a->camera, &QAction::triggered, this, [this] {
    if (auto source = AskCamera(this)) openInputs({*source});
  });
  connect(a->saveFrame, &QAction::triggered, this, [this] {
    const QString path =
        AskSavePath(this, tr("Save frame with overlay"),
                    suggestedPath(QString("frame-%1.png").arg(view_->frameIndex())),
                    tr("Images (*.png *.jpg)"));
    if (!path.isEmpty()) saveFrame(path);
  });
  connect(a->exportAngles, &QAction::triggered, this, [this] {
    const QString path = AskSavePath(this, tr("Export angle file"), suggestedPath("tsv"),
                                     tr("Angle files (*.tsv);;All files (*)"));
    if (!path.isEmpty()) exportAngles(path);
  });
  connect(a->exportVal, &QAction::triggered, this,
          [this] { robot_->exportValInteractive(suggestedPath("val")); });
  connect(a->quit, &QAction::triggered, this, &QWidget::close);
  connect(a->play, &QAction::triggered, player_, &VideoPlayer::togglePlay);
  connect(a->stepBack, &QAction::triggered, player_, [this] { player_->step(-1); });
  connect(a->stepForward, &QAction::triggered, player_, [this] { player_->step(1); });
  connect(a->first, &QAction::triggered, player_, &VideoPlayer::first);
  connect(a->last, &QAction::triggered, player_, &VideoPlayer::last);
  connect(a->faster, &QAction::triggered, this, [this] { bar_->setSpeed(bar_->speed() * 2); });
  connect(a->slower, &QAction::triggered, this, [this] { bar_->setSpeed(bar_->speed() / 2); });
  connect(a->zoomIn, &QAction::triggered, view_, &VideoView::zoomIn);
  connect(a->zoomOut, &QAction::triggered, view_, &VideoView::zoomOut);
  connect(a->zoomFit, &QAction::triggered, view_, &VideoView::zoomToFit);
  connect(a->toolPan, &QAction::triggered, this, [this] { view_->setTool(VideoView::Tool::kPan); });
  connect(a->toolRoi, &QAction::triggered, this, [this] { view_->setTool(VideoView::Tool::kRoi); });
  connect(a->toolShoulder, &QAction::triggered, this,
          [this] { view_->setTool(VideoView::Tool::kShoulder); });
  connect(a->toolJoints, &QAction::triggered, this,
          [this] { view_->setTool(VideoView::Tool::kJoints); });
  connect(a->clearRoi, &QAction::triggered, this, [this] { settings_->setRoi(std::nullopt); });
  connect(a->clearShoulder, &QAction::triggered, this,
          [this] { settings_->setShoulder(std::nullopt); });
  connect(a->analyze, &QAction::triggered, this, &MainWindow::startAnalysis);
  connect(a->cancel, &QAction::triggered, job_, &AnalysisJob::cancel);
  connect(a->estimateBackground, &QAction::triggered, this, [this] {
    const std::optional<int> k = AskBackgroundFrames(this);
    if (!k) return;
    const QString path =
        AskSavePath(this, tr("Save background image"), RecentFiles::lastDir() + "/background.png",
                    tr("Images (*.png *.bmp)"));
    if (!path.isEmpty()) estimateBackground(*k, path);
  });
  connect(actions_, &AppActions::overlayChanged, this, &MainWindow::applyOverlayOptions);
  connect(angles_, &AnglePanel::armChanged, this, &MainWindow::followPickedArm);
  connect(a->about, &QAction::triggered, this, [this] { ShowAbout(this); });

  connect(bar_, &PlaybackBar::seekRequested, player_, &VideoPlayer::seek);
  connect(bar_, &PlaybackBar::speedChanged, player_, &VideoPlayer::setSpeed);
  connect(plot_, &AnglePlot::frameClicked, player_, [this](int f) {
    player_->pause();
    player_->seek(f);
  });
  connect(player_, &VideoPlayer::frameShown, this, &MainWindow::showFrame);
  connect(player_, &VideoPlayer::playingChanged, this, [this](bool playing) {
    actions_->play->setIcon(MakeIcon(playing ? IconKind::kPause : IconKind::kPlay));
  });
  connect(player_, &VideoPlayer::opened, this, [this](const VideoInfo& info) {
    bar_->setFrameCount(info.frame_count, info.fps);
    plot_->setFrameRange(info.frame_count, info.fps);
    angles_->updateTimeAxisButton();
    if (!takePendingResults()) {
      session_path_.clear();  // another input: the session no longer describes what is shown
      results_.clear();
      job_->forgetResult();
      refreshViews();
      robot_->setAngleFile(QString());
      unsaved_ = false;
    }
    recent_->addInput(player_->inputs().first());
    setWindowTitle(QString("%1 — armmimic").arg(QFileInfo(player_->inputs().first()).fileName()));
    log_->info(tr("Opened %1").arg(DescribeSource(info)));
    statusBar()->clearMessage();  // an earlier error is not about this input
    updateStatus();
  });
  connect(player_, &VideoPlayer::error, log_, &LogView::error);
  connect(view_, &VideoView::roiSelected, this, [this](const QRect& r) {
    settings_->setRoi(cv::Rect(r.x(), r.y(), r.width(), r.height()));
  });
  connect(view_, &VideoView::shoulderPicked, this,
          [this](const QPointF& p) { settings_->setShoulder(cv::Point2d(p.x(), p.y())); });
  connect(view_, &VideoView::jointPicked, this, [this](int joint, const QPointF& p) {
    settings_->setJoint(joint, cv::Point2d(p.x(), p.y()));
  });
  connect(settings_, &EngineSettingsPanel::roiChanged, this,
          [this](const std::optional<cv::Rect>& r) {
            view_->setRoi(r ? std::optional<QRect>(QRect(r->x, r->y, r->width, r->height))
                            : std::nullopt);
          });
  connect(settings_, &EngineSettingsPanel::shoulderChanged, this,
          [this](const std::optional<cv::Point2d>& s) {
            view_->setShoulder(s ? std::optional<QPointF>(QPointF(s->x, s->y)) : std::nullopt);
          });
  connect(log_, &LogView::errorShown, this, [this](const QString& text) {
    statusBar()->showMessage(text, 10000);
    log_dock_->show();
    log_dock_->raise();
  });
  connect(robot_, &RobotPanel::message, log_, &LogView::info);
  connect(robot_, &RobotPanel::errorOccurred, log_, &LogView::error);
  connect(robot_, &RobotPanel::linkStateChanged, status_, &StatusLine::setLinkText);
}

void MainWindow::wireAnalysis() {
  connect(job_, &AnalysisJob::started, this, [this] { setBusy(true); });
  connect(job_, &AnalysisJob::phase, status_, &StatusLine::setPhase);
  connect(job_, &AnalysisJob::progress, status_, &StatusLine::setProgress);
  connect(job_, &AnalysisJob::estimated, this,
          [this](const QString& text) { log_->info(tr("Estimated: %1").arg(text)); });
  connect(job_, &AnalysisJob::measured, this, [this](const ArmMeasurement& m) {
    results_.add(m);
    if (!throttle_.isActive()) throttle_.start();
  });
  connect(job_, &AnalysisJob::liveFrame, this, &MainWindow::showFrame);
  connect(job_, &AnalysisJob::failed, this, [this](const QString& message, const QString& key) {
    log_->error(settings_->showError(key, message));
  });
  connect(job_, &AnalysisJob::backgroundReady, this, [this](const QString& path) {
    settings_->setBackgroundImage(path);
    log_->info(tr("Background saved to %1 and selected for the analysis").arg(path));
  });
  connect(job_, &AnalysisJob::finished, this, [this](bool ok, bool cancelled) {
    setBusy(false);
    if (!ok && before_run_) {
      // A run that failed changes nothing: the angles, overlay, plot and plan shown before it.
      results_ = before_run_->results;
      unsaved_ = before_run_->unsaved;
      robot_->setAnglesChanging(false);
    }
    const bool analysis = before_run_.has_value();
    before_run_.reset();
    refreshViews();
    updateStatus();
    if (ok && analysis) {
      unsaved_ = results_.rows() > 0;
      if (!job_->resultPath().isEmpty()) log_->info(job_->describeResult(cancelled));
      // The plan follows the angles shown (the arm picked, with both arms).
      robot_->setAngleFile(job_->resultPaths().value(angles_->arm(), job_->resultPath()));
      ui_->plotDock->raise();  // the angles just measured, not old errors
    }
  });
}

void MainWindow::wireMimic() {
  mimic_->setSources(
      [this] {
        AnalysisOptions options = settings_->options();
        options.inputs.clear();
        for (const QString& s : player_->inputs()) options.inputs.push_back(s.toStdString());
        if (AnalysedArms(options).size() > 1) {  // the robot follows the arm picked
          options.engine.pose.side = angles_->arm() == 1 ? PoseSide::kRight : PoseSide::kLeft;
        }
        if (player_->isLive()) player_->close();  // the live run reads the camera itself
        return options;
      },
      [this] { return robot_->plannerOptions(); }, robot_->link());
  mimic_->setProfileSource([this] { return robot_->profile(); });
  // The live frames fill the big view too while the robot follows.
  connect(mimic_->controller(), &MimicController::frameReady, this,
          [this](const QImage& image, int index, const ArmMeasurement& m) {
            view_->setFrame(image, index, -1);
            view_->setMeasurement(m);
          });
  connect(mimic_, &MimicPanel::message, log_, &LogView::info);
  connect(mimic_, &MimicPanel::errorOccurred, log_, &LogView::error);
}

void MainWindow::setBusy(bool busy) {
  status_->setBusy(busy);
  actions_->analyze->setEnabled(!busy);
  actions_->estimateBackground->setEnabled(!busy);
  actions_->cancel->setEnabled(busy || robot_->link()->isSending());
  settings_->setEnabled(!busy);
}

void MainWindow::openInputs(const QStringList& inputs) {
  if (inputs.isEmpty()) return;
  if (job_->isRunning()) {
    log_->error(tr("An analysis is running: cancel it (Esc) before opening another input"));
    return;
  }
  player_->open(inputs);  // the previous input and its results stay until this one opens
}

bool MainWindow::startAnalysis() {
  if (!player_->isOpen()) {
    log_->error(tr("Open a video, images or a camera first (File > Open)"));
    return false;
  }
  AnalysisOptions options = settings_->options();
  options.inputs.clear();
  for (const QString& s : player_->inputs()) options.inputs.push_back(s.toStdString());
  live_ = player_->isLive();
  if (live_) player_->close();  // the analysis reads the camera itself
  // Refused options change nothing; a run shows its own rows, and the plan of the angles it
  // replaces may not be sent while it lasts.
  if (!job_->start(options, live_)) return false;
  before_run_ = Shown{results_, unsaved_};
  results_.clear();
  pending_.reset();
  robot_->setAnglesChanging(true);
  return true;
}

std::vector<NamedPath> MainWindow::sessionInputs() const {
  return SessionInputs(player_->isOpen() ? player_->inputs() : QStringList(), settings_->options());
}

bool MainWindow::refuseInput(const QString& what, const QString& path) {
  const QString refusal = SameFileRefusal(sessionInputs(), what, path);
  if (!refusal.isEmpty()) log_->error(refusal);
  return !refusal.isEmpty();
}

bool MainWindow::exportAngles(const QString& path) {
  if (refuseInput(tr("the angle file"), path)) return false;
  const QString error = job_->exportResult(path);
  if (!error.isEmpty()) {
    log_->error(error);
    return false;
  }
  RecentFiles::rememberDir(path);
  log_->info(tr("Exported the angle file to %1").arg(path));
  unsaved_ = false;
  return true;
}

bool MainWindow::saveFrame(const QString& path) {
  if (refuseInput(tr("the frame image"), path)) return false;
  const QString error = view_->saveWithOverlay(path);
  if (!error.isEmpty()) {
    log_->error(error);
    return false;
  }
  RecentFiles::rememberDir(path);
  log_->info(tr("Saved frame %1 with its overlay to %2").arg(view_->frameIndex()).arg(path));
  return true;
}

bool MainWindow::estimateBackground(int frames, const QString& path) {
  if (!player_->isOpen() || player_->isLive()) {
    log_->error(tr("Open a video first: the background is the mean of its first frames"));
    return false;
  }
  // The estimate reads only the video; it may replace the background image chosen before.
  const QString refusal =
      SameFileRefusal(SessionInputs(player_->inputs(), {}), tr("the background image"), path);
  if (!refusal.isEmpty()) {
    log_->error(refusal);
    return false;
  }
  return job_->startBackground(player_->inputs(), 0, frames, path);
}

void MainWindow::showFrame(int index, const QImage& image, double time_s) {
  time_s_ = time_s;
  const int count = live_ ? -1 : player_->frameCount();
  view_->setFrame(image, index, count);
  view_->setMeasurement(results_.at(index));
  bar_->setPosition(index, time_s);
  plot_->setCursorFrame(index);
  robot_->setVideoFrame(index);
  updateStatus();
}

void MainWindow::refreshViews() {
  angles_->setArmCount(results_.arms());
  plot_->setResults(results_, angles_->arm());
  view_->setMeasurement(results_.at(view_->frameIndex()));
}

void MainWindow::applyOverlayOptions() {
  OverlayOptions o = actions_->overlayOptions();
  o.arm = angles_->arm();
  view_->setOverlayOptions(o);
}

void MainWindow::followPickedArm() {
  applyOverlayOptions();
  refreshViews();
  if (!job_->isRunning() && job_->resultPaths().size() > 1) {
    robot_->setAngleFile(job_->resultPaths().value(angles_->arm()));
  }
  updateStatus();
}

void MainWindow::updateStatus() {
  if (!player_->isOpen() && !job_->isRunning()) return status_->showNoVideo();
  const OverlayTexts t = view_->overlayTexts();
  const bool still = player_->isOpen() && !player_->isLive() && player_->info().fps <= 0;
  status_->showFrame(t.frame, still ? std::nan("") : time_s_, t.state);
}

void MainWindow::restoreSettings() {
  QSettings s;
  if (!restoreGeometry(s.value("window/geometry").toByteArray()) && screen()) {
    // First start: most of the screen, so the video, the panels and the plot all have room.
    const QRect avail = screen()->availableGeometry();
    resize(avail.width() * 85 / 100, avail.height() * 85 / 100);
  }
  restoreState(s.value("window/state").toByteArray());
  settings_->load(s);
  actions_->loadSettings(s);
  bar_->loadSettings(s);
  robot_->load(s);
}

void MainWindow::saveSettings() const {
  QSettings s;
  s.setValue("window/geometry", saveGeometry());
  s.setValue("window/state", saveState());
  settings_->save(s);
  actions_->saveSettings(s);
  bar_->saveSettings(s);
  robot_->save(s);
}

}  // namespace armmimic::gui
