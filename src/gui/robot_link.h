// RobotLink: the robot panel's handle on the serial link. A thin adapter over
// serial::SerialLink and robot::SendSession, the same transport and send logic the CLI's send
// uses: the program is checked as a whole, every line is gated through robot::CheckLine right
// before it is written, the link lines carry the same timeouts, the journal (INPUT.journal)
// records every line, and a resume whose last line is uncertain asks the arm (WHERE) first. It
// reports in QString messages. Pause holds the next line back; abort stops after the line in
// flight.
#pragma once

#include <memory>

#include <QObject>
#include <QString>

#include "armmimic/robot/profile.h"
#include "armmimic/robot/send_session.h"
#include "armmimic/robot/val_program.h"
#include "armmimic/serial/serial_link.h"

namespace armmimic::gui {

class RobotLink : public QObject {
  Q_OBJECT
 public:
  explicit RobotLink(QObject* parent = nullptr);
  ~RobotLink() override;

  bool connectPort(const serial::PortSettings& port);
  void disconnectPort();
  bool isConnected() const;
  QString device() const { return device_; }
  // The settings the open port was given (empty port name when not connected).
  const serial::PortSettings& portSettings() const { return port_; }

  // Prepares a send of `program` with `profile` and `limits` (tightened by the program's header
  // limits), as `armmimic-cli send` does: `start` chooses fresh, resume or restart, and the
  // journal is INPUT.journal (`input` defaulting to the program's source name). False, with the
  // message, when the session refuses (the program, the journal). prepared() then tells what
  // would be sent; startPrepared() sends it.
  bool prepare(const robot::ValProgram& program, const robot::ControllerProfile& profile,
               const robot::JointLimits& limits, const robot::SendStart& start,
               const std::string& input, QString* error);
  const robot::SendSession* prepared() const { return session_.get(); }
  // Starts the prepared send (asking the arm WHERE first when the last line of an interrupted
  // send is uncertain). A session with nothing to do finishes at once.
  bool startPrepared();
  // prepare() and startPrepared() in one, reporting a refusal through error().
  bool send(const robot::ValProgram& program, const robot::ControllerProfile& profile,
            const robot::JointLimits& limits, const robot::SendStart& start = NoJournal(),
            const std::string& input = "");
  static robot::SendStart NoJournal() {
    robot::SendStart s;
    s.journal = false;
    return s;
  }
  bool isSending() const { return phase_ != Phase::kIdle; }
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
  void note(const QString& message);   // what the WHERE before a resume found
  void finished(bool ok, const QString& message);
  void error(const QString& message);

 private:
  enum class Phase { kIdle, kAskingWhere, kSending };
  void streamLines();
  void onFinished(bool ok);
  void endSend(bool ok, const QString& message);

  serial::SerialLink* link_;
  QString device_;
  serial::PortSettings port_;
  Phase phase_ = Phase::kIdle;
  bool aborted_ = false;
  bool journaled_ = false;
  robot::ControllerProfile profile_;
  std::unique_ptr<robot::SendSession> session_;
};

}  // namespace armmimic::gui
