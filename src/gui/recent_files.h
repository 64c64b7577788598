// RecentFiles: the "Open recent" menu and the folder file dialogs start in, remembered in
// QSettings.
#pragma once

#include <QObject>
#include <QStringList>

class QMenu;

namespace armmimic::gui {

class RecentFiles : public QObject {
  Q_OBJECT
 public:
  RecentFiles(QMenu* menu, QObject* parent);
  void add(const QString& path);
  // Adds an opened input (a file or folder; cameras and stream URLs are not listed) and
  // remembers its folder.
  void addInput(const QString& input);
  // The folder of the last file opened or saved ("" before any).
  static QString lastDir();
  static void rememberDir(const QString& path);
  QStringList files() const { return files_; }

 signals:
  void openRequested(const QString& path);

 private:
  void rebuild();
  QMenu* menu_;
  QStringList files_;
};

}  // namespace armmimic::gui
