#include "recent_files.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace armmimic::gui {

constexpr int kMaxRecent = 10;

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu) {
  files_ = QSettings().value("recentFiles").toStringList();
  rebuild();
}

void RecentFiles::add(const QString& path) {
  files_.removeAll(path);
  files_.prepend(path);
  while (files_.size() > kMaxRecent) files_.removeLast();
  QSettings().setValue("recentFiles", files_);
  rebuild();
}

void RecentFiles::addInput(const QString& input) {
  if (input.startsWith("camera:") || input.contains("://")) return;
  add(input);
  rememberDir(input);
}

QString RecentFiles::lastDir() { return QSettings().value("lastDir").toString(); }

void RecentFiles::rememberDir(const QString& path) {
  QSettings().setValue("lastDir", QFileInfo(path).absolutePath());
}

void RecentFiles::rebuild() {
  menu_->clear();
  for (int i = 0; i < files_.size(); ++i) {
    const QString path = files_[i];
    QAction* a = menu_->addAction(QString("&%1 %2")
                                      .arg((i + 1) % 10)
                                      .arg(QDir::toNativeSeparators(QFileInfo(path).fileName())));
    a->setToolTip(path);
    a->setStatusTip(path);
    connect(a, &QAction::triggered, this, [this, path] { emit openRequested(path); });
  }
  menu_->setEnabled(!files_.isEmpty());
  if (!files_.isEmpty()) {
    menu_->addSeparator();
    menu_->addAction(tr("Clear list"), this, [this] {
      files_.clear();
      QSettings().setValue("recentFiles", files_);
      rebuild();
    });
  }
}

}  // namespace armmimic::gui
