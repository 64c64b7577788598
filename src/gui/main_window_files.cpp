// MainWindow's file commands: angle files and sessions in, CSV and sessions out, what a dropped
// file is, where a plan is written, and the questions before closing (an analysis or a send
// running, results unsaved).
// Length: every file the window reads or writes, and what becomes of them on closing, in one
// place; each function is short.
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>

#include "analysis_job.h"
#include "angle_panel.h"
#include "angle_plot.h"
#include "app_actions.h"
#include "armmimic/engines/recorded_options.h"
#include "csv_export_dialog.h"
#include "engine_settings_panel.h"
#include "log_view.h"
#include "main_window.h"
#include "prompts.h"
#include "recent_files.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "session_file.h"
#include "ui_main_window.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::gui {

void MainWindow::wireFileActions() {
  AppActions* a = actions_;
  connect(a->openAngles, &QAction::triggered, this, [this] {
    const QString path = AskOpenPath(this, tr("Open angle file"), RecentFiles::lastDir(),
                                     tr("Angle files (*.tsv);;All files (*)"));
    if (!path.isEmpty()) openAngleFile(path);
  });
  connect(a->openSession, &QAction::triggered, this, [this] {
    const QString path =
        AskOpenPath(this, tr("Open session"), RecentFiles::lastDir(),
                    tr("Sessions (*.%1 *.json);;All files (*)").arg(kSessionSuffix));
    if (!path.isEmpty()) openSession(path);
  });
  connect(a->saveSession, &QAction::triggered, this, [this] {
    const QString path = AskSavePath(this, tr("Save session"), suggestedPath(kSessionSuffix),
                                     tr("Sessions (*.%1)").arg(kSessionSuffix));
    if (!path.isEmpty()) saveSession(path);
  });
  connect(a->exportCsv, &QAction::triggered, this, [this] { askCsvExport(false); });
  connect(angles_, &AnglePanel::rangeCsvRequested, this, [this] { askCsvExport(true); });
  connect(angles_, &AnglePanel::message, log_, &LogView::info);
  connect(angles_, &AnglePanel::errorOccurred, log_, &LogView::error);
  connect(robot_, &RobotPanel::sendingChanged, this,
          [this](bool sending) { actions_->cancel->setEnabled(sending || job_->isRunning()); });
  connect(a->cancel, &QAction::triggered, robot_, [this] {
    if (robot_->link()->isSending()) robot_->link()->abort();
  });
  connect(player_, &VideoPlayer::opened, this,
          [this] { angles_->setSuggestedPath(suggestedPath("plot.png")); });
  connect(player_, &VideoPlayer::error, this, [this] {
    // The video an angle file or session names did not open: its results still show.
    if (!pending_) return;
    const Pending p = *pending_;
    pending_.reset();
    showResults(p.results, p.angle_path);
  });
}

QString MainWindow::suggestedPath(const QString& suffix) const {
  QString base = "angles";
  if (player_->isOpen() && !player_->isLive() && !player_->inputs().isEmpty()) {
    base = QFileInfo(player_->inputs().first()).completeBaseName();
  } else if (!job_->resultPath().isEmpty() && !job_->resultPath().contains("/angles-")) {
    base = QFileInfo(job_->resultPath()).completeBaseName();
  }
  // "frame-12.png" and the like are added to the name; "csv" replaces the suffix.
  const QString name = suffix.contains('.') ? base + "-" + suffix : base + "." + suffix;
  return RecentFiles::lastDir().isEmpty() ? name : RecentFiles::lastDir() + "/" + name;
}

QString MainWindow::planFilePath() const {
  auto beside = [](const QString& path) {
    const QFileInfo f(path);
    return f.isDir() ? f.absoluteFilePath() + ".val"
                     : f.absoluteDir().filePath(f.completeBaseName() + ".val");
  };
  if (!session_path_.isEmpty()) return beside(session_path_);
  if (player_->isOpen() && !player_->isLive() && !player_->inputs().isEmpty()) {
    return beside(player_->inputs().first());
  }
  const QString angles = job_->resultPath();
  if (!angles.isEmpty() && !angles.startsWith(job_->resultFolder() + "/")) return beside(angles);
  return QString();
}

void MainWindow::showResults(const ResultStore& results, const QString& angle_path) {
  results_ = results;
  if (results_.arms() > 1) angles_->setArm(0);  // the left arm's file is `angle_path`
  refreshViews();
  robot_->setAngleFile(angle_path);
  unsaved_ = false;  // they come from a file
  ui_->plotDock->raise();
  updateStatus();
}

bool MainWindow::takePendingResults() {
  if (!pending_) return false;
  const Pending p = *pending_;
  pending_.reset();
  showResults(p.results, p.angle_path);
  // After the player's own first request for frame 0, which it makes once this returns.
  if (p.frame < 0) return true;
  QMetaObject::invokeMethod(
      player_, [player = player_, frame = p.frame] { player->seek(frame); }, Qt::QueuedConnection);
  return true;
}

bool MainWindow::openAngleFile(const QString& path) {
  if (job_->isRunning()) {
    log_->error(tr("An analysis is running: cancel it (Esc) before opening an angle file"));
    return false;
  }
  AngleFile file;
  Status st = ReadAngleFile(path.toStdString(), &file);
  AnalysisOptions recorded;
  std::vector<std::string> skipped;
  if (st) st = RecordedAnalysisOptions(file, path.toStdString(), &recorded, &skipped);
  if (!st) {
    log_->error(QString::fromStdString(st.message()));
    return false;
  }
  // The engine, start frame and parameters the file was made with; the input images and the
  // other engines' parameters stay.
  AnalysisOptions o = settings_->options();
  o.engine.kind = recorded.engine.kind;
  switch (recorded.engine.kind) {
    case EngineKind::kBgsub:
      o.engine.bgsub = recorded.engine.bgsub;
      break;
    case EngineKind::kLk:
      o.engine.lk = recorded.engine.lk;
      break;
    case EngineKind::kMarker:
      o.engine.marker = recorded.engine.marker;
      break;
    case EngineKind::kPose:
      o.engine.pose = recorded.engine.pose;
      break;
    case EngineKind::kHybrid:  // its own parameters and the two engines' it runs
      o.engine.hybrid = recorded.engine.hybrid;
      o.engine.lk = recorded.engine.lk;
      o.engine.bgsub = recorded.engine.bgsub;
      break;
  }
  o.start = recorded.start;
  settings_->setOptions(o);
  for (const std::string& s : skipped) {
    log_->info(tr("%1: setting not restored: %2").arg(path, QString::fromStdString(s)));
  }
  ResultStore results;
  for (const AngleRow& row : file.rows) results.add(ArmMeasurement::FromRow(row));
  job_->adoptResult(path);
  session_path_.clear();
  RecentFiles::rememberDir(path);
  log_->info(tr("Opened the angle file %1: %2 rows, engine %3")
                 .arg(path)
                 .arg(file.rows.size())
                 .arg(QString::fromStdString(file.Meta("engine"))));
  // Its video (or the marker engine's folder of views), when it lies beside the file, for the
  // overlay. A single image named by a marker file is one view of several: not opened alone.
  const QString video = QFileInfo(path).dir().filePath(QString::fromStdString(file.Meta("source")));
  const QFileInfo source(video);
  const bool openable = !file.Meta("source").empty() &&
                        (source.isDir() || (source.isFile() && file.Meta("engine") != "marker"));
  const bool same = player_->isOpen() && QFileInfo(player_->inputs().first()) == source;
  if (openable && !same) {
    pending_ = Pending{results, path, -1};
    openInputs({video});
    return true;
  }
  if (!same) {
    const double fps = QString::fromStdString(file.Meta("fps")).toDouble();
    plot_->setFrameRange(file.rows.empty() ? 1 : file.rows.back().frame + 1, fps);
    log_->info(tr("%1: its video %2 is not beside it; open the video to see the overlay")
                   .arg(path, QString::fromStdString(file.Meta("source", "?"))));
  }
  showResults(results, path);
  return true;
}

bool MainWindow::openSession(const QString& path) {
  if (job_->isRunning()) {
    log_->error(tr("An analysis is running: cancel it (Esc) before opening a session"));
    return false;
  }
  Session s;
  QString error = ReadSession(path, &s);
  if (error.isEmpty() && !s.angle_text.isEmpty()) {
    QStringList texts = {s.angle_text};
    if (!s.right_angle_text.isEmpty()) texts << s.right_angle_text;
    error = job_->adoptResultTexts(texts, s.options);
  }
  if (!error.isEmpty()) {
    log_->error(error);
    return false;
  }
  settings_->setOptions(s.options);
  ResultStore results;
  if (!s.angle_text.isEmpty()) {
    const Status st = ReadResults(job_->resultPaths(), &results);
    if (!st) {
      log_->error(tr("%1: its results: %2").arg(path, QString::fromStdString(st.message())));
      return false;
    }
  }
  RecentFiles::rememberDir(path);
  session_path_ = QFileInfo(path).absoluteFilePath();  // its plan and journal go beside it
  log_->info(tr("Opened the session %1").arg(path));
  if (!s.ignored.isEmpty()) log_->info(tr("%1: %2").arg(path, s.ignored));
  const QString angles = s.angle_text.isEmpty() ? QString() : job_->resultPath();
  if (s.inputs.isEmpty()) {
    showResults(results, angles);
    return true;
  }
  pending_ = Pending{results, angles, s.frame};
  openInputs(s.inputs);
  return true;
}

bool MainWindow::saveSession(const QString& path) {
  if (refuseInput(tr("the session file"), path)) return false;
  Session s;
  if (player_->isOpen() && !player_->isLive()) s.inputs = player_->inputs();
  s.options = settings_->options();
  s.frame = view_->frameIndex();
  const QStringList results = job_->resultPaths();  // one, or the left and right arm's
  for (int i = 0; i < results.size() && i < 2; ++i) {
    QFile f(results[i]);
    if (f.open(QIODevice::ReadOnly)) {
      (i == 0 ? s.angle_text : s.right_angle_text) = QString::fromUtf8(f.readAll());
    }
  }
  const QString error = WriteSession(path, s);
  if (!error.isEmpty()) {
    log_->error(error);
    return false;
  }
  RecentFiles::rememberDir(path);
  session_path_ = QFileInfo(path).absoluteFilePath();
  log_->info(tr("Saved the session to %1").arg(path));
  unsaved_ = false;
  return true;
}

bool MainWindow::exportCsv(const QString& path, CsvStyle style, bool visible_only) {
  if (refuseInput(tr("the CSV file"), path)) return false;
  std::vector<AngleRow> rows;
  if (visible_only) {
    rows = plot_->visibleRows();
  } else {
    for (const auto& [frame, m] : results_.all()) {
      if (m.row()) rows.push_back(m.ToRow());
    }
  }
  if (rows.empty()) {
    log_->error(visible_only ? tr("No measured frames in the plot's view to export")
                             : tr("Nothing to export yet: run the analysis first (F5)"));
    return false;
  }
  const Status st = WriteAnglesCsv(path.toStdString(), rows, plot_->hasFileColumn(), style);
  if (!st) {
    log_->error(QString::fromStdString(st.message()));
    return false;
  }
  RecentFiles::rememberDir(path);
  log_->info(tr("Exported %1 rows as CSV to %2").arg(rows.size()).arg(path));
  if (!visible_only) unsaved_ = false;
  return true;
}

void MainWindow::askCsvExport(bool visible_only) {
  const auto [first, last] = plot_->visibleFrames();
  const QString range = tr("frames %1–%2").arg(first).arg(last);
  CsvExportDialog dialog(this, suggestedPath("csv"), results_.rows() > 0 ? range : QString(),
                         visible_only);
  if (dialog.exec() == QDialog::Accepted) {
    exportCsv(dialog.path(), dialog.style(), dialog.visibleOnly());
  }
}

// Where the rows of an analysis stopped by quitting are kept: beside the video (or in the last
// folder used), never over an existing file.
QString MainWindow::incompleteResultPath() const {
  QString dir = RecentFiles::lastDir(), base = "angles";
  if (player_->isOpen() && !player_->isLive() && !player_->inputs().isEmpty()) {
    const QFileInfo input(player_->inputs().first());
    dir = input.absolutePath();
    base = input.isDir() ? input.fileName() : input.completeBaseName();
  }
  if (dir.isEmpty()) dir = QDir::homePath();
  QString path = QDir(dir).filePath(base + "-incomplete.tsv");
  for (int n = 2; QFileInfo::exists(path); ++n) {
    path = QDir(dir).filePath(QString("%1-incomplete-%2.tsv").arg(base).arg(n));
  }
  return path;
}

// Quitting during an analysis: asked first; when the operator quits anyway, the run stops and
// its rows so far are kept as an angle file marked complete=no, as `armmimic-cli analyze` keeps
// them when interrupted. True: close.
bool MainWindow::confirmQuitDuringAnalysis() {
  if (!job_->isRunning() || !before_run_) return true;
  const QString path = incompleteResultPath();
  QMessageBox box(QMessageBox::Warning, tr("Quit during the analysis?"),
                  tr("The analysis is running: %1 frames measured so far.").arg(results_.size()),
                  QMessageBox::Cancel, this);
  box.setObjectName("quitDuringAnalysis");
  box.setInformativeText(tr("Quitting stops it and keeps the rows so far in %1, marked as an "
                            "incomplete result (complete=no).")
                             .arg(path));
  QPushButton* quit = box.addButton(tr("Keep the rows and quit"), QMessageBox::DestructiveRole);
  box.setDefaultButton(QMessageBox::Cancel);
  box.exec();
  if (box.clickedButton() != static_cast<QAbstractButton*>(quit)) return false;
  bool stopped = false;  // the run ended by the cancel, its rows so far the result
  const QMetaObject::Connection watch =
      connect(job_, &AnalysisJob::finished, this,
              [&](bool ok, bool cancelled) { stopped = ok && cancelled; });
  job_->cancel();
  const bool ended = job_->waitForFinished(30000);
  disconnect(watch);
  if (!ended) {
    log_->error(tr("The analysis did not stop within 30 s; quit again to wait longer"));
    return false;
  }
  // A run that ended on its own meanwhile is an ordinary result: the questions below.
  return !stopped || exportAngles(path);
}

bool MainWindow::confirmClose() {
  if (!confirmQuitDuringAnalysis()) return false;
  if (robot_->link()->isSending()) {
    QMessageBox box(QMessageBox::Warning, tr("Quit while sending?"),
                    tr("A program is being sent to the robot. Quitting aborts the send after the "
                       "line in flight."),
                    QMessageBox::Cancel, this);
    box.setObjectName("quitWhileSending");
    QPushButton* quit = box.addButton(tr("Abort and quit"), QMessageBox::DestructiveRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    if (box.clickedButton() != static_cast<QAbstractButton*>(quit)) return false;
    robot_->link()->abort();
  }
  if (unsaved_) {
    QMessageBox box(QMessageBox::Question, tr("Quit without saving?"),
                    tr("The angles of the last analysis are not saved."),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setInformativeText(
        tr("Export them as an angle file, or quit and lose them. (A saved "
           "session keeps them too: File > Save session.)"));
    box.setObjectName("quitUnsaved");
    box.button(QMessageBox::Save)->setText(tr("Export angle file…"));
    box.setDefaultButton(QMessageBox::Save);
    const int answer = box.exec();
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Save) {
      const QString path = AskSavePath(this, tr("Export angle file"), suggestedPath("tsv"),
                                       tr("Angle files (*.tsv);;All files (*)"));
      if (path.isEmpty() || !exportAngles(path)) return false;
    }
  }
  return true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!confirmClose()) {
    event->ignore();
    return;
  }
  job_->cancel();
  job_->waitForFinished(5000);
  saveSettings();
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  QStringList media;
  bool any = false;
  for (const QUrl& url : event->mimeData()->urls()) {
    if (!url.isLocalFile()) continue;
    const QString file = url.toLocalFile();
    any = true;
    switch (ClassifyFile(file)) {
      case FileKind::kAngleFile:
        openAngleFile(file);
        break;
      case FileKind::kValProgram:
        ui_->robotDock->show();
        ui_->robotDock->raise();
        robot_->setValProgram(file);
        break;
      case FileKind::kSession:
        openSession(file);
        break;
      case FileKind::kMedia:
        media << file;
        break;
    }
  }
  if (!media.isEmpty()) openInputs(media);
  if (any) event->acceptProposedAction();
}

}  // namespace armmimic::gui
