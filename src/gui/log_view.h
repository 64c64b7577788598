// LogView: the application's message area. Every message is selectable and copyable; an error
// text is shown once (repeats are counted, not repeated), so a failing step never floods the
// window or opens a storm of modal boxes.
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
  // Shows `text` the first time; later identical errors only bump a counter.
  void error(const QString& text);
  int errorCount() const { return static_cast<int>(errors_.size()); }
  QString text() const;

 signals:
  // A distinct error was shown (not emitted for repeats).
  void errorShown(const QString& text);

 public slots:
  void clear();
  void copyAll();

 private:
  void append(const QString& prefix, const QString& text);
  QPlainTextEdit* edit_;
  QHash<QString, int> errors_;
};

}  // namespace armmimic::gui
