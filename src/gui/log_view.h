// LogView: the application's message area. Every message is selectable and copyable. An error
// is one line, never a modal box: the same error again right after it only counts up on that
// line ("(×3)"), so a failing step never floods the window, yet every attempt shows.
#pragma once

#include <QHash>
#include <QString>
#include <QWidget>

class QPlainTextEdit;

namespace armmimic::gui {

class LogView : public QWidget {
  Q_OBJECT
 public:
  explicit LogView(QWidget* parent = nullptr);

  void info(const QString& text);
  // Shows `text`. A repeat of the last line counts up on it; a repeat after other messages is
  // a new line with its count.
  void error(const QString& text);
  // Distinct error texts shown since the last clear.
  int errorCount() const { return static_cast<int>(errors_.size()); }
  // How often `text` was reported since the last clear.
  int repeats(const QString& text) const { return errors_.value(text); }
  QString text() const;

 signals:
  // An error was reported: `text`, with "(×N)" from its second time on.
  void errorShown(const QString& text);

 public slots:
  void clear();
  void copyAll();

 private:
  void append(const QString& prefix, const QString& text);
  bool lastLineIs(const QString& line_end) const;
  QPlainTextEdit* edit_;
  QHash<QString, int> errors_;
};

}  // namespace armmimic::gui
