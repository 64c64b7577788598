// The application's actions (menus, toolbar, shortcuts) and the overlay toggles, with their
// saved settings.
// Length: the constructor is the list of every action with its text, key and name, read as one
// table.
#include "app_actions.h"

#include <QAction>
#include <QActionGroup>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QToolBar>

#include "icons.h"

namespace armmimic::gui {

QAction* AppActions::make(const QString& text, const QKeySequence& key, const QString& name) {
  auto* a = new QAction(text, this);
  a->setObjectName(name);
  if (!key.isEmpty()) {
    a->setShortcut(key);
    a->setToolTip(QString("%1 (%2)").arg(QString(text).remove('&').remove("…"),
                                         key.toString(QKeySequence::NativeText)));
  }
  return a;
}

QAction* AppActions::toggle(const QString& text, const QKeySequence& key, const QString& name,
                            bool on) {
  QAction* a = make(text, key, name);
  a->setCheckable(true);
  a->setChecked(on);
  connect(a, &QAction::toggled, this, &AppActions::overlayChanged);
  return a;
}

AppActions::AppActions(QObject* parent) : QObject(parent) {
  open = make(tr("&Open video or images…"), QKeySequence::Open, "actionOpen");
  open->setIcon(MakeIcon(IconKind::kOpen));
  openFolder = make(tr("Open &folder of images…"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_O),
                    "actionOpenFolder");
  camera = make(tr("Capture from &camera…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O),
                "actionCamera");
  camera->setIcon(MakeIcon(IconKind::kCamera));
  openAngles = make(tr("Open &angle file…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A),
                    "actionOpenAngles");
  openSession = make(tr("Open se&ssion…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L),
                     "actionOpenSession");
  saveSession = make(tr("Save session…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
                     "actionSaveSession");
  saveFrame =
      make(tr("&Save frame with overlay…"), QKeySequence(Qt::CTRL | Qt::Key_S), "actionSaveFrame");
  saveFrame->setIcon(MakeIcon(IconKind::kSaveImage));
  exportAngles =
      make(tr("&Export angle file…"), QKeySequence(Qt::CTRL | Qt::Key_E), "actionExportAngles");
  exportAngles->setIcon(MakeIcon(IconKind::kExport));
  exportCsv =
      make(tr("Export &CSV…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C), "actionExportCsv");
  exportVal = make(tr("Export &VAL program…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E),
                   "actionExportVal");
  quit = make(tr("&Quit"), QKeySequence::Quit, "actionQuit");
  quit->setMenuRole(QAction::QuitRole);

  play = make(tr("&Play / pause"), QKeySequence(Qt::Key_Space), "actionPlay");
  play->setIcon(MakeIcon(IconKind::kPlay));
  stepBack = make(tr("Step &back"), QKeySequence(Qt::Key_Left), "actionStepBack");
  stepBack->setIcon(MakeIcon(IconKind::kStepBack));
  stepForward = make(tr("Step &forward"), QKeySequence(Qt::Key_Right), "actionStepForward");
  stepForward->setIcon(MakeIcon(IconKind::kStepForward));
  first = make(tr("&First frame"), QKeySequence(Qt::Key_Home), "actionFirst");
  first->setIcon(MakeIcon(IconKind::kFirst));
  last = make(tr("&Last frame"), QKeySequence(Qt::Key_End), "actionLast");
  last->setIcon(MakeIcon(IconKind::kLast));
  faster = make(tr("Fas&ter"), QKeySequence(Qt::Key_BracketRight), "actionFaster");
  slower = make(tr("Slo&wer"), QKeySequence(Qt::Key_BracketLeft), "actionSlower");

  zoomIn = make(tr("Zoom &in"), QKeySequence::ZoomIn, "actionZoomIn");
  zoomIn->setIcon(MakeIcon(IconKind::kZoomIn));
  zoomOut = make(tr("Zoom &out"), QKeySequence::ZoomOut, "actionZoomOut");
  zoomOut->setIcon(MakeIcon(IconKind::kZoomOut));
  zoomFit = make(tr("&Fit to window"), QKeySequence(Qt::CTRL | Qt::Key_0), "actionZoomFit");
  zoomFit->setIcon(MakeIcon(IconKind::kZoomFit));

  tools = new QActionGroup(this);
  toolPan = make(tr("&Pan"), QKeySequence(Qt::Key_H), "actionToolPan");
  toolPan->setIcon(MakeIcon(IconKind::kPan));
  toolRoi = make(tr("Draw &region of interest"), QKeySequence(Qt::Key_R), "actionToolRoi");
  toolRoi->setIcon(MakeIcon(IconKind::kRoi));
  toolShoulder = make(tr("Click the &shoulder"), QKeySequence(Qt::Key_S), "actionToolShoulder");
  toolShoulder->setIcon(MakeIcon(IconKind::kShoulder));
  toolJoints = make(tr("Click shoulder, elbow and wrist (start frame)"), QKeySequence(Qt::Key_J),
                    "actionToolJoints");
  toolJoints->setIcon(MakeIcon(IconKind::kShoulder));
  for (QAction* a : {toolPan, toolRoi, toolShoulder, toolJoints}) {
    a->setCheckable(true);
    tools->addAction(a);
  }
  toolPan->setChecked(true);
  clearRoi =
      make(tr("Clear region of interest"), QKeySequence(Qt::SHIFT | Qt::Key_R), "actionClearRoi");
  clearShoulder =
      make(tr("Clear shoulder"), QKeySequence(Qt::SHIFT | Qt::Key_S), "actionClearShoulder");

  analyze = make(tr("&Run analysis"), QKeySequence(Qt::Key_F5), "actionAnalyze");
  analyze->setIcon(MakeIcon(IconKind::kAnalyze));
  cancel = make(tr("&Stop analysis and sending"), QKeySequence(Qt::Key_Escape), "actionCancel");
  cancel->setIcon(MakeIcon(IconKind::kStop));
  cancel->setEnabled(false);
  // A floating Robot panel is a window of its own: Esc stops from there too.
  cancel->setShortcutContext(Qt::ApplicationShortcut);
  estimateBackground = make(tr("Estimate &background…"), QKeySequence(Qt::CTRL | Qt::Key_B),
                            "actionEstimateBackground");
  estimateBackground->setIcon(MakeIcon(IconKind::kBackground));

  const OverlayOptions d;
  ovFrame = toggle(tr("Frame count"), QKeySequence(Qt::ALT | Qt::Key_1), "ovFrame", d.frame_count);
  ovYaw = toggle(tr("Yaw"), QKeySequence(Qt::ALT | Qt::Key_2), "ovYaw", d.yaw);
  ovOrientation = toggle(tr("Upper-arm and forearm orientation"), QKeySequence(Qt::ALT | Qt::Key_3),
                         "ovOrientation", d.orientation);
  ovCentres =
      toggle(tr("Centres of mass"), QKeySequence(Qt::ALT | Qt::Key_4), "ovCentres", d.centres);
  ovSegments = toggle(tr("Segments"), QKeySequence(Qt::ALT | Qt::Key_5), "ovSegments", d.segments);
  ovElbow = toggle(tr("Elbow"), QKeySequence(Qt::ALT | Qt::Key_6), "ovElbow", d.elbow);
  ovShoulder = toggle(tr("Shoulder"), QKeySequence(Qt::ALT | Qt::Key_7), "ovShoulder", d.shoulder);
  ovMarkers = toggle(tr("Markers and candidate boxes"), QKeySequence(Qt::ALT | Qt::Key_8),
                     "ovMarkers", d.markers);
  ovFeatures =
      toggle(tr("Tracked features"), QKeySequence(Qt::ALT | Qt::Key_9), "ovFeatures", d.features);
  ovContour = toggle(tr("Arm contour, hull and body box"), QKeySequence(Qt::ALT | Qt::Key_0),
                     "ovContour", d.contour);
  about = make(tr("&About armmimic"), QKeySequence(), "actionAbout");
  about->setMenuRole(QAction::AboutRole);
}

void AppActions::populate(QMainWindow* w, const QList<QAction*>& dock_toggles) {
  QMenuBar* bar = w->menuBar();
  QMenu* file = bar->addMenu(tr("&File"));
  file->addActions({open, openFolder, camera, openAngles, openSession});
  recent_menu_ = file->addMenu(tr("Open &recent"));
  recent_menu_->setObjectName("recentMenu");
  file->addSeparator();
  file->addActions({saveSession, saveFrame, exportAngles, exportCsv, exportVal});
  file->addSeparator();
  file->addAction(quit);

  QMenu* playback = bar->addMenu(tr("&Playback"));
  playback->addActions({play, stepBack, stepForward, first, last});
  playback->addSeparator();
  playback->addActions({faster, slower});

  QMenu* analysis = bar->addMenu(tr("&Analysis"));
  analysis->addActions({analyze, cancel, estimateBackground});
  analysis->addSeparator();
  analysis->addActions({toolPan, toolRoi, toolShoulder, toolJoints, clearRoi, clearShoulder});

  QMenu* view = bar->addMenu(tr("&View"));
  view->addActions({zoomIn, zoomOut, zoomFit});
  view->addSeparator();
  QMenu* overlay = view->addMenu(tr("&Overlay"));
  overlay->addActions({ovFrame, ovYaw, ovOrientation, ovCentres, ovSegments, ovElbow, ovShoulder,
                       ovMarkers, ovFeatures, ovContour});
  QMenu* panels = view->addMenu(tr("&Panels"));
  panels->addActions(dock_toggles);

  QMenu* help = bar->addMenu(tr("&Help"));
  help->addAction(about);

  QToolBar* tb = w->addToolBar(tr("Main"));
  tb->setObjectName("mainToolBar");
  tb->addActions({open, camera, saveFrame, exportAngles});
  tb->addSeparator();
  tb->addActions({estimateBackground, analyze, cancel});
  tb->addSeparator();
  tb->addActions({toolPan, toolRoi, toolShoulder});
  tb->addSeparator();
  tb->addActions({zoomIn, zoomOut, zoomFit});
}

OverlayOptions AppActions::overlayOptions() const {
  OverlayOptions o;
  o.frame_count = ovFrame->isChecked();
  o.yaw = ovYaw->isChecked();
  o.orientation = ovOrientation->isChecked();
  o.centres = ovCentres->isChecked();
  o.segments = ovSegments->isChecked();
  o.elbow = ovElbow->isChecked();
  o.shoulder = ovShoulder->isChecked();
  o.markers = ovMarkers->isChecked();
  o.features = ovFeatures->isChecked();
  o.contour = ovContour->isChecked();
  return o;
}

void AppActions::saveSettings(QSettings& s) const {
  for (QAction* a : {ovFrame, ovYaw, ovOrientation, ovCentres, ovSegments, ovElbow, ovShoulder,
                     ovMarkers, ovFeatures, ovContour}) {
    s.setValue("overlay/" + a->objectName(), a->isChecked());
  }
}

void AppActions::loadSettings(QSettings& s) {
  for (QAction* a : {ovFrame, ovYaw, ovOrientation, ovCentres, ovSegments, ovElbow, ovShoulder,
                     ovMarkers, ovFeatures, ovContour}) {
    const QSignalBlocker block(a);
    a->setChecked(s.value("overlay/" + a->objectName(), a->isChecked()).toBool());
  }
  emit overlayChanged();
}

void AppActions::setOverlayOptions(const OverlayOptions& o) {
  const std::pair<QAction*, bool> all[] = {{ovFrame, o.frame_count},       {ovYaw, o.yaw},
                                           {ovOrientation, o.orientation}, {ovCentres, o.centres},
                                           {ovSegments, o.segments},       {ovElbow, o.elbow},
                                           {ovShoulder, o.shoulder},       {ovMarkers, o.markers},
                                           {ovFeatures, o.features},       {ovContour, o.contour}};
  for (const auto& [a, on] : all) {
    const QSignalBlocker block(a);
    a->setChecked(on);
  }
  emit overlayChanged();
}

}  // namespace armmimic::gui
