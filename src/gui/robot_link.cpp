#include "robot_link.h"

#include "armmimic/serial/serial_link.h"

namespace armmimic::gui {

RobotLink::RobotLink(QObject* parent)
    : QObject(parent), link_(new serial::SerialLink(robot::LinkSettings{}, this)) {
  connect(link_, &serial::SerialLink::progress, this, &RobotLink::progress);
  connect(link_, &serial::SerialLink::lineReceived, this, &RobotLink::received);
  connect(link_, &serial::SerialLink::portError, this, [this](const QString& message) {
    disconnectPort();
    emit error(message);
  });
  connect(link_, &serial::SerialLink::finished, this, [this](bool ok) {
    if (!sending_) return;
    sending_ = false;
    const robot::LinkProtocol& p = link_->protocol();
    const QString source = QString::fromStdString(source_);
    const Status st = session_ ? session_->Finish(p) : Status::Ok();
    if (ok && !st) {
      emit finished(false, QString::fromStdString(st.message()));
    } else if (ok) {
      emit finished(true, QString("%1: sent %2 lines").arg(source).arg(p.total()));
    } else if (aborted_) {
      emit finished(false, QString("%1: aborted by the operator after %2 of %3 lines")
                               .arg(source)
                               .arg(p.acknowledged())
                               .arg(p.total()));
    } else {
      emit finished(false, QString::fromStdString(st ? p.error_message() : st.message()));
    }
  });
}

RobotLink::~RobotLink() { disconnectPort(); }

bool RobotLink::isConnected() const { return link_->is_open(); }
bool RobotLink::isPaused() const { return sending_ && link_->paused(); }
int RobotLink::acknowledged() const { return static_cast<int>(link_->protocol().acknowledged()); }

bool RobotLink::connectPort(const QString& device, int baud) {
  disconnectPort();
  serial::PortSettings port;
  port.port = device.toStdString();
  port.baud = baud;
  const Status st = link_->Open(port);
  if (!st) {
    emit error(QString::fromStdString(st.message()));
    return false;
  }
  device_ = device;
  emit connectedChanged(true, device_);
  return true;
}

void RobotLink::disconnectPort() {
  // A send, or another stream on the link (Mimic live), ends: nothing more is written.
  const robot::LinkState state = link_->protocol().state();
  if (sending_ || (state != robot::LinkState::kIdle && !link_->protocol().finished())) {
    link_->Cancel("the port was closed");
  }
  if (link_->is_open()) {
    link_->Close();
    emit connectedChanged(false, device_);
  }
}

bool RobotLink::send(const robot::ValProgram& program, const robot::ControllerProfile& profile,
                     const robot::JointLimits& limits, const robot::SendStart& start,
                     const std::string& input) {
  if (!link_->is_open()) {
    emit error(tr("not connected: choose a port and connect first"));
    return false;
  }
  if (sending_) return false;
  auto session = std::make_unique<robot::SendSession>();
  Status st = session->Prepare(program, profile, limits,
                               input.empty() ? program.source_name : input, start);
  if (st && session->nothing_to_do()) {
    emit finished(true, tr("%1: already sent completely; nothing to resume")
                            .arg(QString::fromStdString(program.source_name)));
    return true;
  }
  if (st) {
    link_->SetLinkSettings(robot::LinkSettings::FromProfile(profile));
    st = session->Attach(&link_->protocol());
  }
  if (!st) {
    emit error(QString::fromStdString(st.message()));
    return false;
  }
  session_ = std::move(session);
  source_ = program.source_name;
  sending_ = true;
  aborted_ = false;
  const std::vector<robot::LinkLine> lines = session_->lines();
  emit progress(0, static_cast<int>(lines.size()));
  link_->Start(lines, program.source_name);
  return true;
}

void RobotLink::setPaused(bool paused) {
  if (sending_) link_->SetPaused(paused);
}

void RobotLink::abort() {
  if (!sending_) return;
  aborted_ = true;
  link_->Cancel("aborted by the operator");
}

}  // namespace armmimic::gui
