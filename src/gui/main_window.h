// MainWindow: a thin shell that creates one widget per task and wires them together. No analysis,
// decoding or serial code lives here: that is in VideoPlayer, AnalysisJob and the robot panel.
#pragma once

#include <QMainWindow>
#include <QStringList>
#include <QTimer>

#include "armmimic/core/same_file.h"
#include "result_store.h"

class QDockWidget;

namespace armmimic::gui {

class AnalysisJob;
class AnglePlot;
class AppActions;
class EngineSettingsPanel;
class LogView;
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

  VideoPlayer* player() const { return player_; }
  VideoView* view() const { return view_; }
  PlaybackBar* playbackBar() const { return bar_; }
  EngineSettingsPanel* settingsPanel() const { return settings_; }
  AnalysisJob* job() const { return job_; }
  AnglePlot* plot() const { return plot_; }
  LogView* log() const { return log_; }
  RobotPanel* robotPanel() const { return robot_; }
  StatusLine* statusLine() const { return status_; }
  AppActions* actions() const { return actions_; }
  const ResultStore& results() const { return results_; }

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  QDockWidget* dock(const QString& title, const QString& name, QWidget* w, Qt::DockWidgetArea a);
  void wireActions();
  void wireAnalysis();
  void refreshViews();
  void updateStatus();
  void setBusy(bool busy);
  void showFrame(int index, const QImage& image, double time_s);
  void restoreSettings();
  void saveSettings() const;
  // The files the session reads, which no export may replace.
  std::vector<NamedPath> sessionInputs() const;
  // Logs why `path` may not be written as `what`; true when refused.
  bool refuseInput(const QString& what, const QString& path);

  AppActions* actions_;
  VideoPlayer* player_;
  VideoView* view_;
  PlaybackBar* bar_;
  EngineSettingsPanel* settings_;
  AnglePlot* plot_;
  LogView* log_;
  RobotPanel* robot_;
  AnalysisJob* job_;
  RecentFiles* recent_ = nullptr;
  QDockWidget* log_dock_ = nullptr;
  ResultStore results_;
  QTimer throttle_;  // one-shot: redraw the overlay and the plot at most every 40 ms
  StatusLine* status_;
  double time_s_ = 0;
  bool live_ = false;
};

}  // namespace armmimic::gui
