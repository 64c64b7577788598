// The robot panel's send: the program the plan gives, the journal's choices (fresh, resume,
// start over), the confirmation, and the hand-over to RobotLink. Every decision the CLI's `send`
// makes is robot::SendSession's; this file only asks the operator and shows the answers.
#include <sstream>

#include <QFileInfo>
#include <QPlainTextEdit>
#include <QPushButton>

#include "armmimic/robot/send_setup.h"
#include "armmimic/robot/send_summary.h"
#include "controller_settings.h"
#include "robot_link.h"
#include "robot_panel.h"
#include "robot_words.h"
#include "send_questions.h"

namespace armmimic::gui {

Status RobotPanel::programToSend(const robot::ControllerProfile& profile,
                                 robot::ValProgram* program, std::string* input) const {
  std::string text;
  Status st = plan_.ValText(profile, &text);
  if (!st) return st;
  // A program opened from a file is named (and journaled) as that file, as `send FILE` does; a
  // plan is journaled beside the angle file it was planned from.
  const std::string name =
      plan_.fromProgram()
          ? QFileInfo(QString::fromStdString(plan_.angle_path())).fileName().toStdString()
          : "plan.val";
  std::istringstream in(text);
  st = robot::ParseValProgram(in, name, profile.max_line_length, program);
  *input = plan_.angle_path();
  return st;
}

bool RobotPanel::checkResumable(const robot::ValProgram& program, const std::string& input) {
  robot::UnfinishedSend u;
  const Status st = robot::FindUnfinishedSend(program, input, &u);
  if (!st) {
    emit errorOccurred(tr("Resume: %1").arg(RobotPanelWords(st)));
    return false;
  }
  const QString journal = QString::fromStdString(u.journal_path);
  if (!u.journal_exists) {
    emit errorOccurred(
        tr("Resume: there is no journal %1, so no interrupted send to resume; use Send")
            .arg(journal));
    return false;
  }
  if (!u.same_program) {
    emit errorOccurred(tr("Resume: the journal %1 belongs to a different program (the plan, its "
                          "settings or the controller profile changed since that send), so it "
                          "cannot be resumed; use Send to start from the first line")
                           .arg(journal));
    return false;
  }
  return true;
}

bool RobotPanel::sendPlan(bool confirmed) {
  return startSend(robot::SendStart::Mode::kFresh, confirmed);
}

bool RobotPanel::resumeSend(bool confirmed) {
  return startSend(robot::SendStart::Mode::kResume, confirmed);
}

bool RobotPanel::startSend(robot::SendStart::Mode mode, bool confirmed) {
  if (!plan_.planned()) {
    emit errorOccurred(
        last_plan_failure_.isEmpty()
            ? tr("Nothing to send: no plan (run the analysis first)")
            : tr("Nothing to send: the plan was refused: %1").arg(last_plan_failure_));
    return false;
  }
  if (!link_->isConnected()) {
    emit errorOccurred(tr("Not connected: choose a port and connect first"));
    return false;
  }
  robot::ControllerProfile profile;
  QString why;
  if (!controller_->loadProfile(&profile, &why)) {
    emit errorOccurred(tr("Controller profile: %1").arg(why));
    return false;
  }
  robot::ValProgram program;
  std::string input;
  if (const Status st = programToSend(profile, &program, &input); !st) {
    emit errorOccurred(RobotPanelWords(st));
    return false;
  }
  robot::SendStart start;
  start.mode = mode;
  if (mode == robot::SendStart::Mode::kFresh) {
    robot::UnfinishedSend unfinished;
    if (const Status st = robot::FindUnfinishedSend(program, input, &unfinished); !st) {
      emit errorOccurred(RobotPanelWords(st));
      return false;
    }
    if (unfinished.found && confirmed) {
      emit errorOccurred(tr("An earlier send of %1 stopped after %2 of %3 lines (journal %4): "
                            "Resume continues it; Send asks whether to start over instead")
                             .arg(QString::fromStdString(program.source_name))
                             .arg(unfinished.acknowledged)
                             .arg(unfinished.total)
                             .arg(QString::fromStdString(unfinished.journal_path)));
      return false;
    }
    if (unfinished.found) {
      switch (AskAboutUnfinished(this, unfinished, QString::fromStdString(program.source_name))) {
        case UnfinishedChoice::kCancel:
          return false;
        case UnfinishedChoice::kResume:
          start.mode = robot::SendStart::Mode::kResume;
          break;
        case UnfinishedChoice::kStartOver:
          start.mode = robot::SendStart::Mode::kRestart;
          break;
      }
    }
  }
  if (start.mode == robot::SendStart::Mode::kResume && !checkResumable(program, input)) {
    return false;
  }
  if (!link_->prepare(program, profile, plan_.SendLimits(), start, input, &why)) {
    emit errorOccurred(why);
    return false;
  }
  const robot::SendSession& session = *link_->prepared();
  if (!confirmed && !session.nothing_to_do() &&
      !ConfirmSend(this, robot::SummarizeSend(session), link_->device())) {
    return false;
  }
  replies_->clear();
  const bool ok = link_->startPrepared();
  if (ok && link_->isSending()) {
    emit linkStateChanged(tr("robot: sending to %1").arg(link_->device()));
    emit sendingChanged(true);
  }
  updateButtons();
  return ok;
}

}  // namespace armmimic::gui
