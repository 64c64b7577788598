// The window without analysis: playback keys, scrubbing, zoom, the ROI and shoulder tools,
// saving a frame with its overlay, actions and shortcuts, and remembered settings.
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTest>
#include <QTimer>

#include "app_actions.h"
#include "armmimic/core/angles.h"
#include "armmimic/synth/truth_file.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "playback_bar.h"
#include "robot_panel.h"
#include "status_line.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class WindowTest : public GuiTest {
 protected:
  int total() const {
    return scenes().background_frames + scenes().standstill_frames + scenes().motion_frames;
  }
};

TEST_F(WindowTest, KeysStepSeekAndPlay) {
  MainWindow w;
  ShowAndOpen(w);
  EXPECT_EQ(w.player()->frameCount(), total());
  EXPECT_EQ(w.view()->frameIndex(), 0);
  w.view()->setFocus();
  QTest::keyClick(&w, Qt::Key_Right);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 1; }));
  QTest::keyClick(&w, Qt::Key_End);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == total() - 1; }));
  QTest::keyClick(&w, Qt::Key_Left);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == total() - 2; }));
  QTest::keyClick(&w, Qt::Key_Home);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 0; }));
  EXPECT_EQ(w.playbackBar()->position(), 0);
  // Scrubbing the slider seeks.
  emit w.playbackBar()->seekRequested(17);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 17; }));
  EXPECT_EQ(w.playbackBar()->position(), 17);
  // Space plays; the frame advances on its own; Space again pauses.
  w.playbackBar()->setSpeed(4.0);
  QTest::keyClick(&w, Qt::Key_Space);
  EXPECT_TRUE(w.player()->isPlaying());
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() > 20; }));
  QTest::keyClick(&w, Qt::Key_Space);
  EXPECT_FALSE(w.player()->isPlaying());
}

TEST_F(WindowTest, RoiAndShoulderToolsFillTheAnalysisOptions) {
  MainWindow w;
  ShowAndOpen(w);
  gui::VideoView* v = w.view();
  w.actions()->toolRoi->trigger();
  const QPoint a = v->toWidget(QPointF(100, 50)).toPoint();
  const QPoint b = v->toWidget(QPointF(260, 200)).toPoint();
  QTest::mousePress(v, Qt::LeftButton, {}, a);
  QTest::mouseRelease(v, Qt::LeftButton, {}, b);
  const AnalysisOptions o = w.settingsPanel()->options();
  ASSERT_TRUE(o.roi.has_value());
  EXPECT_NEAR(o.roi->x, 100, 2);
  EXPECT_NEAR(o.roi->y, 50, 2);
  EXPECT_NEAR(o.roi->x + o.roi->width, 260, 3);
  EXPECT_NEAR(o.roi->y + o.roi->height, 200, 3);

  w.actions()->toolShoulder->trigger();
  QTest::mouseClick(v, Qt::LeftButton, {}, v->toWidget(QPointF(180, 90)).toPoint());
  const AnalysisOptions o2 = w.settingsPanel()->options();
  ASSERT_TRUE(o2.shoulder_px.has_value());
  EXPECT_NEAR(o2.shoulder_px->x, 180, 1.5);
  EXPECT_NEAR(o2.shoulder_px->y, 90, 1.5);

  // The marker engine ignores both: the video stops drawing them, and draws them again for
  // an arm engine.
  EXPECT_TRUE(v->roi().has_value());
  EXPECT_TRUE(v->shoulder().has_value());
  auto* engine = w.settingsPanel()->findChild<QComboBox*>("engineCombo");
  engine->setCurrentIndex(engine->findData(int(EngineKind::kMarker)));
  EXPECT_FALSE(v->roi().has_value());
  EXPECT_FALSE(v->shoulder().has_value());
  engine->setCurrentIndex(engine->findData(int(EngineKind::kLk)));
  ASSERT_TRUE(v->roi().has_value());
  EXPECT_NEAR(v->roi()->x(), 100, 2);
  EXPECT_TRUE(v->shoulder().has_value());

  w.actions()->clearRoi->trigger();
  EXPECT_FALSE(w.settingsPanel()->options().roi.has_value());
  EXPECT_FALSE(v->roi().has_value());
  // Zoom keeps the image point under the view's centre mapping consistent.
  const double before = v->zoom();
  w.actions()->zoomIn->trigger();
  EXPECT_GT(v->zoom(), before);
  w.actions()->zoomFit->trigger();
  EXPECT_DOUBLE_EQ(v->zoom(), before);
}

// The joints tool: three clicks on the start frame give the shoulder, the elbow and the wrist
// that --shoulder/--elbow/--wrist give the tracking engine.
TEST_F(WindowTest, TheJointsToolClicksShoulderElbowAndWrist) {
  MainWindow w;
  ShowAndOpen(w);
  auto* engine = w.settingsPanel()->findChild<QComboBox*>("engineCombo");
  engine->setCurrentIndex(engine->findData(int(EngineKind::kLk)));
  gui::VideoView* v = w.view();
  w.actions()->toolJoints->trigger();
  const QPointF joints[3] = {{180, 90}, {190, 130}, {200, 170}};
  for (const QPointF& j : joints) {
    QTest::mouseClick(v, Qt::LeftButton, {}, v->toWidget(j).toPoint());
  }
  AnalysisOptions o = w.settingsPanel()->options();
  o.inputs = {scenes().video()};
  ASSERT_TRUE(o.shoulder_px && o.elbow_px && o.wrist_px);
  EXPECT_NEAR(o.shoulder_px->x, 180, 1.5);
  EXPECT_NEAR(o.elbow_px->y, 130, 1.5);
  EXPECT_NEAR(o.wrist_px->x, 200, 1.5);
  EXPECT_TRUE(o.Check().ok()) << o.Check().message();
  // The pose engine needs none of them, and its entry is in the engine list.
  engine->setCurrentIndex(engine->findData(int(EngineKind::kPose)));
  ASSERT_GE(engine->currentIndex(), 0);
  EXPECT_EQ(w.settingsPanel()->options().engine.kind, EngineKind::kPose);
  EXPECT_FALSE(w.settingsPanel()->options().elbow_px.has_value());
}

#ifdef ARMMIMIC_HAVE_POSE_MODEL
// The Auto-calibrate button: the pose network's shoulder, elbow and wrist in the start frame of
// the generated person, near the truth.
TEST_F(WindowTest, AutoCalibrateFillsTheJointsFromThePoseNetwork) {
  MainWindow w;
  ShowAndOpen(w);
  auto* engine = w.settingsPanel()->findChild<QComboBox*>("engineCombo");
  engine->setCurrentIndex(engine->findData(int(EngineKind::kLk)));
  const int start = scenes().background_frames + scenes().standstill_frames;
  w.settingsPanel()->findChild<QSpinBox*>("startFrame")->setValue(start);
  auto* button = w.settingsPanel()->findChild<QPushButton*>("autoCalibrate");
  ASSERT_NE(button, nullptr);
  ASSERT_TRUE(button->isEnabled());
  button->click();
  const AnalysisOptions o = w.settingsPanel()->options();
  ASSERT_TRUE(o.shoulder_px && o.elbow_px && o.wrist_px);
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(scenes().arm_dir + "/truth.tsv", &truth).ok());
  const synth::TruthRow* t = truth.Find(start);
  ASSERT_NE(t, nullptr);
  EXPECT_NEAR(DirectionDeg(*o.shoulder_px, *o.elbow_px), t->upper_deg, 15);
  EXPECT_NEAR(DirectionDeg(*o.elbow_px, *o.wrist_px), t->fore_deg, 15);
}
#endif

TEST_F(WindowTest, SaveFrameWritesTheOverlayAtVideoResolution) {
  MainWindow w;
  ShowAndOpen(w);
  const QString path = QString::fromStdString(tmp_.file("frame.png"));
  ASSERT_TRUE(w.saveFrame(path)) << w.log()->text().toStdString();
  const QImage saved(path);
  ASSERT_EQ(saved.size(), w.view()->image().size());
  // The frame count is painted in the upper left: the saved image differs from the frame there.
  const QImage raw = w.view()->image().convertToFormat(QImage::Format_RGB32);
  const QImage got = saved.convertToFormat(QImage::Format_RGB32);
  int changed = 0;
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 80; ++x) changed += raw.pixel(x, y) != got.pixel(x, y) ? 1 : 0;
  }
  EXPECT_GT(changed, 20);
  // Turning the frame count off removes it.
  w.actions()->ovFrame->setChecked(false);
  ASSERT_TRUE(w.saveFrame(path));
  EXPECT_EQ(QImage(path).convertToFormat(QImage::Format_RGB32), raw);
}

TEST_F(WindowTest, EveryActionHasAMenuEntryAndShortcutsAreUnique) {
  MainWindow w;
  QSet<QString> keys;
  int with_key = 0;
  for (QAction* a : w.findChildren<QAction*>()) {
    if (a->objectName().startsWith("action") || a->objectName().startsWith("ov")) {
      EXPECT_FALSE(a->associatedObjects().isEmpty()) << a->objectName().toStdString();
      if (!a->shortcut().isEmpty()) {
        const QString k = a->shortcut().toString();
        EXPECT_FALSE(keys.contains(k)) << "shortcut " << k.toStdString() << " used twice";
        keys.insert(k);
        ++with_key;
      }
    }
  }
  EXPECT_GE(with_key, 25);
}

TEST_F(WindowTest, SettingsAndRecentFilesAreRemembered) {
  {
    MainWindow w;
    ShowAndOpen(w);
    AnalysisOptions o = w.settingsPanel()->options();
    o.engine.kind = EngineKind::kLk;
    o.engine.bgsub.threshold = 61;
    o.engine.lk.initial_upper_deg = -80;
    w.settingsPanel()->setOptions(o);
    w.close();
  }
  MainWindow w2;
  const AnalysisOptions o = w2.settingsPanel()->options();
  EXPECT_EQ(o.engine.kind, EngineKind::kLk);
  EXPECT_EQ(o.engine.bgsub.threshold, 61);
  EXPECT_DOUBLE_EQ(o.engine.lk.initial_upper_deg, -80);
  const QStringList recent = QSettings().value("recentFiles").toStringList();
  ASSERT_FALSE(recent.isEmpty());
  EXPECT_EQ(recent.first().toStdString(), scenes().video());
}

TEST_F(WindowTest, ScrollingThePanelsNeverChangesASetting) {
  MainWindow w;
  w.resize(1000, 600);  // the Analysis panel is taller than its dock: it scrolls
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  auto* scroll = w.findChild<QScrollArea*>("analysisScroll");
  ASSERT_NE(scroll, nullptr);
  ASSERT_GT(scroll->verticalScrollBar()->maximum(), 0);
  auto* engine = w.settingsPanel()->findChild<QComboBox*>("engineCombo");
  auto* start = w.settingsPanel()->findChild<QSpinBox*>("startFrame");
  ASSERT_TRUE(engine && start);
  start->setValue(45);
  const int engine_before = engine->currentIndex();
  // The wheel over an editor without the focus scrolls the panel and leaves the value alone.
  Wheel(start, -120);
  EXPECT_EQ(start->value(), 45);
  EXPECT_GT(scroll->verticalScrollBar()->value(), 0);
  scroll->verticalScrollBar()->setValue(0);
  Wheel(engine, -120);
  EXPECT_EQ(engine->currentIndex(), engine_before);
  // The focused editor takes the wheel, as the operator asked for it.
  start->setFocus();
  ASSERT_TRUE(WaitUntil([&] { return start->hasFocus(); }, 2000));
  Wheel(start, 120);
  EXPECT_EQ(start->value(), 46);

  // The robot's plan settings: scrolling past the filter cutoff or a mapping sign never
  // changes the plan.
  w.findChild<QDockWidget*>("robotDock")->raise();
  gui::RobotPanel* robot = w.robotPanel();
  auto* cutoff = robot->findChild<QDoubleSpinBox*>("cutoff");
  auto* sign = robot->findChild<QComboBox*>("sign2");
  auto* baud = robot->findChild<QComboBox*>("baudCombo");
  ASSERT_TRUE(cutoff && sign && baud);
  const robot::PlannerOptions before = robot->plannerOptions();
  for (QWidget* editor :
       {static_cast<QWidget*>(cutoff), static_cast<QWidget*>(sign), static_cast<QWidget*>(baud)}) {
    Wheel(editor, -120);
    Wheel(editor, 120);
    Wheel(editor, 120);
  }
  const robot::PlannerOptions after = robot->plannerOptions();
  EXPECT_EQ(after.cutoff_hz, before.cutoff_hz);
  EXPECT_EQ(after.mapping.j2.sign, before.mapping.j2.sign);
  EXPECT_EQ(baud->currentText(), "9600");
}

TEST_F(WindowTest, ARepeatedErrorShowsAgainAndCountsUp) {
  MainWindow w;
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  // F5 with nothing open, twice: one line that counts, and the status bar says it again.
  EXPECT_FALSE(w.startAnalysis());
  const QString first = w.statusBar()->currentMessage();
  EXPECT_NE(first.indexOf("Open a video"), -1) << first.toStdString();
  w.statusBar()->clearMessage();
  EXPECT_FALSE(w.startAnalysis());
  EXPECT_EQ(w.log()->text().count("error: "), 1) << w.log()->text().toStdString();
  EXPECT_NE(w.log()->text().indexOf("(×2)"), -1) << w.log()->text().toStdString();
  EXPECT_NE(w.statusBar()->currentMessage().indexOf("(×2)"), -1)
      << w.statusBar()->currentMessage().toStdString();
  EXPECT_EQ(w.log()->errorCount(), 1);
  EXPECT_EQ(w.log()->repeats(first), 2);
  // Opening an input clears the status bar's error: it is not about the new input.
  w.openInputs({QString::fromStdString(scenes().video())});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
  EXPECT_TRUE(w.statusBar()->currentMessage().isEmpty())
      << w.statusBar()->currentMessage().toStdString();
  EXPECT_NE(w.statusLine()->frameText().indexOf("frame 0"), -1);
  // After other messages the same error is a new line with its count.
  w.player()->close();
  EXPECT_FALSE(w.startAnalysis());
  EXPECT_EQ(w.log()->text().count("error: "), 2) << w.log()->text().toStdString();
  EXPECT_TRUE(w.log()->text().endsWith(first + "  (×3)")) << w.log()->text().toStdString();
}

TEST_F(WindowTest, ZoomedInTheOverlayTextsStayInViewAtTheirSize) {
  gui::VideoView view;
  view.resize(640, 480);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  QImage grey(320, 240, QImage::Format_RGB888);
  grey.fill(QColor(128, 128, 128));
  view.setFrame(grey, 12, 100);  // no measurement: the frame count is the only text
  // White letters (the frame count) in the view's upper left quarter.
  auto white_upper_left = [&] {
    const QImage shot = view.grab().toImage();
    int n = 0;
    for (int y = 0; y < shot.height() / 4; ++y) {
      for (int x = 0; x < shot.width() / 2; ++x) {
        const QColor c(shot.pixel(x, y));
        n += c.red() > 230 && c.green() > 230 && c.blue() > 230 ? 1 : 0;
      }
    }
    return n;
  };
  const int at_fit = white_upper_left();
  ASSERT_GT(at_fit, 30);
  for (int i = 0; i < 8; ++i) view.zoomIn();  // about 6x: the frame's corner is far off screen
  EXPECT_GT(view.zoom(), 5.0);
  EXPECT_TRUE(QRectF(view.rect()).contains(view.textArea()));
  const int zoomed = white_upper_left();
  EXPECT_GT(zoomed, at_fit / 2);
  EXPECT_LT(zoomed, at_fit * 2);  // not blown up with the zoom
}

TEST_F(WindowTest, FileOpenFolderOpensTheImagesInIt) {
  MainWindow w;
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  const QString folder = QString::fromStdString(scenes().marker_dir + "/views");
  bool answered = false;
  QTimer poll;
  QObject::connect(&poll, &QTimer::timeout, [&] {
    auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
    if (!dialog) return;
    poll.stop();
    EXPECT_EQ(dialog->fileMode(), QFileDialog::Directory);
    dialog->setDirectory(folder);
    QMetaObject::invokeMethod(dialog, "accept");  // the Choose button
    answered = true;
  });
  poll.start(10);
  w.actions()->openFolder->trigger();  // File > Open folder of images…
  ASSERT_TRUE(answered);
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && !w.view()->image().isNull(); }))
      << w.log()->text().toStdString();
  EXPECT_EQ(QFileInfo(w.player()->inputs().value(0)).canonicalFilePath(),
            QFileInfo(folder).canonicalFilePath());
  EXPECT_EQ(w.player()->frameCount(), 6);  // every view in the folder
  EXPECT_EQ(w.log()->errorCount(), 0) << w.log()->text().toStdString();
  // Still images have no frame rate: counted as images, with no time beside the frame.
  EXPECT_NE(w.log()->text().indexOf("6 images, "), -1) << w.log()->text().toStdString();
  EXPECT_EQ(w.log()->text().indexOf("0 fps"), -1) << w.log()->text().toStdString();
  const QString bar = w.playbackBar()->findChild<QLabel*>("frameLabel")->text();
  EXPECT_EQ(bar, "0 / 5") << bar.toStdString();
  EXPECT_EQ(w.statusLine()->frameText().indexOf(" s "), -1)
      << w.statusLine()->frameText().toStdString();
}

}  // namespace
}  // namespace armmimic::test
