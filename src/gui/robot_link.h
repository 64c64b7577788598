// RobotLink: streams VAL lines to a controller over a serial port (QSerialPort, asynchronous:
// readyRead, errorOccurred and a tick timer). The protocol itself (wake, echo, prompt, error
// lines, timeouts) is robot::LinkProtocol; every line passes robot::CheckLine right before it
// is written. Pause holds the next line back; abort stops after the line in flight.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QSerialPort>
#include <QTimer>

#include "armmimic/robot/link_protocol.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::gui {

class RobotLink : public QObject {
  Q_OBJECT
 public:
  explicit RobotLink(QObject* parent = nullptr);
  ~RobotLink() override;

  bool connectPort(const QString& device, int baud);
  void disconnectPort();
  bool isConnected() const { return port_.isOpen(); }
  QString device() const { return port_.portName(); }

  // Sends `program` (already checked as a whole) with `profile` and `limits`.
  bool send(const robot::ValProgram& program, const robot::ControllerProfile& profile,
            const robot::JointLimits& limits);
  bool isSending() const { return sending_; }
  bool isPaused() const { return paused_; }
  void setPaused(bool paused);
  void abort();
  int acknowledged() const { return static_cast<int>(protocol_.acknowledged()); }

 signals:
  void connectedChanged(bool connected, const QString& device);
  void progress(int acknowledged, int total);
  void received(const QString& line);  // each line the controller sent, as is
  void finished(bool ok, const QString& message);
  void error(const QString& message);

 private:
  void onReadyRead();
  void onTick();
  void flush();
  void finish();
  double now() const { return clock_.elapsed() / 1000.0; }

  QSerialPort port_;
  QTimer tick_;
  QElapsedTimer clock_;
  robot::LinkProtocol protocol_;
  robot::SafetyState safety_;
  QByteArray held_;     // bytes received while paused
  QByteArray rx_line_;  // for the reply log
  bool sending_ = false;
  bool paused_ = false;
  bool refused_ = false;
  QString refusal_;
  std::string source_;
  std::vector<int> line_nos_;
};

}  // namespace armmimic::gui
