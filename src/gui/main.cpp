// armmimic: the desktop application. Load a video, watch the overlay, export the angle file and
// send the sequence to the PUMA controller.
#include <QApplication>
#include <QCoreApplication>

#include "armmimic/version.h"
#include "command_line.h"
#include "main_window.h"

int main(int argc, char** argv) {
  QCoreApplication::setOrganizationName("armmimic");
  QCoreApplication::setApplicationName("armmimic");
  QCoreApplication::setApplicationVersion(ARMMIMIC_VERSION);
  {
    // --help, --version and usage errors need no display: they are handled before the
    // QApplication (which needs one) exists.
    QCoreApplication core(argc, argv);
    const armmimic::gui::CommandLine early = armmimic::gui::ParseCommandLine(core.arguments());
    if (early.exit_code >= 0) return early.exit_code;
  }
  QApplication::setHighDpiScaleFactorRoundingPolicy(
      Qt::HighDpiScaleFactorRoundingPolicy::PassThrough);
  QApplication app(argc, argv);
  // QApplication has taken its own options (-platform, -style, ...) out of the arguments.
  const armmimic::gui::CommandLine command_line =
      armmimic::gui::ParseCommandLine(QApplication::arguments());
  armmimic::gui::MainWindow window;
  window.show();
  if (!command_line.inputs.isEmpty()) window.openInputs(command_line.inputs);
  return QApplication::exec();
}
