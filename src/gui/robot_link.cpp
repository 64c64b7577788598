#include "robot_link.h"

namespace armmimic::gui {

RobotLink::RobotLink(QObject* parent) : QObject(parent) {
  clock_.start();
  tick_.setInterval(20);
  connect(&tick_, &QTimer::timeout, this, &RobotLink::onTick);
  connect(&port_, &QSerialPort::readyRead, this, &RobotLink::onReadyRead);
  connect(&port_, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
    if (e == QSerialPort::NoError) return;
    const QString msg = QString("%1: %2").arg(port_.portName(), port_.errorString());
    if (sending_) protocol_.Abort(msg.toStdString());
    if (e == QSerialPort::ResourceError) disconnectPort();
    emit error(msg);
    if (sending_) finish();
  });
}

RobotLink::~RobotLink() { disconnectPort(); }

bool RobotLink::connectPort(const QString& device, int baud) {
  disconnectPort();
  port_.setPortName(device);
  if (!port_.open(QIODevice::ReadWrite)) {
    emit error(QString("%1: cannot open: %2").arg(device, port_.errorString()));
    return false;
  }
  port_.setBaudRate(baud);
  port_.setDataBits(QSerialPort::Data8);
  port_.setParity(QSerialPort::NoParity);
  port_.setStopBits(QSerialPort::OneStop);
  port_.setFlowControl(QSerialPort::NoFlowControl);
  emit connectedChanged(true, device);
  return true;
}

void RobotLink::disconnectPort() {
  if (sending_) {
    protocol_.Abort("the port was closed");
    finish();
  }
  if (port_.isOpen()) {
    port_.close();
    emit connectedChanged(false, port_.portName());
  }
}

bool RobotLink::send(const robot::ValProgram& program, const robot::ControllerProfile& profile,
                     const robot::JointLimits& limits) {
  if (!port_.isOpen()) {
    emit error("not connected: choose a port and connect first");
    return false;
  }
  if (sending_) return false;
  std::vector<robot::LinkLine> lines;
  line_nos_.clear();
  for (const robot::ValLine& l : program.lines) {
    robot::LinkLine line;
    line.text = l.text;
    line.line_no = l.line_no;
    line.index = static_cast<int>(lines.size());
    line.timeout_s =
        robot::IsMotionLine(l.text) ? profile.motion_timeout_s : profile.prompt_timeout_s;
    lines.push_back(line);
  }
  safety_ = robot::SafetyState::For(limits, profile);
  protocol_ = robot::LinkProtocol(robot::LinkSettings::FromProfile(profile));
  refused_ = false;
  refusal_.clear();
  source_ = program.source_name;
  // The last check before the port: a line the checker refuses is never written.
  protocol_.SetSentCallback([this, program](const robot::LinkLine& line) {
    const double t = line.index < static_cast<int>(program.lines.size())
                         ? program.lines[line.index].time_s
                         : kNaN;
    const Status st = robot::CheckLine(line.text, t, safety_);
    if (!st && !refused_) {
      refused_ = true;
      refusal_ = QString("%1:%2: refused: %3")
                     .arg(QString::fromStdString(source_))
                     .arg(line.line_no)
                     .arg(QString::fromStdString(st.message()));
    }
  });
  sending_ = true;
  paused_ = false;
  held_.clear();
  protocol_.Start(std::move(lines), program.source_name, now());
  flush();
  tick_.start();
  emit progress(0, static_cast<int>(protocol_.total()));
  return true;
}

void RobotLink::flush() {
  std::string out = protocol_.TakeOutput();
  if (refused_) {
    protocol_.Abort(refusal_.toStdString());
    finish();
    return;
  }
  if (!out.empty()) port_.write(out.data(), static_cast<qint64>(out.size()));
  emit progress(static_cast<int>(protocol_.acknowledged()), static_cast<int>(protocol_.total()));
  if (protocol_.finished()) finish();
}

void RobotLink::onReadyRead() {
  const QByteArray data = port_.readAll();
  for (char c : data) {
    if (c == '\r' || c == '\n') {
      if (!rx_line_.isEmpty()) emit received(QString::fromLatin1(rx_line_));
      rx_line_.clear();
    } else {
      rx_line_.append(c);
    }
  }
  if (!sending_) return;
  if (paused_) {
    held_.append(data);
    return;
  }
  protocol_.OnBytes(std::string_view(data.constData(), data.size()), now());
  flush();
}

void RobotLink::onTick() {
  if (!sending_ || paused_) return;
  protocol_.OnTick(now());
  flush();
}

void RobotLink::setPaused(bool paused) {
  if (!sending_ || paused == paused_) return;
  paused_ = paused;
  if (!paused_ && !held_.isEmpty()) {
    const QByteArray data = held_;
    held_.clear();
    protocol_.OnBytes(std::string_view(data.constData(), data.size()), now());
    flush();
  }
}

void RobotLink::abort() {
  if (!sending_) return;
  protocol_.Abort("aborted by the operator");
  finish();
}

void RobotLink::finish() {
  if (!sending_) return;
  sending_ = false;
  paused_ = false;
  tick_.stop();
  const bool ok = protocol_.state() == robot::LinkState::kDone;
  const QString msg =
      ok ? QString("%1: sent %2 lines").arg(QString::fromStdString(source_)).arg(protocol_.total())
         : QString::fromStdString(protocol_.error_message());
  emit progress(static_cast<int>(protocol_.acknowledged()), static_cast<int>(protocol_.total()));
  emit finished(ok, msg);
}

}  // namespace armmimic::gui
