#include "send_questions.h"

#include <QMessageBox>
#include <QPushButton>

namespace armmimic::gui {

QString SendQuestion(const robot::SendSummary& s, const QString& device) {
  if (!s.resumed_at.empty()) {
    return QObject::tr(
               "Resume at %1: send the %2 of %3 lines still to send to %4? The arm will "
               "move as follows:")
        .arg(QString::fromStdString(s.resumed_at))
        .arg(s.remaining_lines)
        .arg(s.total_lines)
        .arg(device);
  }
  return QObject::tr("Send %1 lines to %2? The arm will move as follows:").arg(s.lines).arg(device);
}

QString SendDetails(const robot::SendSummary& summary) {
  return QString::fromStdString(robot::FormatSendSummary(summary));
}

bool ConfirmSend(QWidget* parent, const robot::SendSummary& summary, const QString& device) {
  QMessageBox box(QMessageBox::Warning, QObject::tr("Move the robot?"),
                  SendQuestion(summary, device), QMessageBox::Cancel, parent);
  box.setObjectName("sendConfirmation");
  box.setInformativeText("<pre>" + SendDetails(summary).toHtmlEscaped() + "</pre>");
  QPushButton* move = box.addButton(QObject::tr("Move the robot"), QMessageBox::AcceptRole);
  box.setDefaultButton(QMessageBox::Cancel);
  box.exec();
  return box.clickedButton() == static_cast<QAbstractButton*>(move);
}

bool AskReplacePlan(QWidget* parent, const QString& path) {
  QMessageBox box(QMessageBox::Question, QObject::tr("Replace the plan file?"),
                  QObject::tr("%1 holds a different plan.").arg(path), QMessageBox::Cancel, parent);
  box.setObjectName("replacePlan");
  box.setInformativeText(QObject::tr(
      "The send writes the plan it sends to this file and keeps its journal beside it. Replace "
      "it with the plan shown? (An unfinished send of the old plan can then no longer be "
      "resumed.)"));
  QPushButton* replace = box.addButton(QObject::tr("Replace"), QMessageBox::AcceptRole);
  box.setDefaultButton(QMessageBox::Cancel);
  box.exec();
  return box.clickedButton() == static_cast<QAbstractButton*>(replace);
}

UnfinishedChoice AskAboutUnfinished(QWidget* parent, const robot::UnfinishedSend& unfinished,
                                    const QString& program) {
  QMessageBox box(QMessageBox::Question, QObject::tr("Resume the interrupted send?"),
                  QObject::tr("An earlier send of %1 stopped after %2 of %3 lines (journal %4).")
                      .arg(program)
                      .arg(unfinished.acknowledged)
                      .arg(unfinished.total)
                      .arg(QString::fromStdString(unfinished.journal_path)),
                  QMessageBox::Cancel, parent);
  box.setObjectName("unfinishedSend");
  box.setInformativeText(
      QObject::tr("Resume continues after the last acknowledged line (asking the arm whether the "
                  "line in flight ran). Start over sends every line again, repeating the moves "
                  "already made. If that send is still running elsewhere, let it end first."));
  QPushButton* resume = box.addButton(QObject::tr("Resume"), QMessageBox::AcceptRole);
  QPushButton* over = box.addButton(QObject::tr("Start over"), QMessageBox::DestructiveRole);
  box.setDefaultButton(QMessageBox::Cancel);
  box.exec();
  if (box.clickedButton() == static_cast<QAbstractButton*>(resume)) {
    return UnfinishedChoice::kResume;
  }
  if (box.clickedButton() == static_cast<QAbstractButton*>(over)) {
    return UnfinishedChoice::kStartOver;
  }
  return UnfinishedChoice::kCancel;
}

}  // namespace armmimic::gui
