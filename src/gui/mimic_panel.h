// MimicPanel: the "Mimic live" mode. The robot follows the person while the video (paced at its
// frame rate) or the camera is analysed: the live overlay, a robot preview that follows the
// planned (filtered, limited) targets rather than the raw angles, the latency, and a large Stop
// button with an application-wide shortcut (F12 or Ctrl+.). Nothing moves until the operator
// ticks that the mapping and limits shown are right; a change to them clears the tick. The
// dead-man option lets the robot move only while "Hold to move" is held (mouse, or Space with
// the button focused). The work is MimicController's; the window wires the sources in.
#pragma once

#include <functional>

#include <QString>
#include <QTimer>
#include <QWidget>

#include "armmimic/engines/analysis.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"

class QCheckBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QShortcut;

namespace armmimic::gui {

class MimicController;
class RobotLink;
class RobotPreview;
class VideoView;

class MimicPanel : public QWidget {
  Q_OBJECT
 public:
  explicit MimicPanel(QWidget* parent = nullptr);
  ~MimicPanel() override;

  // Where the options come from: the Analysis panel with the open input, the Robot panel's
  // planner options, and its link (connected to a port or the simulated controller).
  void setSources(std::function<AnalysisOptions()> analysis,
                  std::function<robot::PlannerOptions()> planner, RobotLink* link);

  // The controller profile the Robot panel's Controller tab picked (default: the built-in one).
  void setProfileSource(std::function<robot::ControllerProfile()> profile) {
    profile_source_ = std::move(profile);
  }

  MimicController* controller() const { return controller_; }
  VideoView* view() const { return view_; }
  RobotPreview* preview() const { return preview_; }

  // The buttons' actions, for menus and tests.
  bool startMimicking();
  void stopMimicking();
  // The mapping and limits the operator is asked to confirm, as shown.
  QString shownSettings() const { return shown_; }

 signals:
  void message(const QString& text);
  void errorOccurred(const QString& text);

 private:
  void refreshSettings();
  void updateState();

  MimicController* controller_;
  std::function<AnalysisOptions()> analysis_;
  std::function<robot::PlannerOptions()> planner_;
  RobotLink* link_ = nullptr;
  robot::ControllerProfile profile_;
  std::function<robot::ControllerProfile()> profile_source_;
  QString shown_;
  QTimer refresh_;
  VideoView* view_;
  RobotPreview* preview_;
  QPlainTextEdit* settings_;
  QCheckBox* confirm_;
  QCheckBox* deadman_;
  QPushButton* start_;
  QPushButton* stop_;
  QPushButton* hold_;
  QLabel* state_;
  QLabel* latency_;
  QShortcut* stop_shortcut_;
};

}  // namespace armmimic::gui
