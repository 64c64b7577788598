// RobotLink: the robot panel's handle on the serial link. A thin adapter over
// serial::SerialLink and robot::SendSession, the same transport and send logic the CLI's send
// uses: the program is checked as a whole, every line is gated through robot::CheckLine right
// before it is written, and the link lines carry the same timeouts. It reports in QString
// messages. Pause holds the next line back; abort stops after the line in flight.
#pragma once

#include <memory>

#include <QObject>
#include <QString>

#include "armmimic/robot/profile.h"
#include "armmimic/robot/send_session.h"
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

  // Sends `program` with `profile` and `limits` (tightened by the program's header limits),
  // as `armmimic-cli send` does. `start` chooses the journal and resume behaviour (default:
  // from the first line, no journal); the journal is INPUT.journal, `input` defaulting to the
  // program's source name. A resume whose last line is uncertain needs the WHERE step first
  // (robot::SendSession::UncertainQuery / ResolveUncertain), as the CLI does.
  bool send(const robot::ValProgram& program, const robot::ControllerProfile& profile,
            const robot::JointLimits& limits, const robot::SendStart& start = NoJournal(),
            const std::string& input = "");
  static robot::SendStart NoJournal() {
    robot::SendStart s;
    s.journal = false;
    return s;
  }
  bool isSending() const { return sending_; }
  bool isPaused() const;
  void setPaused(bool paused);
  void abort();
  int acknowledged() const;
  // The last send ended because the operator aborted it (not a controller or port fault).
  bool wasAborted() const { return aborted_; }
  // The transport, for other streams over the same connection (live mimicking). Not while
  // isSending().
  serial::SerialLink* serialLink() const { return link_; }

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
  std::unique_ptr<robot::SendSession> session_;
};

}  // namespace armmimic::gui
