// An angle file or a session saved before some engine settings were removed (removed_options.h)
// still opens: the settings this version has come back, and one log line names the ignored ones.
#include <QTest>

#include "armmimic/core/angle_file.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

class RemovedOptionsTest : public GuiTest {
 protected:
  static void Show(MainWindow& w) {
    w.resize(1200, 800);
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  }
};

TEST_F(RemovedOptionsTest, AnOldAngleFileOpensAndOneLineNamesWhatWasIgnored) {
  const std::string made = tmp_.file("new.tsv");
  const CliResult r =
      RunCli({"-q", "analyze", scenes().video(), "-o", made, "--engine", "bgsub", "--background",
              scenes().background(), "--arm-length", scenes().arm_length(), "--start",
              std::to_string(scenes().background_frames), "--standstill-frames",
              std::to_string(scenes().standstill_frames), "--param", "bgsub.closing_size=7"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The same file as written before the removal: its header also records removed settings.
  AngleFile file;
  ASSERT_TRUE(ReadAngleFile(made, &file).ok());
  file.meta.emplace_back("bgsub.reject_shadow", "false");
  file.meta.emplace_back("bgsub.bend_hysteresis", "0.05");
  std::string text = ReadFile(made);
  const std::string line = FormatMetaLine(file.meta);
  const auto begin = text.find("\n# engine=") + 1;
  text.replace(begin, text.find('\n', begin) - begin, line);
  const std::string old = tmp_.file("old.tsv");
  WriteFile(old, text);

  MainWindow w;
  Show(w);
  ASSERT_TRUE(w.openAngleFile(QString::fromStdString(old))) << w.log()->text().toStdString();
  const AnalysisOptions o = w.settingsPanel()->options();
  EXPECT_EQ(o.engine.kind, EngineKind::kBgsub);
  EXPECT_EQ(o.engine.bgsub.closing_size, 7);
  const QString log = w.log()->text();
  EXPECT_EQ(log.count("ignored"), 1) << log.toStdString();
  EXPECT_TRUE(log.contains("ignored 2 recorded settings")) << log.toStdString();
  EXPECT_TRUE(log.contains("bgsub.reject_shadow: replaced by")) << log.toStdString();
  EXPECT_TRUE(log.contains("bgsub.bend_hysteresis: replaced by")) << log.toStdString();
}

TEST_F(RemovedOptionsTest, AnOldSessionOpensAndOneLineNamesWhatWasIgnored) {
  const std::string path = tmp_.file("old.armmimic");
  WriteFile(path,
            "{\"format\": \"armmimic-session\", \"version\": 1, \"frame\": 0, \"inputs\": [],"
            " \"analysis\": {\"engine\": \"bgsub\", \"parameters\": {"
            "\"bgsub.closing_size\": \"7\", \"bgsub.reject_shadow\": \"false\","
            " \"lk.max_corners\": \"123\"}}}");
  MainWindow w;
  Show(w);
  ASSERT_TRUE(w.openSession(QString::fromStdString(path))) << w.log()->text().toStdString();
  const AnalysisOptions o = w.settingsPanel()->options();
  EXPECT_EQ(o.engine.kind, EngineKind::kBgsub);
  EXPECT_EQ(o.engine.bgsub.closing_size, 7);
  EXPECT_EQ(o.engine.lk.max_corners, 123);
  const QString log = w.log()->text();
  EXPECT_EQ(log.count("ignored"), 1) << log.toStdString();
  EXPECT_TRUE(log.contains(QString::fromStdString(path) + ": ignored 1 recorded setting"))
      << log.toStdString();
  EXPECT_TRUE(log.contains("bgsub.reject_shadow: replaced by")) << log.toStdString();
}

}  // namespace
}  // namespace armmimic::test
