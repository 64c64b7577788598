// RobotLink: the robot panel's handle on the serial link. A thin adapter over
// serial::SerialLink (the same QSerialPort transport and robot::LinkProtocol the CLI's send
// uses): it turns a checked VAL program into link lines, gates every line through
// robot::CheckLine right before it is written, and reports in QString messages. Pause holds the
// next line back; abort stops after the line in flight.
#pragma once

#include <QObject>
#include <QString>

#include "armmimic/robot/profile.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::serial {
class SerialLink;
}

namespace armmimic::gui {

class RobotLink : public QObject {
  Q_OBJECT
 public:
  explicit RobotLink(QObject* parent = nullptr);
  ~RobotLink() override;

  bool connectPort(const QString& device, int baud);
  void disconnectPort();
  bool isConnected() const;
  QString device() const { return device_; }

  // Sends `program` (already checked as a whole) with `profile` and `limits`.
  bool send(const robot::ValProgram& program, const robot::ControllerProfile& profile,
            const robot::JointLimits& limits);
  bool isSending() const { return sending_; }
  bool isPaused() const;
  void setPaused(bool paused);
  void abort();
  int acknowledged() const;
  // The last send ended because the operator aborted it (not a controller or port fault).
  bool wasAborted() const { return aborted_; }

 signals:
  void connectedChanged(bool connected, const QString& device);
  void progress(int acknowledged, int total);
  void received(const QString& line);  // each line the controller sent, as is
  void finished(bool ok, const QString& message);
  void error(const QString& message);

 private:
  serial::SerialLink* link_;
  QString device_;
  bool sending_ = false;
  bool aborted_ = false;
  std::string source_;
  robot::SafetyState safety_;
};

}  // namespace armmimic::gui
