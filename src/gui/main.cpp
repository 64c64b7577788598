// armmimic: the desktop application. Load a video, watch the overlay, export the angle file and
// send the sequence to the PUMA controller.
#include <QApplication>
#include <QStringList>

#include "armmimic/version.h"
#include "main_window.h"

int main(int argc, char** argv) {
  QApplication::setHighDpiScaleFactorRoundingPolicy(
      Qt::HighDpiScaleFactorRoundingPolicy::PassThrough);
  QApplication app(argc, argv);
  QApplication::setOrganizationName("armmimic");
  QApplication::setApplicationName("armmimic");
  QApplication::setApplicationVersion(ARMMIMIC_VERSION);
  armmimic::gui::MainWindow window;
  window.show();
  const QStringList args = QApplication::arguments().mid(1);
  if (!args.isEmpty()) window.openInputs(args);
  return QApplication::exec();
}
