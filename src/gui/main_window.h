// MainWindow: a thin shell that wires one widget per task together; the docks and the central
// view are laid out in ui/main_window.ui. No analysis, decoding or serial code lives here: that
// is in VideoPlayer, AnalysisJob and the robot panel. The file commands (angle files, sessions,
// CSV, drops, the question before closing) are in main_window_files.cpp.
#pragma once

#include <memory>
#include <optional>

#include <QMainWindow>
#include <QStringList>
#include <QTimer>

#include "armmimic/core/angle_csv.h"
#include "armmimic/core/same_file.h"
#include "result_store.h"

class QDockWidget;
namespace Ui {
class MainWindowForm;
}

namespace armmimic::gui {

class AnalysisJob;
class AnglePanel;
class AnglePlot;
class AppActions;
class EngineSettingsPanel;
class LogView;
class MimicPanel;
class PlaybackBar;
class RecentFiles;
class RobotPanel;
class StatusLine;
class VideoPlayer;
class VideoView;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Commands without dialogs (the menu actions ask for the paths, then call these).
  void openInputs(const QStringList& inputs);
  bool startAnalysis();
  bool exportAngles(const QString& path);
  bool saveFrame(const QString& path);
  bool estimateBackground(int frames, const QString& path);
  // File > Open angle file: the plot, the overlay (with the video named in its header, when it
  // is beside the file) and the robot panel; the options restored from its header.
  bool openAngleFile(const QString& path);
  bool openSession(const QString& path);
  bool saveSession(const QString& path);
  // The results as CSV: every row, or those of the frames in the plot's view.
  bool exportCsv(const QString& path, CsvStyle style, bool visible_only);
  // A file name for `suffix` after the open video's ("scene.csv"), in the last folder used.
  QString suggestedPath(const QString& suffix) const;
  // Results of an analysis that are in no exported file or saved session yet.
  bool hasUnsavedResults() const { return unsaved_; }

  VideoPlayer* player() const { return player_; }
  VideoView* view() const { return view_; }
  PlaybackBar* playbackBar() const { return bar_; }
  EngineSettingsPanel* settingsPanel() const { return settings_; }
  AnalysisJob* job() const { return job_; }
  AnglePlot* plot() const { return plot_; }
  AnglePanel* anglePanel() const { return angles_; }
  LogView* log() const { return log_; }
  RobotPanel* robotPanel() const { return robot_; }
  MimicPanel* mimicPanel() const { return mimic_; }
  StatusLine* statusLine() const { return status_; }
  AppActions* actions() const { return actions_; }
  const ResultStore& results() const { return results_; }

 protected:
  void closeEvent(QCloseEvent* event) override;
  // Asks before closing while sending, or with unsaved results. True: close.
  bool confirmClose();
  bool confirmQuitDuringAnalysis();
  QString incompleteResultPath() const;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void wireActions();
  void wireFileActions();
  void askCsvExport(bool visible_only);
  // After an input opened: the results waiting for it (an angle file or a session), if any.
  bool takePendingResults();
  void showResults(const ResultStore& results, const QString& angle_path);
  void wireAnalysis();
  void wireMimic();
  // The calibration buttons of the Analysis panel: the pose network's joints, and the
  // standstill's estimated joints shown as handles to accept or drag (main_window_calibration.cpp).
  void wireCalibration();
  void refreshViews();
  // The overlay's options as the actions set them, its texts about the arm picked.
  void applyOverlayOptions();
  // The arm picked on the angle panel (both arms analysed): the plot, the overlay's angles and
  // the robot's angle file follow it.
  void followPickedArm();
  void updateStatus();
  void setBusy(bool busy);
  void showFrame(int index, const QImage& image, double time_s);
  void restoreSettings();
  void saveSettings() const;
  // The files the session reads, which no export may replace.
  std::vector<NamedPath> sessionInputs() const;
  // Where a send writes its plan (and keeps its journal): SESSION.val beside the session opened
  // or saved, else VIDEO.val beside the video, else beside an angle file opened; "" when none.
  QString planFilePath() const;
  // Logs why `path` may not be written as `what`; true when refused.
  bool refuseInput(const QString& what, const QString& path);

  std::unique_ptr<Ui::MainWindowForm> ui_;
  AppActions* actions_;
  VideoPlayer* player_;
  AnalysisJob* job_;
  VideoView* view_;
  PlaybackBar* bar_;
  EngineSettingsPanel* settings_;
  AnglePanel* angles_;
  AnglePlot* plot_;
  LogView* log_;
  RobotPanel* robot_;
  MimicPanel* mimic_ = nullptr;
  RecentFiles* recent_ = nullptr;
  QDockWidget* log_dock_ = nullptr;
  ResultStore results_;
  QTimer throttle_;  // one-shot: redraw the overlay and the plot at most every 40 ms
  StatusLine* status_;
  double time_s_ = 0;
  bool live_ = false;
  bool unsaved_ = false;
  QString session_path_;  // the session opened or saved last, while its input stays open
  struct Pending {
    ResultStore results;
    QString angle_path;
    int frame = -1;  // the frame to show (-1: the first)
  };
  std::optional<Pending> pending_;  // results waiting for their video to open
  struct Shown {
    ResultStore results;
    bool unsaved = false;
  };
  std::optional<Shown> before_run_;  // while an analysis runs: what it replaces, if it succeeds
};

}  // namespace armmimic::gui
