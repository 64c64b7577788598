#include "prompts.h"

#include <QFileDialog>
#include <QInputDialog>
#include <QLineEdit>
#include <QMessageBox>

#include "armmimic/version.h"

namespace armmimic::gui {

QStringList AskInputs(QWidget* parent, const QString& dir) {
  return QFileDialog::getOpenFileNames(
      parent, QObject::tr("Open video or images"), dir,
      QObject::tr("Videos and images (*.avi *.mp4 *.mkv *.mov *.png *.jpg *.jpeg *.bmp *.tif "
                  "*.tiff);;All files (*)"));
}

QString AskImageFolder(QWidget* parent, const QString& dir) {
  return QFileDialog::getExistingDirectory(parent, QObject::tr("Open a folder of images"), dir);
}

std::optional<QString> AskCamera(QWidget* parent) {
  bool ok = false;
  const QString src =
      QInputDialog::getText(parent, QObject::tr("Capture from camera"),
                            QObject::tr("Camera index (0, 1, …) or stream URL (rtsp://…):"),
                            QLineEdit::Normal, "0", &ok)
          .trimmed();
  if (!ok || src.isEmpty()) return std::nullopt;
  bool is_index = false;
  src.toInt(&is_index);
  return is_index ? "camera:" + src : src;
}

QString AskOpenPath(QWidget* parent, const QString& title, const QString& dir,
                    const QString& filter) {
  return QFileDialog::getOpenFileName(parent, title, dir, filter);
}

QString AskSavePath(QWidget* parent, const QString& title, const QString& suggested,
                    const QString& filter) {
  return QFileDialog::getSaveFileName(parent, title, suggested, filter);
}

std::optional<int> AskBackgroundFrames(QWidget* parent) {
  bool ok = false;
  const int k = QInputDialog::getInt(
      parent, QObject::tr("Estimate background"),
      QObject::tr("Average the first K frames of the empty scene (thesis 5.2.1), K ="), 45, 1,
      100000, 1, &ok);
  return ok ? std::optional<int>(k) : std::nullopt;
}

void ShowAbout(QWidget* parent) {
  QMessageBox::about(
      parent, QObject::tr("About armmimic"),
      QObject::tr("<b>armmimic %1</b><p>Makes a PUMA 760 arm mimic a human arm seen on video: "
                  "marker joint, background subtraction and Lucas–Kanade engines, angle file "
                  "v1, VAL II over RS-232.</p>")
          .arg(ARMMIMIC_VERSION));
}

}  // namespace armmimic::gui
