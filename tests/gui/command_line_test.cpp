// The desktop application's command line: the real armmimic binary run as a child process with
// no display at all (no DISPLAY, no WAYLAND_DISPLAY, no QT_QPA_PLATFORM), as on a server or in a
// packaging check; and a VIDEO argument reaching the window.
#include <QStringList>

#include "armmimic/version.h"
#include "command_line.h"
#include "gui_fixture.h"
#include "main_window.h"
#include "video_player.h"

namespace armmimic::test {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

CliResult RunWithoutDisplay(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {ARMMIMIC_GUI_PATH};
  argv.insert(argv.end(), args.begin(), args.end());
  return RunProgram(argv, EnvironmentWithout({"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}));
}

TEST(GuiCommandLine, HelpAndVersionPrintAndExitWithoutADisplay) {
  for (const char* help : {"--help", "-h"}) {
    const CliResult r = RunWithoutDisplay({help});
    EXPECT_EQ(r.exit_code, 0) << help << ": " << r.err;
    EXPECT_TRUE(Contains(r.out, "Usage:")) << r.out;
    EXPECT_TRUE(Contains(r.out, "[VIDEO...]")) << r.out;
    EXPECT_TRUE(Contains(r.out, "--version")) << r.out;
    EXPECT_FALSE(Contains(r.out, "-platform")) << "Qt's own options stay hidden: " << r.out;
  }
  CliResult r = RunWithoutDisplay({"--version"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, std::string("armmimic ") + ARMMIMIC_VERSION + "\n");
  // Qt's options are accepted (QApplication would take them), even before --version.
  r = RunWithoutDisplay({"-platform", "offscreen", "--version"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(GuiCommandLine, AnUnknownOptionIsAUsageError) {
  const CliResult r = RunWithoutDisplay({"--bogus", "video.avi"});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_TRUE(Contains(r.err, "armmimic: Unknown option 'bogus'")) << r.err;
  EXPECT_TRUE(Contains(r.err, "armmimic --help")) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

class GuiCommandLineWindow : public GuiTest {};

TEST_F(GuiCommandLineWindow, AVideoArgumentIsOpened) {
  const gui::CommandLine cl =
      gui::ParseCommandLine({"armmimic", QString::fromStdString(scenes().video())});
  EXPECT_EQ(cl.exit_code, -1);
  ASSERT_EQ(cl.inputs, QStringList{QString::fromStdString(scenes().video())});
  // "--" ends the options: a file whose name starts with '-' can be opened too.
  EXPECT_EQ(gui::ParseCommandLine({"armmimic", "--", "-take1.avi"}).inputs,
            QStringList{"-take1.avi"});
  gui::MainWindow w;
  w.openInputs(cl.inputs);
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen(); }));
  EXPECT_EQ(w.player()->inputs(), cl.inputs);
}

}  // namespace
}  // namespace armmimic::test
