// armmimic: the desktop application (placeholder until the GUI issue lands its widgets).
#include <QApplication>
#include <QLabel>

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QApplication::setApplicationName("armmimic");
  QLabel label("armmimic");
  label.show();
  return QApplication::exec();
}
