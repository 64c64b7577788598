// AppActions: every command of the window as a QAction with a shortcut, an icon and a menu entry
// (menus and the toolbar are built here so MainWindow only connects them).
#pragma once

#include <QList>
#include <QObject>

#include "overlay.h"

class QAction;
class QActionGroup;
class QMainWindow;
class QMenu;
class QSettings;
class QToolBar;

namespace armmimic::gui {

class AppActions : public QObject {
  Q_OBJECT
 public:
  explicit AppActions(QObject* parent);

  // Builds the menu bar and the main toolbar of `window`. `docks` go into View > Panels.
  void populate(QMainWindow* window, const QList<QAction*>& dock_toggles);
  OverlayOptions overlayOptions() const;
  void setOverlayOptions(const OverlayOptions& o);
  // The overlay toggles, remembered between sessions.
  void saveSettings(QSettings& settings) const;
  void loadSettings(QSettings& settings);
  QMenu* recentMenu() const { return recent_menu_; }

  // File.
  QAction* open;
  QAction* openFolder;
  QAction* camera;
  QAction* openAngles;
  QAction* openSession;
  QAction* saveSession;
  QAction* saveFrame;
  QAction* exportAngles;
  QAction* exportCsv;
  QAction* exportVal;
  QAction* quit;
  // Playback.
  QAction* play;
  QAction* stepBack;
  QAction* stepForward;
  QAction* first;
  QAction* last;
  QAction* faster;
  QAction* slower;
  // View.
  QAction* zoomIn;
  QAction* zoomOut;
  QAction* zoomFit;
  // Tools.
  QActionGroup* tools;
  QAction* toolPan;
  QAction* toolRoi;
  QAction* toolShoulder;
  QAction* toolJoints;  // shoulder, elbow and wrist in the start frame, in turn
  QAction* clearRoi;
  QAction* clearShoulder;
  // Analysis.
  QAction* analyze;
  // Esc, wherever the focus is: cancels the analysis and aborts a send to the robot.
  QAction* cancel;
  QAction* estimateBackground;
  // Overlay toggles.
  QAction* ovFrame;
  QAction* ovYaw;
  QAction* ovOrientation;
  QAction* ovCentres;
  QAction* ovSegments;
  QAction* ovElbow;
  QAction* ovShoulder;
  QAction* ovMarkers;
  QAction* ovFeatures;
  QAction* ovContour;
  // Help.
  QAction* about;

 signals:
  void overlayChanged();

 private:
  QAction* make(const QString& text, const QKeySequence& key, const QString& name);
  QAction* toggle(const QString& text, const QKeySequence& key, const QString& name, bool on);
  QMenu* recent_menu_ = nullptr;
};

}  // namespace armmimic::gui
