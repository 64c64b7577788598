#include "log_view.h"

#include <QApplication>
#include <QClipboard>
#include <QDateTime>
#include <QHBoxLayout>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QVBoxLayout>

namespace armmimic::gui {

LogView::LogView(QWidget* parent) : QWidget(parent), edit_(new QPlainTextEdit(this)) {
  edit_->setReadOnly(true);
  edit_->setObjectName("logText");
  edit_->setMaximumBlockCount(5000);
  edit_->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  auto* copy = new QPushButton(tr("Copy all"), this);
  auto* clear_button = new QPushButton(tr("Clear"), this);
  connect(copy, &QPushButton::clicked, this, &LogView::copyAll);
  connect(clear_button, &QPushButton::clicked, this, &LogView::clear);
  auto* buttons = new QHBoxLayout;
  buttons->addStretch();
  buttons->addWidget(copy);
  buttons->addWidget(clear_button);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(edit_);
  layout->addLayout(buttons);
}

void LogView::append(const QString& prefix, const QString& text) {
  const QString stamp = QDateTime::currentDateTime().toString("HH:mm:ss");
  edit_->appendPlainText(stamp + "  " + prefix + text);
}

void LogView::info(const QString& text) { append(QString(), text); }

void LogView::error(const QString& text) {
  const int n = ++errors_[text];
  const QString counted = n > 1 ? QString("%1  (×%2)").arg(text).arg(n) : text;
  const QString previous = n > 2 ? QString("%1  (×%2)").arg(text).arg(n - 1) : text;
  if (n > 1 && lastLineIs(tr("error: ") + previous)) {
    // The same error again: count up on its line instead of adding one.
    QTextCursor c(edit_->document()->lastBlock());
    c.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
    c.insertText(QDateTime::currentDateTime().toString("HH:mm:ss") + "  " + tr("error: ") +
                 counted);
  } else {
    append(tr("error: "), counted);
  }
  emit errorShown(counted);
}

bool LogView::lastLineIs(const QString& line_end) const {
  const QString last = edit_->document()->lastBlock().text();
  // Every line is "HH:mm:ss  " and the message.
  return last.mid(10) == line_end;
}

QString LogView::text() const { return edit_->toPlainText(); }

void LogView::clear() {
  edit_->clear();
  errors_.clear();
}

void LogView::copyAll() { QApplication::clipboard()->setText(edit_->toPlainText()); }

}  // namespace armmimic::gui
