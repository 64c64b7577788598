// The hybrid engine in the window: its entry and inputs, its page with lk's and bgsub's
// parameters, its options through sessions, saved settings and Mimic live, and the standstill's
// estimated joints shown as handles on the last standstill frame, accepted or dragged into the
// clicked joints.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTest>

#include "analysis_job.h"
#include "armmimic/engines/option_fields.h"
#include "armmimic/synth/random_arm_scene.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::EngineSettingsPanel;
using gui::MainWindow;

// A thesis-protocol scene the standstill calibration takes (`synth arm --random --seed 1000`, a
// tuning seed), written once: scene.avi, background.png, armlength.png.
struct CalibrationScene {
  synth::RandomArmSceneOptions options;
  std::string dir;
  std::string file(const char* name) const { return dir + "/" + name; }
};

const CalibrationScene& Scene() {
  static CalibrationScene scene = [] {
    CalibrationScene s;
    s.options.seed = 1000;
    bool created = false;
    s.dir = SharedTempDir("gui-hybrid-scene", &created).file("seed1000");
    if (created) {
      const Status st = synth::WriteRandomArmScene(s.options, s.dir, {});
      EXPECT_TRUE(st.ok()) << st.message();
    }
    return s;
  }();
  return scene;
}

class HybridTest : public GuiTest {
 protected:
  static QComboBox* Engine(EngineSettingsPanel* panel) {
    return panel->findChild<QComboBox*>("engineCombo");
  }
  static void Choose(EngineSettingsPanel* panel, EngineKind kind) {
    Engine(panel)->setCurrentIndex(Engine(panel)->findData(int(kind)));
  }
  // The scene opened with the hybrid engine in the thesis protocol set in the fields.
  static void OpenProtocol(MainWindow& w) {
    const synth::RandomArmScene truth(Scene().options);
    w.resize(1200, 800);
    w.show();
    w.openInputs({QString::fromStdString(Scene().file("scene.avi"))});
    ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && !w.view()->image().isNull(); }));
    AnalysisOptions o = w.settingsPanel()->options();
    o.engine.kind = EngineKind::kHybrid;
    o.background_path = Scene().file("background.png");
    o.arm_length_path = Scene().file("armlength.png");
    o.start = truth.background_frames();
    o.engine.lk.standstill_frames = truth.standstill_frames();
    w.settingsPanel()->setOptions(o);
  }
};

TEST_F(HybridTest, ItsEntryEnablesTheTrackingInputsAndShowsLkAndBgsubParameters) {
  EngineSettingsPanel panel;
  panel.show();
  QComboBox* engine = Engine(&panel);
  const int entry = engine->findData(int(EngineKind::kHybrid));
  ASSERT_GE(entry, 0);
  EXPECT_TRUE(engine->itemText(entry).startsWith("Hybrid"));
  auto enabled = [&](const char* name) {
    QWidget* w = panel.findChild<QWidget*>(name);
    EXPECT_NE(w, nullptr) << name;
    return w && w->isEnabledTo(&panel);
  };
  Choose(&panel, EngineKind::kBgsub);
  EXPECT_FALSE(enabled("elbowWristBox"));
  EXPECT_FALSE(enabled("autoCalibrate"));
  engine->setCurrentIndex(entry);
  EXPECT_EQ(panel.options().engine.kind, EngineKind::kHybrid);
  for (const char* name : {"backgroundMode", "armLengthPath", "startFrame", "shoulderBox",
                           "elbowWristBox", "autoCalibrate", "roiBox"}) {
    EXPECT_TRUE(enabled(name)) << name;
  }
  EXPECT_FALSE(enabled("referencePath"));
  // Calibrating from the standstill needs the background and the arm-length image.
  EXPECT_FALSE(enabled("standstillCalibrate"));
  EXPECT_FALSE(enabled("acceptEstimate"));
  panel.findChild<QComboBox*>("backgroundMode")->setCurrentIndex(1);  // the first K frames
  EXPECT_FALSE(enabled("standstillCalibrate"));
  QTest::keyClicks(panel.findChild<QLineEdit*>("armLengthPath"), "arm.png");
  EXPECT_TRUE(enabled("standstillCalibrate"));
  EXPECT_EQ(panel.options().arm_length_path, "arm.png");

  // Its own parameters, and lk's and bgsub's on its page, edited there.
  QWidget* own = panel.parameterEditor(EngineKind::kHybrid, "max_disagreement_deg");
  QWidget* lk = panel.parameterEditor(EngineKind::kLk, "standstill_frames");
  QWidget* bgsub = panel.parameterEditor(EngineKind::kBgsub, "threshold");
  ASSERT_TRUE(own && lk && bgsub);
  for (QWidget* w : {own, lk, bgsub}) EXPECT_TRUE(w->isVisibleTo(&panel));
  qobject_cast<QDoubleSpinBox*>(own)->setValue(9);
  qobject_cast<QSpinBox*>(lk)->setValue(50);
  qobject_cast<QSpinBox*>(bgsub)->setValue(40);
  const AnalysisOptions o = panel.options();
  EXPECT_EQ(o.engine.hybrid.max_disagreement_deg, 9);
  EXPECT_EQ(o.engine.lk.standstill_frames, 50);
  EXPECT_EQ(o.engine.bgsub.threshold, 40);
  // The lk engine's page has its form back, and the hybrid's own is hidden with its page.
  Choose(&panel, EngineKind::kLk);
  EXPECT_TRUE(lk->isVisibleTo(&panel));
  EXPECT_FALSE(own->isVisibleTo(&panel));
  EXPECT_FALSE(bgsub->isVisibleTo(&panel));
}

TEST_F(HybridTest, ItsOptionsSurviveASessionAndTheSavedSettings) {
  const QString session = QString::fromStdString(tmp_.file("hybrid.armmimic"));
  AnalysisOptions saved;
  {
    MainWindow w;
    ShowAndOpen(w);
    AnalysisOptions o = scenes().BgsubProtocol();
    o.engine.kind = EngineKind::kHybrid;
    for (const char* set : {"hybrid.max_disagreement_deg=9.5", "hybrid.joint_px=3",
                            "lk.max_corners=77", "bgsub.threshold=40"}) {
      ASSERT_TRUE(SetEngineOption(set, &o.engine).ok()) << set;
    }
    w.settingsPanel()->setOptions(o);
    ASSERT_TRUE(w.saveSession(session)) << w.log()->text().toStdString();
    saved = w.settingsPanel()->options();
    QSettings s(QString::fromStdString(tmp_.file("panel.ini")), QSettings::IniFormat);
    w.settingsPanel()->save(s);
  }
  EXPECT_EQ(saved.engine.kind, EngineKind::kHybrid);
  MainWindow w;
  w.show();
  ASSERT_TRUE(w.openSession(session)) << w.log()->text().toStdString();
  const AnalysisOptions o = w.settingsPanel()->options();
  EXPECT_EQ(o.engine.kind, EngineKind::kHybrid);
  EXPECT_EQ(o.engine.hybrid.max_disagreement_deg, 9.5);
  EXPECT_EQ(o.engine.hybrid.joint_px, 3);
  EXPECT_EQ(o.engine.lk.max_corners, 77);
  EXPECT_EQ(o.engine.bgsub.threshold, 40);
  EXPECT_EQ(o.arm_length_path, scenes().arm_length());

  EngineSettingsPanel restored;
  QSettings s(QString::fromStdString(tmp_.file("panel.ini")), QSettings::IniFormat);
  restored.load(s);
  EXPECT_EQ(restored.options().engine.kind, EngineKind::kHybrid);
  EXPECT_EQ(restored.options().engine.hybrid.max_disagreement_deg, 9.5);
}

// An angle file the CLI made with the hybrid engine opens with its engine, its own parameters
// and those of the two engines it ran.
TEST_F(HybridTest, AHybridAngleFileRestoresItsThreeSetsOfParameters) {
  const synth::RandomArmScene truth(Scene().options);
  const std::string out = tmp_.file("hybrid.tsv");
  const CliResult r = RunCli({"-q",
                              "analyze",
                              Scene().file("scene.avi"),
                              "-o",
                              out,
                              "--engine",
                              "hybrid",
                              "--background",
                              Scene().file("background.png"),
                              "--arm-length",
                              Scene().file("armlength.png"),
                              "--start",
                              std::to_string(truth.background_frames()),
                              "--standstill-frames",
                              std::to_string(truth.standstill_frames()),
                              "--param",
                              "hybrid.max_disagreement_deg=9.5",
                              "--param",
                              "lk.max_corners=77",
                              "--param",
                              "bgsub.closing_size=7"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  MainWindow w;
  w.show();
  ASSERT_TRUE(w.openAngleFile(QString::fromStdString(out))) << w.log()->text().toStdString();
  const AnalysisOptions o = w.settingsPanel()->options();
  EXPECT_EQ(o.engine.kind, EngineKind::kHybrid);
  EXPECT_EQ(Engine(w.settingsPanel())->currentData().toInt(), int(EngineKind::kHybrid));
  EXPECT_EQ(o.engine.hybrid.max_disagreement_deg, 9.5);
  EXPECT_EQ(o.engine.lk.max_corners, 77);
  EXPECT_EQ(o.engine.lk.standstill_frames, truth.standstill_frames());
  EXPECT_EQ(o.engine.bgsub.closing_size, 7);
  EXPECT_EQ(o.start, truth.background_frames());
  EXPECT_GT(w.results().rows(), 0);
}

TEST_F(HybridTest, MimicLiveRunsTheHybridEngine) {
  MainWindow w;
  ShowAndOpen(w);
  AnalysisOptions o = scenes().BgsubProtocol();
  o.engine.kind = EngineKind::kHybrid;
  o.engine.lk.standstill_frames = scenes().standstill_frames;
  w.settingsPanel()->setOptions(o);
  AngleFile f;
  ASSERT_NO_FATAL_FAILURE(RunMimicToEnd(w, &f));
  EXPECT_EQ(f.Meta("engine"), "hybrid");
  EXPECT_EQ(f.Meta("second_opinion"), "bgsub");
}

// Calibrate from standstill: the video goes to the last standstill frame, whose estimated joints
// lie near the scene's truth as handles; accepting leaves the run to calibrate itself, and a
// dragged handle turns the three joints into the clicked ones.
TEST_F(HybridTest, CalibrateShowsTheEstimatedJointsToAcceptOrDrag) {
  MainWindow w;
  OpenProtocol(w);
  const synth::RandomArmScene truth_scene(Scene().options);
  const int last = truth_scene.first_motion_frame() - 1;
  auto* calibrate = w.settingsPanel()->findChild<QPushButton*>("standstillCalibrate");
  auto* accept = w.settingsPanel()->findChild<QPushButton*>("acceptEstimate");
  ASSERT_TRUE(calibrate && accept);
  ASSERT_TRUE(calibrate->isEnabled());
  EXPECT_FALSE(accept->isEnabled());
  QTest::mouseClick(calibrate, Qt::LeftButton);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == last; }))
      << w.log()->text().toStdString();
  const gui::VideoView* view = w.view();
  ASSERT_TRUE(view->jointHandles().shownOn(last)) << w.log()->text().toStdString();
  EXPECT_TRUE(accept->isEnabled());
  const synth::ArmTruth truth = truth_scene.Truth(last);
  const auto& shown = view->jointHandles().joints();
  auto off = [](const QPointF& a, const cv::Point2d& b) {
    return std::hypot(a.x() - b.x, a.y() - b.y);
  };
  // The bounds of the library's test on this scene (standstill_estimate_test).
  EXPECT_LT(off(shown[0], truth.shoulder_px), 10.0);
  EXPECT_LT(off(shown[1], truth.elbow_px), 20.0);
  EXPECT_LT(off(shown[2], truth.wrist_px), 20.0);
  EXPECT_FALSE(w.settingsPanel()->options().shoulder_px.has_value());

  // Accepted: nothing to click, the run calibrates itself.
  QTest::mouseClick(accept, Qt::LeftButton);
  EXPECT_TRUE(view->jointHandles().empty());
  AnalysisOptions o = w.settingsPanel()->options();
  EXPECT_FALSE(o.shoulder_px || o.elbow_px || o.wrist_px);

  // Again, and the elbow's handle dragged 12 image pixels right: the three joints become the
  // clicked ones, the elbow where it was dropped.
  QTest::mouseClick(calibrate, Qt::LeftButton);
  ASSERT_TRUE(WaitUntil([&] { return view->jointHandles().shownOn(view->frameIndex()); }));
  const auto before = view->jointHandles().joints();
  const QPointF to = before[1] + QPointF(12, 0);
  gui::VideoView* v = w.view();
  QTest::mousePress(v, Qt::LeftButton, {}, v->toWidget(before[1]).toPoint());
  QTest::mouseMove(v, v->toWidget(before[1] + QPointF(6, 0)).toPoint());
  QTest::mouseRelease(v, Qt::LeftButton, {}, v->toWidget(to).toPoint());
  o = w.settingsPanel()->options();
  ASSERT_TRUE(o.shoulder_px && o.elbow_px && o.wrist_px);
  const double px = 1.0 / v->zoom() + 0.5;  // one screen pixel, rounded
  EXPECT_NEAR(o.elbow_px->x, to.x(), px);
  EXPECT_NEAR(o.elbow_px->y, to.y(), px);
  // The others where they were estimated, to the fields' 0.1 pixel.
  EXPECT_NEAR(o.shoulder_px->x, before[0].x(), 0.051);
  EXPECT_NEAR(o.shoulder_px->y, before[0].y(), 0.051);
  EXPECT_NEAR(o.wrist_px->x, before[2].x(), 0.051);
  EXPECT_NEAR(o.wrist_px->y, before[2].y(), 0.051);
  EXPECT_EQ(o.engine.kind, EngineKind::kHybrid);
  EXPECT_TRUE(w.settingsPanel()->findChild<QGroupBox*>("elbowWristBox")->isChecked());
  QTest::mouseClick(accept, Qt::LeftButton);
  EXPECT_TRUE(w.settingsPanel()->options().elbow_px.has_value());  // accepted as dragged
}

// Handles estimated for one start frame are not shown for another: changing the start frame takes
// them away (the run would calibrate from other frames), while a drag, which changes only the
// joints, keeps them.
TEST_F(HybridTest, AnotherStartFrameTakesTheEstimatedJointsAway) {
  MainWindow w;
  OpenProtocol(w);
  auto* calibrate = w.settingsPanel()->findChild<QPushButton*>("standstillCalibrate");
  auto* start = w.settingsPanel()->findChild<QSpinBox*>("startFrame");
  ASSERT_TRUE(calibrate && start);
  QTest::mouseClick(calibrate, Qt::LeftButton);
  const gui::VideoView* view = w.view();
  ASSERT_TRUE(WaitUntil([&] { return view->jointHandles().shownOn(view->frameIndex()); }))
      << w.log()->text().toStdString();
  start->setValue(start->value() + 5);
  EXPECT_TRUE(view->jointHandles().empty());
  EXPECT_TRUE(w.log()->text().contains("calibrate from the standstill again"));
  EXPECT_FALSE(w.settingsPanel()->findChild<QPushButton*>("acceptEstimate")->isEnabled());
}

// A calibration the inputs cannot give is reported at its field, and shows no handles.
TEST_F(HybridTest, ACalibrationThatCannotBeMadeIsNamedAtItsField) {
  MainWindow w;
  OpenProtocol(w);
  AnalysisOptions o = w.settingsPanel()->options();
  o.arm_length_path = tmp_.file("missing.png");
  w.settingsPanel()->setOptions(o);
  auto* calibrate = w.settingsPanel()->findChild<QPushButton*>("standstillCalibrate");
  ASSERT_TRUE(calibrate->isEnabled());
  QTest::mouseClick(calibrate, Qt::LeftButton);
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }));
  const QString log = w.log()->text();
  EXPECT_TRUE(log.contains("Arm-length image: ")) << log.toStdString();
  EXPECT_TRUE(log.contains("missing.png")) << log.toStdString();
  EXPECT_TRUE(w.view()->jointHandles().empty());
  EXPECT_FALSE(w.settingsPanel()->findChild<QPushButton*>("acceptEstimate")->isEnabled());
}

}  // namespace
}  // namespace armmimic::test
