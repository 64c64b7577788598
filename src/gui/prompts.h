// Prompts: the small dialogs the window's commands ask before they act (file names, camera,
// background length). Kept out of MainWindow so it only wires widgets together.
#pragma once

#include <optional>

#include <QString>
#include <QStringList>

class QWidget;

namespace armmimic::gui {

QStringList AskInputs(QWidget* parent, const QString& dir);
// A folder whose images are the views, in name order; "" when cancelled.
QString AskImageFolder(QWidget* parent, const QString& dir);
// "camera:N" for an index, the URL as typed otherwise; nullopt when cancelled.
std::optional<QString> AskCamera(QWidget* parent);
// A file to read; "" when cancelled.
QString AskOpenPath(QWidget* parent, const QString& title, const QString& dir,
                    const QString& filter);
// A file to write; "" when cancelled.
QString AskSavePath(QWidget* parent, const QString& title, const QString& suggested,
                    const QString& filter);
std::optional<int> AskBackgroundFrames(QWidget* parent);
void ShowAbout(QWidget* parent);

}  // namespace armmimic::gui
