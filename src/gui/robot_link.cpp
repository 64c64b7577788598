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
    if (ok) {
      emit finished(true, QString("%1: sent %2 lines").arg(source).arg(p.total()));
    } else if (aborted_) {
      emit finished(false, QString("%1: aborted by the operator after %2 of %3 lines")
                               .arg(source)
                               .arg(p.acknowledged())
                               .arg(p.total()));
    } else {
      emit finished(false, QString::fromStdString(p.error_message()));
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
  if (sending_) link_->Cancel("the port was closed");
  if (link_->is_open()) {
    link_->Close();
    emit connectedChanged(false, device_);
  }
}

bool RobotLink::send(const robot::ValProgram& program, const robot::ControllerProfile& profile,
                     const robot::JointLimits& limits) {
  if (!link_->is_open()) {
    emit error(tr("not connected: choose a port and connect first"));
    return false;
  }
  if (sending_) return false;
  std::vector<robot::LinkLine> lines;
  std::vector<double> times_s;
  for (const robot::ValLine& l : program.lines) {
    robot::LinkLine line;
    line.text = l.text;
    line.line_no = l.line_no;
    line.index = static_cast<int>(lines.size());
    line.timeout_s =
        robot::IsMotionLine(l.text) ? profile.motion_timeout_s : profile.prompt_timeout_s;
    lines.push_back(line);
    times_s.push_back(l.time_s);
  }
  link_->SetLinkSettings(robot::LinkSettings::FromProfile(profile));
  safety_ = robot::SafetyState::For(limits, profile);
  source_ = program.source_name;
  // The last check before the port: a line the checker refuses is never written.
  link_->protocol().SetGate([this, times_s](const robot::LinkLine& line) -> std::string {
    const double t = line.index < static_cast<int>(times_s.size()) ? times_s[line.index] : kNaN;
    const Status st = robot::CheckLine(line.text, t, safety_);
    return st ? std::string() : st.message();
  });
  sending_ = true;
  aborted_ = false;
  emit progress(0, static_cast<int>(lines.size()));
  link_->Start(std::move(lines), program.source_name);
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
