// The same-file rule in the application: an export never replaces a file the session reads
// (the open video, the analysis' images, the angle file the plan comes from). The operator
// sees the refusal in the status bar and the log, and the file stays byte for byte.
#include <unistd.h>

#include <QStatusBar>

#include "analysis_job.h"
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

class ExportGuardTest : public GuiTest {};

TEST_F(ExportGuardTest, NoExportReplacesTheVideoOrTheImagesTheAnalysisReads) {
  const GuiScenes& s = scenes();
  const std::string video = tmp_.file("take 1.avi");
  WriteFile(video, ReadFile(s.video()));
  const std::string background = tmp_.file("bg.png");
  WriteFile(background, ReadFile(s.background()));
  const std::string video_bytes = ReadFile(video);
  const std::string background_bytes = ReadFile(background);
  // Other names for the same files: a symlink with an image name, a hard link.
  ASSERT_EQ(symlink(video.c_str(), tmp_.file("take.png").c_str()), 0);
  ASSERT_EQ(link(background.c_str(), tmp_.file("hard.tsv").c_str()), 0);

  MainWindow w;
  w.openInputs({QString::fromStdString(video)});
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && !w.view()->image().isNull(); }));
  AnalysisOptions o;
  o.engine.kind = EngineKind::kLk;
  o.background_path = background;
  o.start = s.background_frames;
  o.engine.lk.standstill_frames = s.standstill_frames;
  w.settingsPanel()->setOptions(o);
  ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
  ASSERT_FALSE(w.job()->resultPath().isEmpty()) << w.log()->text().toStdString();

  const QString v = QString::fromStdString(video);
  EXPECT_FALSE(w.exportAngles(v));
  EXPECT_TRUE(w.statusBar()->currentMessage().contains("is the same file as"))
      << w.statusBar()->currentMessage().toStdString();
  EXPECT_TRUE(w.log()->text().contains(v)) << w.log()->text().toStdString();
  EXPECT_FALSE(w.exportAngles(QString::fromStdString(tmp_.file("hard.tsv"))));
  EXPECT_TRUE(
      w.log()->text().contains("the background image " + QString::fromStdString(background)))
      << w.log()->text().toStdString();
  EXPECT_FALSE(w.saveFrame(QString::fromStdString(tmp_.file("take.png"))));
  EXPECT_FALSE(w.estimateBackground(5, QString::fromStdString(tmp_.file("take.png"))));
  ASSERT_TRUE(w.robotPanel()->plan().planned()) << w.log()->text().toStdString();
  EXPECT_FALSE(w.robotPanel()->exportVal(v));
  EXPECT_FALSE(
      w.robotPanel()->exportVal(QString::fromStdString(w.robotPanel()->plan().angle_path())));
  EXPECT_EQ(ReadFile(video), video_bytes);
  EXPECT_EQ(ReadFile(background), background_bytes);

  // Other files are written as before.
  EXPECT_TRUE(w.exportAngles(QString::fromStdString(tmp_.file("angles.tsv"))))
      << w.log()->text().toStdString();
  EXPECT_TRUE(w.robotPanel()->exportVal(QString::fromStdString(tmp_.file("arm.val"))));
  // Re-estimating the background may replace the background image chosen before: the estimate
  // reads only the video.
  EXPECT_TRUE(w.estimateBackground(5, QString::fromStdString(background)))
      << w.log()->text().toStdString();
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }));
}

}  // namespace
}  // namespace armmimic::test
