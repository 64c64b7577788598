// RecentFiles: the "Open recent" menu, remembered in QSettings.
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
  QStringList files() const { return files_; }

 signals:
  void openRequested(const QString& path);

 private:
  void rebuild();
  QMenu* menu_;
  QStringList files_;
};

}  // namespace armmimic::gui
