// The analysis workflow as an operator runs it: load the sample, run each engine, read the
// overlay, export, and compare the export with armmimic-cli's output for the same options.
#include <cmath>

#include <QCheckBox>
#include <QFileInfo>
#include <QImage>
#include <QSpinBox>
#include <QTabBar>
#include <QTest>
#include <QToolButton>

#include "analysis_job.h"
#include "angle_plot.h"
#include "app_actions.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/synth/truth_file.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_panel.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class AnalysisExportTest : public GuiTest {
 protected:
  // Opens `inputs`, sets `options`, runs the analysis to the end.
  void Run(MainWindow& w, const QStringList& inputs, const AnalysisOptions& options) {
    w.openInputs(inputs);
    ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && !w.view()->image().isNull(); }))
        << w.log()->text().toStdString();
    w.settingsPanel()->setOptions(options);
    ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
    ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
    ASSERT_FALSE(w.job()->resultPath().isEmpty()) << w.log()->text().toStdString();
  }

  void ExpectSameAsCli(MainWindow& w, const std::vector<std::string>& cli_args) {
    const std::string gui_path = tmp_.file("gui.tsv");
    ASSERT_TRUE(w.exportAngles(QString::fromStdString(gui_path))) << w.log()->text().toStdString();
    std::vector<std::string> args = {"-q", "analyze"};
    args.insert(args.end(), cli_args.begin(), cli_args.end());
    args.push_back("-o");
    args.push_back(tmp_.file("cli.tsv"));
    const CliResult r = RunCli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string gui = ReadFile(gui_path);
    EXPECT_FALSE(gui.empty());
    EXPECT_EQ(gui, ReadFile(tmp_.file("cli.tsv")));
  }
};

TEST_F(AnalysisExportTest, BgsubOverlayFollowsTruthAndExportEqualsCli) {
  const GuiScenes& s = scenes();
  MainWindow w;
  AnalysisOptions o = s.BgsubProtocol();
  o.engine.lk.standstill_frames = s.standstill_frames;
  Run(w, {QString::fromStdString(s.video())}, o);

  // One row per frame after the standstill, kept per frame for scrubbing and the plot.
  EXPECT_EQ(w.results().rows(), s.motion_frames);
  EXPECT_EQ(w.job()->summary().frames, s.motion_frames);
  EXPECT_GT(w.plot()->pointCount(), s.motion_frames / 2);
  EXPECT_EQ(w.plot()->frameTickStep(), 20);  // frames 0..69: labels every 20 frames

  // Scrub to a motion frame: the overlay shows that frame's measurement, and it follows truth.
  synth::TruthFile truth;
  ASSERT_TRUE(synth::ReadTruthFile(s.arm_dir + "/truth.tsv", &truth).ok());
  const int frame = s.background_frames + s.standstill_frames + s.motion_frames / 2;
  w.player()->seek(frame);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == frame; }));
  ASSERT_TRUE(w.view()->measurement().has_value());
  const ArmMeasurement& m = *w.view()->measurement();
  EXPECT_EQ(m.frame, frame);
  ASSERT_EQ(m.phase, MeasurementPhase::kOk) << m.note;
  const gui::OverlayTexts texts = w.view()->overlayTexts();
  EXPECT_EQ(texts.frame.toStdString(),
            "frame " + std::to_string(frame) + " / " +
                std::to_string(s.background_frames + s.standstill_frames + s.motion_frames - 1));
  EXPECT_NE(texts.orientation.indexOf(QString::number(m.upper_deg, 'f', 1)), -1)
      << texts.orientation.toStdString();
  const synth::TruthRow* t = nullptr;
  for (const synth::TruthRow& row : truth.rows) {
    if (row.frame == frame) t = &row;
  }
  ASSERT_NE(t, nullptr);
  EXPECT_LE(std::abs(AngleDiff(m.upper_deg, t->upper_deg)), 10.0)
      << "overlay upper " << m.upper_deg << " truth " << t->upper_deg;
  EXPECT_EQ(w.plot()->cursorFrame(), frame);

  ExpectSameAsCli(
      w, {s.video(), "--engine", "bgsub", "--background", s.background(), "--arm-length",
          s.arm_length(), "--start", std::to_string(s.background_frames), "--standstill-frames",
          std::to_string(s.standstill_frames)});
  AngleFile file;
  ASSERT_TRUE(ReadAngleFile(tmp_.file("gui.tsv"), &file).ok());
  EXPECT_EQ(static_cast<int>(file.rows.size()), s.motion_frames);
}

// The end-of-run message says why rows were lost, as the CLI's report does: here an arm-length
// image that shows no arm (the empty room itself) leaves bgsub without a calibration.
TEST_F(AnalysisExportTest, TheEndOfRunMessageSaysWhyRowsWereLost) {
  const GuiScenes& s = scenes();
  MainWindow w;
  AnalysisOptions o = s.BgsubProtocol();
  o.arm_length_path = s.background();
  Run(w, {QString::fromStdString(s.video())}, o);
  EXPECT_EQ(w.job()->summary().lost, s.motion_frames);
  const std::string expected = "lost rows: arm-length image: no arm differs from the standstill (" +
                               std::to_string(s.motion_frames) + ")";
  EXPECT_NE(w.log()->text().toStdString().find(expected), std::string::npos)
      << w.log()->text().toStdString();
}

TEST_F(AnalysisExportTest, LkExportEqualsCli) {
  const GuiScenes& s = scenes();
  MainWindow w;
  AnalysisOptions o;
  o.engine.kind = EngineKind::kLk;
  o.background_path = s.background();
  o.start = s.background_frames;
  o.engine.bgsub.standstill_frames = s.standstill_frames;
  o.engine.lk.standstill_frames = s.standstill_frames;
  Run(w, {QString::fromStdString(s.video())}, o);
  EXPECT_EQ(w.results().rows(), s.motion_frames);
  // What lk estimated without joints (the calibration from the standstill) is in the log, as
  // armmimic-cli prints it.
  EXPECT_NE(w.log()->text().toStdString().find("Estimated: lk: "), std::string::npos)
      << w.log()->text().toStdString();
  ExpectSameAsCli(w, {s.video(), "--engine", "lk", "--background", s.background(), "--start",
                      std::to_string(s.background_frames), "--standstill-frames",
                      std::to_string(s.standstill_frames)});
}

TEST_F(AnalysisExportTest, AdvancedParametersReachTheEngineAsCliParamDoes) {
  const GuiScenes& s = scenes();
  MainWindow w;
  AnalysisOptions o;
  o.engine.kind = EngineKind::kLk;
  o.background_path = s.background();
  o.start = s.background_frames;
  o.engine.lk.standstill_frames = s.standstill_frames;
  w.openInputs({QString::fromStdString(s.video())});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
  w.settingsPanel()->setOptions(o);
  // Three advanced fields changed through their editors, as an operator does.
  gui::EngineSettingsPanel* panel = w.settingsPanel();
  panel->advancedToggle(EngineKind::kLk)->click();
  auto* corners = qobject_cast<QSpinBox*>(panel->parameterEditor(EngineKind::kLk, "max_corners"));
  auto* window = qobject_cast<QSpinBox*>(panel->parameterEditor(EngineKind::kLk, "window_px"));
  auto* bar = qobject_cast<QCheckBox*>(panel->parameterEditor(EngineKind::kLk, "use_bar"));
  ASSERT_TRUE(corners && window && bar);
  corners->setValue(120);
  window->setValue(21);
  bar->click();
  EXPECT_EQ(panel->options().engine.lk.max_corners, 120);
  EXPECT_FALSE(panel->options().engine.lk.use_bar);
  ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
  ASSERT_FALSE(w.job()->resultPath().isEmpty()) << w.log()->text().toStdString();
  ExpectSameAsCli(w, {s.video(), "--engine", "lk", "--background", s.background(), "--start",
                      std::to_string(s.background_frames), "--standstill-frames",
                      std::to_string(s.standstill_frames), "--param", "lk.max_corners=120",
                      "--param", "lk.window_px=21", "--param=lk.use_bar=false"});
  // And the parameters matter: the defaults give another file.
  const CliResult r =
      RunCli({"-q", "analyze", s.video(), "--engine", "lk", "--background", s.background(),
              "--start", std::to_string(s.background_frames), "--standstill-frames",
              std::to_string(s.standstill_frames), "-o", tmp_.file("defaults.tsv")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(ReadFile(tmp_.file("defaults.tsv")), ReadFile(tmp_.file("gui.tsv")));
}

TEST_F(AnalysisExportTest, MarkerExportEqualsCliAndShowsTheCylinderAndSignedYaw) {
  const GuiScenes& s = scenes();
  MainWindow w;
  AnalysisOptions o;
  o.engine.kind = EngineKind::kMarker;
  o.reference_path = s.marker_dir + "/reference.png";
  Run(w, {QString::fromStdString(s.marker_dir + "/views")}, o);
  EXPECT_EQ(w.results().rows(), 6);
  // The first view's overlay carries the markers and the dark patches weighed (Fig. 4-3).
  ASSERT_TRUE(WaitUntil([&] { return w.view()->measurement().has_value(); }));
  EXPECT_FALSE(w.view()->measurement()->candidate_boxes.empty());
  // The joint's bend, not arm segments, in the lower right.
  const gui::OverlayTexts texts = w.view()->overlayTexts();
  EXPECT_TRUE(texts.orientation.startsWith("bend ")) << texts.orientation.toStdString();
  // The fitted cylinder's axis, and the yaw with its sign (positive: the joint's right side
  // turned to the camera).
  const ArmMeasurement shown = *w.view()->measurement();
  ASSERT_EQ(shown.phase, MeasurementPhase::kOk) << shown.note;
  ASSERT_EQ(shown.cylinder_axis_px.size(), 2u);
  const QString yaw = QString::number(std::abs(shown.yaw_signed_deg), 'f', 1);
  EXPECT_EQ(texts.yaw,
            QString("yaw ") + (shown.yaw_signed_deg >= 0 ? "+" : "-") + yaw + QChar(0x00B0));
  // The saved frame draws the axis (magenta) from the lower part up to the pivot, and only with
  // the marker overlay on.
  auto axis_pixels = [&](const QString& path) {
    const QImage image = QImage(path).convertToFormat(QImage::Format_RGB32);
    const cv::Point2d a = shown.cylinder_axis_px[0], b = shown.cylinder_axis_px[1];
    int n = 0;
    for (double t = 0.05; t <= 0.95; t += 0.01) {
      const int x = static_cast<int>(std::lround(a.x + t * (b.x - a.x)));
      const int y = static_cast<int>(std::lround(a.y + t * (b.y - a.y)));
      bool magenta = false;
      for (int dx = -1; dx <= 1; ++dx) {
        const QColor c = image.pixelColor(x + dx, y);
        magenta |= c.red() > 200 && c.green() < 100 && c.blue() > 170;
      }
      n += magenta;
    }
    return n;
  };
  const QString frame_path = QString::fromStdString(tmp_.file("marker_frame.png"));
  ASSERT_TRUE(w.saveFrame(frame_path)) << w.log()->text().toStdString();
  EXPECT_GT(axis_pixels(frame_path), 20);
  w.actions()->ovMarkers->setChecked(false);
  ASSERT_TRUE(w.saveFrame(frame_path));
  EXPECT_EQ(axis_pixels(frame_path), 0);
  w.actions()->ovMarkers->setChecked(true);
  // The plot shows the signed yaw and the bend of every measured view; 6 views give whole-frame
  // labels.
  const QList<QPointF> yaws = w.plot()->yawPoints();
  ASSERT_EQ(yaws.size(), w.job()->summary().ok);
  for (const QPointF& p : yaws) {
    const ArmMeasurement* m = w.results().find(static_cast<int>(p.x()));
    ASSERT_NE(m, nullptr);
    EXPECT_DOUBLE_EQ(p.y(), m->yaw_signed_deg);
  }
  EXPECT_EQ(w.plot()->bendCount(), w.job()->summary().ok);
  EXPECT_EQ(w.plot()->pointCount(), 0);
  EXPECT_EQ(w.plot()->frameTickStep(), 1);
  EXPECT_EQ(texts.orientation.indexOf("upper"), -1) << texts.orientation.toStdString();
  // Still images (no frame rate) are planned for the robot without a low-pass filter instead of
  // failing on it; the filter setting stays for the next video.
  EXPECT_TRUE(w.robotPanel()->plan().loaded());
  EXPECT_EQ(w.log()->text().indexOf("cutoff"), -1) << w.log()->text().toStdString();
  EXPECT_TRUE(w.robotPanel()->plan().planned()) << w.log()->text().toStdString();
  EXPECT_EQ(w.robotPanel()->plan().report().filter_cutoff_hz, 0);
  EXPECT_DOUBLE_EQ(w.robotPanel()->plannerOptions().cutoff_hz, robot::PlannerOptions().cutoff_hz);
  // The mapping rows switched to the marker defaults (J2 = -bend - 90), and the planned program
  // is the one `armmimic-cli plan` makes from the same file with no flags.
  EXPECT_EQ(w.robotPanel()->plannerOptions().mapping.j2.offset_deg, -90);
  const std::string gui_val = tmp_.file("gui.val");
  ASSERT_TRUE(w.robotPanel()->exportVal(QString::fromStdString(gui_val)));
  const CliResult plan =
      RunCli({"-q", "plan", w.robotPanel()->plan().angle_path(), "-o", tmp_.file("cli.val")});
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_EQ(ReadFile(gui_val), ReadFile(tmp_.file("cli.val")));
  ExpectSameAsCli(w, {s.marker_dir + "/views", "--engine", "marker", "--reference",
                      s.marker_dir + "/reference.png"});
}

TEST_F(AnalysisExportTest, BackgroundEstimationMatchesCli) {
  const GuiScenes& s = scenes();
  MainWindow w;
  w.openInputs({QString::fromStdString(s.video())});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
  const QString path = QString::fromStdString(tmp_.file("bg.png"));
  ASSERT_TRUE(w.estimateBackground(s.background_frames, path));
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 30000));
  ASSERT_TRUE(QFileInfo::exists(path)) << w.log()->text().toStdString();
  EXPECT_EQ(w.settingsPanel()->options().background_path, path.toStdString());
  const CliResult r = RunCli({"-q", "background", s.video(), "-o", tmp_.file("cli_bg.png"),
                              "--frames", std::to_string(s.background_frames)});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const QImage gui(path), cli(QString::fromStdString(tmp_.file("cli_bg.png")));
  ASSERT_FALSE(gui.isNull());
  EXPECT_EQ(gui.convertToFormat(QImage::Format_RGB888), cli.convertToFormat(QImage::Format_RGB888));
}

TEST_F(AnalysisExportTest, CancelKeepsTheWindowResponsiveAndMarksTheFileIncomplete) {
  const GuiScenes& s = scenes();
  MainWindow w;
  AnalysisOptions o = s.BgsubProtocol();
  w.openInputs({QString::fromStdString(s.video())});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
  w.settingsPanel()->setOptions(o);
  ASSERT_TRUE(w.startAnalysis());
  w.job()->cancel();
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 30000));
  if (!w.job()->resultPath().isEmpty()) {
    AngleFile file;
    ASSERT_TRUE(ReadAngleFile(w.job()->resultPath().toStdString(), &file).ok());
    EXPECT_EQ(file.complete, !w.job()->summary().cancelled);
  }
  EXPECT_FALSE(w.job()->isRunning());
}

TEST_F(AnalysisExportTest, BadInputIsReportedOnceAndNamed) {
  MainWindow w;
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  EXPECT_FALSE(w.exportAngles(QString::fromStdString(tmp_.file("x.tsv"))));
  EXPECT_FALSE(w.exportAngles(QString::fromStdString(tmp_.file("x.tsv"))));
  EXPECT_EQ(w.log()->errorCount(), 1);
  const std::string missing = tmp_.file("missing.avi");
  w.openInputs({QString::fromStdString(missing)});
  ASSERT_TRUE(WaitUntil([&] { return w.log()->errorCount() == 2; }));
  EXPECT_NE(w.log()->text().indexOf("missing.avi"), -1) << w.log()->text().toStdString();
  // A missing arm-length image is named before anything runs.
  const GuiScenes& s = scenes();
  w.openInputs({QString::fromStdString(s.video())});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
  AnalysisOptions o;
  o.background_path = s.background();
  o.arm_length_path = tmp_.file("no-arm.png");
  w.settingsPanel()->setOptions(o);
  if (w.startAnalysis()) {
    ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 30000));
  }
  EXPECT_NE(w.log()->text().indexOf("no-arm.png"), -1) << w.log()->text().toStdString();
  EXPECT_TRUE(w.job()->resultPath().isEmpty());
  // The error brought Messages to the front; the corrected run brings its angles back.
  auto bottom_tab = [&] {  // the tab in front in the Angles | Messages dock area
    for (QTabBar* bar : w.findChildren<QTabBar*>()) {
      for (int i = 0; i < bar->count(); ++i) {
        if (bar->tabText(i) == "Messages") return bar->tabText(bar->currentIndex());
      }
    }
    return QString();
  };
  EXPECT_EQ(bottom_tab(), "Messages");
  o.arm_length_path = s.arm_length();
  o.start = s.background_frames;
  o.engine.bgsub.standstill_frames = s.standstill_frames;
  w.settingsPanel()->setOptions(o);
  ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
  ASSERT_FALSE(w.job()->resultPath().isEmpty()) << w.log()->text().toStdString();
  EXPECT_EQ(bottom_tab(), "Angles");
}

}  // namespace
}  // namespace armmimic::test
