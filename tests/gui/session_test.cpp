// Work that survives a restart: an angle file made by the CLI opened with its options, a session
// that restores video, options, clicks and results, reset to defaults on every parameter form,
// drops of angle files, VAL programs and sessions, and CSV next to the TSV.
#include <QApplication>
#include <QDir>
#include <QDropEvent>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMimeData>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QToolButton>
#include <QUrl>
#include <QWindow>

#include "analysis_job.h"
#include "angle_plot.h"
#include "app_actions.h"
#include "armmimic/core/angle_csv.h"
#include "armmimic/engines/option_fields.h"
#include "csv_export_dialog.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "robot_panel.h"
#include "robot_plan.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class SessionTest : public GuiTest {
 protected:
  // The arm scene's video copied to `dir` and analysed there by the CLI with changed settings.
  std::string CliAngles(const std::string& dir) {
    QDir().mkpath(QString::fromStdString(dir));
    const std::string video = dir + "/scene.avi";
    QFile::copy(QString::fromStdString(scenes().video()), QString::fromStdString(video));
    const std::string out = dir + "/scene.tsv";
    const CliResult r =
        RunCli({"-q", "analyze", video, "-o", out, "--engine", "bgsub", "--background",
                scenes().background(), "--arm-length", scenes().arm_length(), "--start",
                std::to_string(scenes().background_frames), "--standstill-frames",
                std::to_string(scenes().standstill_frames), "--threshold", "40", "--param",
                "bgsub.closing_size=7"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  }
  // A file dragged over the middle of the window and dropped, through the window system's path
  // (the top-level window finds the widget under the pointer that takes drops).
  static void Drop(MainWindow& w, const QString& path) {
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(path)});
    const QPointF at(w.width() / 2, w.height() / 2);
    QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w.windowHandle(), &enter);
    ASSERT_TRUE(enter.isAccepted());
    QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w.windowHandle(), &drop);
  }
  static void Show(MainWindow& w) {
    w.resize(1200, 800);
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  }
};

TEST_F(SessionTest, AnAngleFileFromTheCliOpensWithItsVideoOptionsAndPlan) {
  const std::string tsv = CliAngles(tmp_.file("run"));
  AngleFile file;
  ASSERT_TRUE(ReadAngleFile(tsv, &file).ok());
  MainWindow w;
  Show(w);
  AnalysisOptions mine = w.settingsPanel()->options();
  mine.engine.kind = EngineKind::kLk;
  mine.engine.lk.max_corners = 99;  // another engine's setting: not the file's to change
  w.settingsPanel()->setOptions(mine);
  ASSERT_TRUE(w.openAngleFile(QString::fromStdString(tsv))) << w.log()->text().toStdString();
  // The video named in the header lies beside the file: it opens, for the overlay.
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && w.results().rows() > 0; }));
  EXPECT_EQ(QFileInfo(w.player()->inputs().first()).fileName(), "scene.avi");
  EXPECT_EQ(w.results().rows(), static_cast<int>(file.rows.size()));
  int ok = 0;
  for (const AngleRow& r : file.rows) ok += r.ok() ? 1 : 0;
  EXPECT_EQ(w.plot()->pointCount(), ok);
  const AngleRow& row = file.rows[file.rows.size() / 2];
  w.player()->seek(row.frame);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == row.frame; }));
  ASSERT_TRUE(w.view()->measurement().has_value());
  EXPECT_DOUBLE_EQ(w.view()->measurement()->fore_deg, row.fore_deg);
  // The options it was made with.
  const AnalysisOptions o = w.settingsPanel()->options();
  EXPECT_EQ(o.engine.kind, EngineKind::kBgsub);
  EXPECT_EQ(o.engine.bgsub.threshold, 40);
  EXPECT_EQ(o.engine.bgsub.closing_size, 7);
  EXPECT_EQ(o.engine.bgsub.standstill_frames, scenes().standstill_frames);
  EXPECT_EQ(o.start, scenes().background_frames);
  EXPECT_EQ(o.engine.lk.max_corners, 99);
  // The robot panel plans from it, and exporting gives the file back as it is.
  EXPECT_TRUE(w.robotPanel()->plan().planned()) << w.log()->text().toStdString();
  EXPECT_FALSE(w.hasUnsavedResults());
  ASSERT_TRUE(w.exportAngles(QString::fromStdString(tmp_.file("again.tsv"))));
  EXPECT_EQ(ReadFile(tmp_.file("again.tsv")), ReadFile(tsv));

  // Without its video beside it: the plot and the plan, and a word about the overlay.
  QDir().mkpath(QString::fromStdString(tmp_.file("alone")));
  const std::string alone = tmp_.file("alone/scene.tsv");
  WriteFile(alone, ReadFile(tsv));
  MainWindow w2;
  Show(w2);
  ASSERT_TRUE(w2.openAngleFile(QString::fromStdString(alone)));
  EXPECT_FALSE(w2.player()->isOpen());
  EXPECT_EQ(w2.plot()->pointCount(), ok);
  EXPECT_TRUE(w2.robotPanel()->plan().planned());
  EXPECT_TRUE(w2.log()->text().contains("not beside it")) << w2.log()->text().toStdString();
  // A file that is no angle file is named.
  WriteFile(tmp_.file("bad.tsv"), "frame\tnothing\n");
  EXPECT_FALSE(w2.openAngleFile(QString::fromStdString(tmp_.file("bad.tsv"))));
  EXPECT_TRUE(w2.log()->text().contains(QString::fromStdString(tmp_.file("bad.tsv"))));
}

TEST_F(SessionTest, AMarkerFileOpensWithItsFolderOfViews) {
  const std::string out = tmp_.file("views.tsv");
  const CliResult r =
      RunCli({"-q", "analyze", scenes().marker_dir + "/views", "-o", out, "--engine", "marker",
              "--reference", scenes().marker_dir + "/reference.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The views lie beside the file, as the header's source names them.
  ASSERT_TRUE(QDir().rename(QString::fromStdString(tmp_.file("views.tsv")),
                            QString::fromStdString(scenes().marker_dir + "/views.tsv")));
  MainWindow w;
  Show(w);
  ASSERT_TRUE(w.openAngleFile(QString::fromStdString(scenes().marker_dir + "/views.tsv")));
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && w.results().rows() > 0; }))
      << w.log()->text().toStdString();
  EXPECT_EQ(QFileInfo(w.player()->inputs().first()).fileName(), "views");
  EXPECT_GT(w.plot()->bendCount(), 0);
  EXPECT_EQ(w.settingsPanel()->options().engine.kind, EngineKind::kMarker);
  QFile::remove(QString::fromStdString(scenes().marker_dir + "/views.tsv"));
}

TEST_F(SessionTest, ASessionRestoresVideoOptionsClicksAndResults) {
  const QString session = QString::fromStdString(tmp_.file("scene.armmimic"));
  std::string exported;
  AnalysisOptions saved;
  {
    MainWindow w;
    ShowAndAnalyze(w);
    w.settingsPanel()->setRoi(cv::Rect(100, 20, 150, 200));
    w.settingsPanel()->setShoulder(cv::Point2d(160.5, 88));
    AnalysisOptions o = w.settingsPanel()->options();
    ASSERT_TRUE(SetEngineOption("lk.max_corners=123", &o.engine).ok());  // another engine's
    w.settingsPanel()->setOptions(o);
    w.player()->seek(42);
    ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == 42; }));
    ASSERT_TRUE(w.saveSession(session)) << w.log()->text().toStdString();
    EXPECT_FALSE(w.hasUnsavedResults());
    ASSERT_TRUE(w.exportAngles(QString::fromStdString(tmp_.file("first.tsv"))));
    exported = ReadFile(tmp_.file("first.tsv"));
    saved = w.settingsPanel()->options();
  }
  MainWindow w;
  Show(w);
  ASSERT_TRUE(w.openSession(session)) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && w.view()->frameIndex() == 42; }))
      << w.log()->text().toStdString();
  EXPECT_EQ(w.player()->inputs().first().toStdString(), scenes().video());
  const AnalysisOptions o = w.settingsPanel()->options();
  EXPECT_EQ(o.roi, saved.roi);
  EXPECT_EQ(o.shoulder_px, saved.shoulder_px);
  EXPECT_EQ(o.engine.lk.max_corners, 123);
  EXPECT_EQ(o.engine.bgsub.standstill_frames, scenes().standstill_frames);
  EXPECT_EQ(o.background_path, scenes().background());
  EXPECT_EQ(o.start, scenes().background_frames);
  EXPECT_GT(w.results().rows(), 0);
  EXPECT_TRUE(w.robotPanel()->plan().planned());
  ASSERT_TRUE(w.exportAngles(QString::fromStdString(tmp_.file("second.tsv"))));
  EXPECT_EQ(ReadFile(tmp_.file("second.tsv")), exported);
}

TEST_F(SessionTest, ASessionFolderCanMoveAsAWhole) {
  const std::string tsv = CliAngles(tmp_.file("a"));
  const QString session = QString::fromStdString(tmp_.file("a/scene.armmimic"));
  {
    MainWindow w;
    Show(w);
    ASSERT_TRUE(w.openAngleFile(QString::fromStdString(tsv)));
    ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && w.results().rows() > 0; }));
    ASSERT_TRUE(w.saveSession(session));
  }
  QFile f(session);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
  EXPECT_EQ(root.value("inputs").toVariant().toStringList(), QStringList{"scene.avi"});
  ASSERT_TRUE(QDir().rename(QString::fromStdString(tmp_.file("a")),
                            QString::fromStdString(tmp_.file("b"))));
  MainWindow w;
  Show(w);
  ASSERT_TRUE(w.openSession(QString::fromStdString(tmp_.file("b/scene.armmimic"))));
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && w.results().rows() > 0; }));
  EXPECT_EQ(w.player()->inputs().first().toStdString(), tmp_.file("b/scene.avi"));
}

TEST_F(SessionTest, ABrokenSessionIsNamedWithWhatIsWrong) {
  MainWindow w;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{ not json", "not a session file"},
      {"{\"format\": \"something else\"}", "not a session file"},
      {"{\"format\": \"armmimic-session\", \"version\": 9}", "version 9"},
      {"{\"format\": \"armmimic-session\", \"version\": 1, \"analysis\": {\"engine\": \"x\"}}",
       "analysis.engine"},
      {"{\"format\": \"armmimic-session\", \"version\": 1, \"analysis\": {\"engine\": \"lk\", "
       "\"parameters\": {\"lk.no_such\": \"1\"}}}",
       "analysis.parameters"}};
  for (const auto& [text, what] : cases) {
    const std::string path = tmp_.file("broken.armmimic");
    WriteFile(path, text);
    EXPECT_FALSE(w.openSession(QString::fromStdString(path)));
    const QString log = w.log()->text();
    EXPECT_TRUE(log.contains(QString::fromStdString(path))) << log.toStdString();
    EXPECT_TRUE(log.contains(QString::fromStdString(what))) << what << "\n" << log.toStdString();
    w.log()->clear();
  }
  EXPECT_FALSE(w.player()->isOpen());
}

TEST_F(SessionTest, EveryParameterFormResetsToItsDefaults) {
  MainWindow w;
  gui::EngineSettingsPanel* panel = w.settingsPanel();
  AnalysisOptions o = panel->options();
  o.engine.bgsub.threshold = 70;
  o.engine.lk.max_corners = 99;
  o.engine.marker.low = 33;
  panel->setOptions(o);
  for (EngineKind kind : {EngineKind::kBgsub, EngineKind::kLk, EngineKind::kMarker}) {
    panel->resetButton(kind)->click();
  }
  const EngineOptions defaults;
  const EngineOptions now = panel->options().engine;
  EXPECT_EQ(now.bgsub.threshold, defaults.bgsub.threshold);
  EXPECT_EQ(now.lk.max_corners, defaults.lk.max_corners);
  EXPECT_EQ(now.marker.low, defaults.marker.low);
  EXPECT_TRUE(ChangedEngineOptions(now).empty());

  gui::RobotPanel* robot = w.robotPanel();
  robot::PlannerOptions p = robot->plannerOptions();
  p.cutoff_hz = 1.5;
  p.limits.max_deg[2] = 10;
  p.mapping.mirror = true;
  robot->setPlannerOptions(p);
  robot->findChild<QPushButton*>("planDefaultsButton")->click();
  const robot::PlannerOptions d;
  const robot::PlannerOptions after = robot->plannerOptions();
  EXPECT_EQ(after.cutoff_hz, d.cutoff_hz);
  EXPECT_EQ(after.limits.max_deg, d.limits.max_deg);
  EXPECT_FALSE(after.mapping.mirror);
  EXPECT_EQ(robot->findChild<QTableWidget*>("limitsTable")->item(2, 1)->text(), "45");
}

TEST_F(SessionTest, APoseAngleFileRestoresThePoseSettings) {
  const std::string dir = tmp_.file("pose");
  QDir().mkpath(QString::fromStdString(dir));
  QFile::copy(QString::fromStdString(scenes().video()), QString::fromStdString(dir + "/scene.avi"));
  const std::string tsv = dir + "/scene.tsv";
  std::string text =
      "# armmimic angles v1\n"
      "# engine=pose source=scene.avi fps=30 width=320 height=240 start=0 pose.side=left "
      "pose.min_score=0.35 pose.arm_crop=1.25 pose.max_disagreement_deg=12\n"
      "# units: degrees; directions CCW on screen from +x, (-180,180]; image y down\n"
      "frame\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\tupper_cx\tupper_cy\t"
      "fore_cx\tfore_cy\tconfidence\n";
  for (int f = 0; f < 5; ++f) {
    text += std::to_string(f) + "\t" + std::to_string(f / 30.0) +
            "\tok\t-90.000\t-80.000\tnan\tnan\t100.00\t100.00\t100.00\t140.00\t0.900\n";
  }
  QFile out(QString::fromStdString(tsv));
  ASSERT_TRUE(out.open(QIODevice::WriteOnly));
  out.write(text.c_str());
  out.close();
  MainWindow w;
  Show(w);
  ASSERT_TRUE(w.openAngleFile(QString::fromStdString(tsv))) << w.log()->text().toStdString();
  const EngineOptions e = w.settingsPanel()->options().engine;
  EXPECT_EQ(e.kind, EngineKind::kPose);
  EXPECT_EQ(e.pose.side, PoseSide::kLeft);
  EXPECT_DOUBLE_EQ(e.pose.min_score, 0.35);
  EXPECT_DOUBLE_EQ(e.pose.arm_crop, 1.25);
  EXPECT_DOUBLE_EQ(e.pose.max_disagreement_deg, 12);
  EXPECT_TRUE(WaitUntil([&] { return w.results().rows() == 5; }));
}

TEST_F(SessionTest, DropsOpenAngleFilesProgramsAndSessions) {
  const std::string tsv = CliAngles(tmp_.file("run"));
  const std::string val = tmp_.file("run/program.val");
  const CliResult plan = RunCli({"-q", "plan", tsv, "-o", val});
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  MainWindow w;
  Show(w);
  // An angle file is read as one, not opened as a video.
  Drop(w, QString::fromStdString(tsv));
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && w.results().rows() > 0; }))
      << w.log()->text().toStdString();
  EXPECT_EQ(QFileInfo(w.player()->inputs().first()).suffix(), "avi");
  // A VAL program goes to the robot panel, checked and ready to send as written.
  Drop(w, QString::fromStdString(val));
  EXPECT_TRUE(w.robotPanel()->plan().fromProgram());
  EXPECT_TRUE(w.robotPanel()->plan().planned()) << w.log()->text().toStdString();
  EXPECT_GE(w.robotPanel()->plan().trajectory().keyframes.size(), 2u);
  std::string text;
  ASSERT_TRUE(w.robotPanel()->plan().ValText({}, &text).ok());
  EXPECT_EQ(text, ReadFile(val));
  // A session restores its results, also when its name ends in .json.
  const QString session = QString::fromStdString(tmp_.file("run/work.json"));
  ASSERT_TRUE(w.saveSession(session));
  MainWindow w2;
  Show(w2);
  Drop(w2, session);
  ASSERT_TRUE(WaitUntil([&] { return w2.player()->isOpen() && w2.results().rows() > 0; }))
      << w2.log()->text().toStdString();
  EXPECT_EQ(w2.results().rows(), w.results().rows());
}

TEST_F(SessionTest, CsvSitsNextToTheAngleFileWithTheVideosName) {
  MainWindow w;
  ShowAndAnalyze(w);
  EXPECT_TRUE(w.suggestedPath("csv").endsWith("/scene.csv"))
      << w.suggestedPath("csv").toStdString();
  EXPECT_TRUE(w.suggestedPath("tsv").endsWith("/scene.tsv"));
  EXPECT_TRUE(w.suggestedPath("plot.png").endsWith("/scene-plot.png"));
  ASSERT_TRUE(w.exportAngles(QString::fromStdString(tmp_.file("scene.tsv"))));
  AngleFile file;
  ASSERT_TRUE(ReadAngleFile(tmp_.file("scene.tsv"), &file).ok());
  const QString csv = QString::fromStdString(tmp_.file("scene.csv"));
  ASSERT_TRUE(w.exportCsv(csv, CsvStyle::kComma, false));
  EXPECT_EQ(ReadFile(csv.toStdString()), FormatAnglesCsv(file.rows, false, CsvStyle::kComma));
  ASSERT_TRUE(w.exportCsv(csv, CsvStyle::kSemicolon, false));
  EXPECT_EQ(ReadFile(csv.toStdString()), FormatAnglesCsv(file.rows, false, CsvStyle::kSemicolon));
  // Only the frames in the plot's view.
  w.plot()->zoomTo(60, 69, -180, 180);
  ASSERT_TRUE(w.exportCsv(csv, CsvStyle::kComma, true));
  const std::string part = ReadFile(csv.toStdString());
  EXPECT_EQ(std::count(part.begin(), part.end(), '\n'), 1 + 10);
  EXPECT_EQ(part.find("\r\n60,"), part.find("\r\n"));  // the first row is frame 60
}

TEST_F(SessionTest, TheCsvDialogAsksFileStyleAndRows) {
  MainWindow w;
  ShowAndAnalyze(w);
  const QString csv = QString::fromStdString(tmp_.file("dialog.csv"));
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  bool semicolon_first = false;
  const bool shown = AnswerModal<gui::CsvExportDialog>(
      [&] { w.actions()->exportCsv->trigger(); },
      [&](gui::CsvExportDialog* d) {
        semicolon_first = d->style() == CsvStyle::kSemicolon;
        EXPECT_TRUE(d->path().endsWith("scene.csv")) << d->path().toStdString();
        EXPECT_FALSE(d->visibleOnly());
        d->setPath(csv);
        d->accept();
      });
  QLocale::setDefault(QLocale::c());
  EXPECT_TRUE(shown);
  EXPECT_TRUE(semicolon_first);  // a decimal-comma locale gets "1,5;2,25"
  const std::string text = ReadFile(csv.toStdString());
  EXPECT_EQ(text.rfind("frame;time (s);status;", 0), 0u) << text.substr(0, 80);
}

}  // namespace
}  // namespace armmimic::test
