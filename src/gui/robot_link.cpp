#include "robot_link.h"

#include "robot_words.h"

namespace armmimic::gui {

RobotLink::RobotLink(QObject* parent)
    : QObject(parent), link_(new serial::SerialLink(robot::LinkSettings{}, this)) {
  connect(link_, &serial::SerialLink::progress, this, [this](int done, int total) {
    if (phase_ == Phase::kSending) emit progress(done, total);
  });
  connect(link_, &serial::SerialLink::lineReceived, this, &RobotLink::received);
  connect(link_, &serial::SerialLink::portError, this, [this](const QString& message) {
    disconnectPort();
    emit error(message);
  });
  connect(link_, &serial::SerialLink::finished, this, &RobotLink::onFinished);
}

RobotLink::~RobotLink() { disconnectPort(); }

bool RobotLink::isConnected() const { return link_->is_open(); }
bool RobotLink::isPaused() const { return isSending() && link_->paused(); }
int RobotLink::acknowledged() const { return static_cast<int>(link_->protocol().acknowledged()); }

bool RobotLink::connectPort(const serial::PortSettings& port) {
  disconnectPort();
  const Status st = link_->Open(port);
  if (!st) {
    emit error(RobotPanelWords(st));
    return false;
  }
  port_ = port;
  device_ = QString::fromStdString(port.port);
  emit connectedChanged(true, device_);
  return true;
}

void RobotLink::disconnectPort() {
  // A send, or another stream on the link (Mimic live), ends: nothing more is written.
  const robot::LinkState state = link_->protocol().state();
  if (isSending() || (state != robot::LinkState::kIdle && !link_->protocol().finished())) {
    link_->Cancel("the port was closed");
  }
  if (link_->is_open()) {
    link_->Close();
    port_ = serial::PortSettings();
    port_.port.clear();
    emit connectedChanged(false, device_);
  }
}

bool RobotLink::prepare(const robot::ValProgram& program, const robot::ControllerProfile& profile,
                        const robot::JointLimits& limits, const robot::SendStart& start,
                        const std::string& input, QString* error) {
  if (isSending()) {
    if (error) *error = tr("a send is already running");
    return false;
  }
  auto session = std::make_unique<robot::SendSession>();
  const Status st = session->Prepare(program, profile, limits,
                                     input.empty() ? program.source_name : input, start);
  if (!st) {
    session_.reset();
    if (error) *error = RobotPanelWords(st);
    return false;
  }
  session_ = std::move(session);
  profile_ = profile;
  journaled_ = start.journal;
  return true;
}

bool RobotLink::startPrepared() {
  if (!session_) return false;
  if (!link_->is_open()) {
    emit error(tr("not connected: choose a port and connect first"));
    return false;
  }
  if (isSending()) return false;
  const QString source = QString::fromStdString(session_->program().source_name);
  aborted_ = false;
  if (session_->nothing_to_do()) {
    emit finished(true, tr("%1: already sent completely; nothing to resume").arg(source));
    return true;
  }
  bool ask = false;
  robot::LinkLine query;
  const Status st = session_->UncertainQuery(&ask, &query);
  if (!st) {
    emit error(RobotPanelWords(st));
    return false;
  }
  link_->SetLinkSettings(robot::LinkSettings::FromProfile(profile_));
  emit progress(0, static_cast<int>(session_->lines().size()));
  if (ask) {
    phase_ = Phase::kAskingWhere;
    link_->Start({query}, session_->program().source_name);
    return true;
  }
  phase_ = Phase::kSending;
  streamLines();
  return isSending();
}

void RobotLink::streamLines() {
  const Status st = session_->Attach(&link_->protocol());
  if (!st) {
    endSend(false, RobotPanelWords(st));
    return;
  }
  phase_ = Phase::kSending;
  link_->Start(session_->lines(), session_->program().source_name);
}

void RobotLink::onFinished(bool ok) {
  if (!isSending() || !session_) return;
  const robot::LinkProtocol& p = link_->protocol();
  const QString source = QString::fromStdString(session_->program().source_name);
  if (phase_ == Phase::kAskingWhere) {
    if (!ok) {
      endSend(false,
              RobotPanelWords(p.error_key(), p.error_message()) + tr(" (while asking WHERE)"));
      return;
    }
    std::string found;
    const Status st = session_->ResolveUncertain(p.last_replies(), &found);
    if (!st) {
      endSend(false, RobotPanelWords(st));
      return;
    }
    emit note(QString::fromStdString(found));
    link_->SetLinkSettings(robot::LinkSettings::FromProfile(profile_));
    streamLines();
    return;
  }
  const Status st = session_->Finish(p);
  if (ok && st) {
    const QString resumed = QString::fromStdString(session_->ResumedAt());
    endSend(true, tr("%1: sent %2 lines%3")
                      .arg(source)
                      .arg(p.total())
                      .arg(resumed.isEmpty() ? QString() : tr(" (resumed at %1)").arg(resumed)));
    return;
  }
  QString message = aborted_ ? tr("%1: aborted by the operator after %2 of %3 lines")
                                   .arg(source)
                                   .arg(p.acknowledged())
                                   .arg(p.total())
                             : RobotPanelWords(st);
  if (journaled_ && p.acknowledged() < p.total()) {
    message += tr(". The journal %1 records how far it got: Resume continues after the last "
                  "acknowledged line%2")
                   .arg(QString::fromStdString(session_->journal_path()))
                   .arg(session_->MotionWasInFlight(p) ? tr(" (it asks the arm whether the line in "
                                                            "flight ran)")
                                                       : QString());
  }
  endSend(false, message);
}

void RobotLink::endSend(bool ok, const QString& message) {
  phase_ = Phase::kIdle;
  emit finished(ok, message);
}

bool RobotLink::send(const robot::ValProgram& program, const robot::ControllerProfile& profile,
                     const robot::JointLimits& limits, const robot::SendStart& start,
                     const std::string& input) {
  if (!link_->is_open()) {
    emit error(tr("not connected: choose a port and connect first"));
    return false;
  }
  QString why;
  if (!prepare(program, profile, limits, start, input, &why)) {
    emit error(why);
    return false;
  }
  return startPrepared();
}

void RobotLink::setPaused(bool paused) {
  if (isSending()) link_->SetPaused(paused);
}

void RobotLink::abort() {
  if (!isSending()) return;
  aborted_ = true;
  link_->Cancel("aborted by the operator");
}

}  // namespace armmimic::gui
