// SerialLink: the robot link over a real serial port (QSerialPort), driving the transport-free
// LinkProtocol from Qt's event loop. Usable from the CLI's QCoreApplication and from the GUI
// (connect to progress()/finished(); the protocol's callbacks run on the link's thread).
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QSerialPort>
#include <QTimer>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "armmimic/core/status.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/serial/port_lock.h"

namespace armmimic::serial {

enum class FlowControl { kNone, kXonXoff, kRtsCts };

struct PortSettings {
  std::string port;  // "/dev/ttyUSB0" or "ttyUSB0"
  int baud = 9600;
  int data_bits = 8;  // 5..8
  char parity = 'N';  // N (none), E (even), O (odd)
  int stop_bits = 1;  // 1 or 2
  FlowControl flow = FlowControl::kNone;
  // The error is keyed by the setting ("port.data_bits"); each shell names it in its words.
  Status Check() const;
};

// Flag parsers: "none|xonxoff|rtscts", "none|even|odd" (or N/E/O). Return an error text or "".
std::string ParseFlowControl(const std::string& text, FlowControl* out);
std::string ParseParity(const std::string& text, char* out);
const char* FlowControlName(FlowControl flow);

struct PortInfo {
  std::string name;             // "ttyUSB0"
  std::string system_location;  // "/dev/ttyUSB0"
  std::string description;
  std::string manufacturer;
  std::string serial_number;
  bool has_ids = false;
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
};
std::vector<PortInfo> ListPorts();

class SerialLink : public QObject {
  Q_OBJECT

 public:
  explicit SerialLink(const robot::LinkSettings& settings, QObject* parent = nullptr);
  ~SerialLink() override;

  // Opens and configures the port. Clear messages for a missing port, permission denied, a
  // port another program holds, or settings the port refuses; each names the port or flag.
  Status Open(const PortSettings& settings);
  void Close();
  bool is_open() const;
  // The open port's file descriptor (-1 when closed), to read back what the device was given.
  qintptr native_handle() const { return port_->handle(); }

  // Wakes the controller and streams `lines`. progress() follows each acknowledgement;
  // finished() comes once, when the protocol is done, failed or was cancelled.
  void Start(std::vector<robot::LinkLine> lines, const std::string& source_name);
  // An open-ended stream (LinkProtocol::StartStream): lines given to Append() go out one at a
  // time as each is acknowledged; EndStream() lets finished() come after the last one.
  void StartStream(const std::string& source_name);
  void Append(robot::LinkLine line);
  void EndStream();
  // Seconds on the protocol's clock (since Start/StartStream), as the protocol sees them.
  double now_s() const { return Now(); }
  // Stops the stream (kAborted) with `reason`; nothing more is written.
  void Cancel(const std::string& reason);
  // Replaces the protocol (prompt, terminator, timeouts) for the next Start(). The protocol's
  // callbacks are reset too: set them after this call.
  void SetLinkSettings(const robot::LinkSettings& settings);
  // Pause holds back what the controller sends, so the next line waits; the protocol's clock
  // stands still meanwhile (a pause is no timeout). Resuming feeds what arrived.
  void SetPaused(bool paused);
  bool paused() const { return paused_; }

  // For callbacks (safety gate, journal) and results. Set callbacks before Start().
  robot::LinkProtocol& protocol() { return protocol_; }
  const robot::LinkProtocol& protocol() const { return protocol_; }

 signals:
  void progress(int acknowledged, int total);
  void finished(bool ok);
  // Each non-empty line the controller sent, as received (for a reply log).
  void lineReceived(const QString& line);
  // The port failed while no stream was running (a stream fails through finished() instead).
  void portError(const QString& message);

 private:
  // Resets the clock, the pause and the reports, then starts the protocol at the new time.
  void Begin(const std::function<void(double now_s)>& start_protocol);
  void OnReadyRead();
  void OnError(QSerialPort::SerialPortError error);
  void OnTick();
  void Flush();
  double Now() const;

  QSerialPort* port_;
  PortLock lock_;  // held from Open() to Close()
  QTimer* timer_;
  QElapsedTimer clock_;
  robot::LinkProtocol protocol_;
  PortSettings settings_;
  std::size_t reported_ = 0;
  bool finished_sent_ = true;
  bool paused_ = false;
  QByteArray held_;       // received while paused
  QByteArray rx_line_;    // the reply line being assembled for lineReceived()
  qint64 paused_ns_ = 0;  // time spent paused, not seen by the protocol
  qint64 pause_started_ns_ = 0;
};

}  // namespace armmimic::serial
