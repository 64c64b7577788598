// The robot panel's send: the program the plan gives, the journal's choices (fresh, resume,
// start over), the confirmation, and the hand-over to RobotLink. Every decision the CLI's `send`
// makes is robot::SendSession's; this file only asks the operator and shows the answers.
// Length: RobotPanel::startSend is the one path from the send button to RobotLink, asking each
// question of SendSession in the order the CLI's send asks it.
#include <sstream>

#include <QFile>
#include <QFileInfo>
#include <QPlainTextEdit>
#include <QPushButton>

#include "armmimic/core/output_file.h"
#include "armmimic/robot/send_setup.h"
#include "armmimic/robot/send_summary.h"
#include "controller_settings.h"
#include "field_error.h"
#include "robot_link.h"
#include "robot_option_keys.h"
#include "robot_panel.h"
#include "robot_words.h"
#include "send_questions.h"

namespace armmimic::gui {

QString RobotPanel::planFile() const {
  if (plan_.fromProgram()) return QString::fromStdString(plan_.angle_path());
  return plan_file_ ? plan_file_() : QString();
}

// A plan is sent as a file, written first beside the session or the video (as `plan` then `send`
// would), so that its journal beside it outlives this process and a restart can resume it. The
// same text already there is kept; other text is replaced only when the operator says so.
bool RobotPanel::writePlanFile(const std::string& text, const QString& path, bool confirmed) {
  QFile existing(path);
  if (existing.exists()) {
    if (existing.open(QIODevice::ReadOnly) && existing.readAll() == QByteArray::fromStdString(text))
      return true;
    if (!confirmed && !AskReplacePlan(this, path)) return false;
  }
  std::vector<NamedPath> inputs = inputs_ ? inputs_() : std::vector<NamedPath>();
  if (!plan_.angle_path().empty()) inputs.push_back({"the angle file", plan_.angle_path()});
  Status st = CheckOutputsAreNotInputs(inputs, {{"the VAL program", path.toStdString()}});
  if (st) st = WriteOutputFile(path.toStdString(), text);
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    return false;
  }
  emit message(tr("Wrote the plan to %1; its journal goes beside it").arg(path));
  return true;
}

bool RobotPanel::programToSend(const robot::ControllerProfile& profile, bool write, bool confirmed,
                               robot::ValProgram* program, std::string* input) {
  std::string text;
  Status st = plan_.ValText(profile, &text);
  const QString path = planFile();
  if (st && path.isEmpty()) {
    st = Status::Error(tr("there is no file to write the plan to: open the video or save the "
                          "session first (the plan and its journal go beside it)")
                           .toStdString());
  }
  if (!st) {
    emit errorOccurred(RobotPanelWords(st));
    return false;
  }
  // A program opened from a file is sent (and journaled) as that file, as `send FILE` does.
  if (write && !plan_.fromProgram() && !writePlanFile(text, path, confirmed)) return false;
  std::istringstream in(text);
  st = robot::ParseValProgram(in, QFileInfo(path).fileName().toStdString(), profile.max_line_length,
                              program);
  if (!st) {
    emit errorOccurred(RobotPanelWords(st));
    return false;
  }
  *input = path.toStdString();
  return true;
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

void RobotPanel::offerResume() {
  resume_offered_ = false;
  const QString path = planFile();
  std::string text;
  if (!plan_.planned() || path.isEmpty() || !plan_.ValText(profile_, &text)) return;
  robot::ValProgram program;
  std::istringstream in(text);
  if (!robot::ParseValProgram(in, QFileInfo(path).fileName().toStdString(),
                              profile_.max_line_length, &program)) {
    return;
  }
  robot::UnfinishedSend u;
  if (!robot::FindUnfinishedSend(program, path.toStdString(), &u) || !u.found) return;
  resume_offered_ = true;
  emit message(tr("An earlier send of %1 stopped after %2 of %3 lines (journal %4): connect and "
                  "click Resume… to continue it")
                   .arg(path)
                   .arg(u.acknowledged)
                   .arg(u.total)
                   .arg(QString::fromStdString(u.journal_path)));
}

bool RobotPanel::sendPlan(bool confirmed) {
  return startSend(robot::SendStart::Mode::kFresh, confirmed);
}

bool RobotPanel::resumeSend(bool confirmed) {
  return startSend(robot::SendStart::Mode::kResume, confirmed);
}

bool RobotPanel::startSend(robot::SendStart::Mode mode, bool confirmed) {
  if (!plan_.planned()) {
    MarkFieldError(RobotOptionField(this, last_plan_failure_key_));  // the field that refused it
    emit errorOccurred(
        last_plan_failure_.isEmpty()
            ? tr("Nothing to send: no plan (run the analysis first)")
            : tr("Nothing to send: the plan was refused: %1").arg(last_plan_failure_));
    return false;
  }
  if (angles_changing_) {
    emit errorOccurred(
        tr("Nothing to send yet: the analysis is replacing the angles shown; the "
           "plan follows once it ends"));
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
  // A resume sends the plan its journal was written for: nothing is written before the checks.
  if (!programToSend(profile, mode == robot::SendStart::Mode::kFresh, confirmed, &program,
                     &input)) {
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
