// SerialLink: the robot link over a QSerialPort (serial_link.h).
// Length: SerialLink::Open checks the path, takes the lock, opens and configures the port in one
// sequence whose every failure undoes the steps before it.
#include "armmimic/serial/serial_link.h"

#include <QSerialPortInfo>
#include <cerrno>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace armmimic::serial {
namespace {

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The paths a port name stands for: a path as it is; a bare name as given (a file in the
// current folder) and under /dev ("ttyUSB0" -> "/dev/ttyUSB0"), in that order.
std::vector<std::string> Candidates(const std::string& port) {
  if (port.find('/') != std::string::npos) return {port};
  return {"./" + port, "/dev/" + port};
}

// "a regular file", "a folder", ... for a path that is no character device.
std::string KindOf(const struct stat& st) {
  if (S_ISREG(st.st_mode)) return "a regular file";
  if (S_ISDIR(st.st_mode)) return "a folder";
  if (S_ISFIFO(st.st_mode)) return "a pipe";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  if (S_ISBLK(st.st_mode)) return "a block device";
  return "not a terminal device";
}

// True when `device` is a terminal (a serial port or a pseudo-terminal). Opened without making
// it the controlling terminal and without waiting for a modem line; closed again at once.
bool IsTerminal(const std::string& device) {
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return true;  // cannot tell: let the open's own error speak
  const bool tty = ::isatty(fd) == 1;
  ::close(fd);
  return tty;
}

}  // namespace

Status PortSettings::Check() const {
  if (port.empty()) return Status::Error("port.port", "no serial port given");
  if (baud <= 0) {
    return Status::Error("port.baud",
                         "the baud rate " + std::to_string(baud) + " must be positive");
  }
  if (data_bits < 5 || data_bits > 8) {
    return Status::Error("port.data_bits",
                         "the data bits " + std::to_string(data_bits) + " must be 5, 6, 7 or 8");
  }
  if (parity != 'N' && parity != 'E' && parity != 'O') {
    return Status::Error("port.parity",
                         std::string("the parity ") + parity + " must be none, even or odd");
  }
  if (stop_bits != 1 && stop_bits != 2) {
    return Status::Error("port.stop_bits",
                         "the stop bits " + std::to_string(stop_bits) + " must be 1 or 2");
  }
  return Status::Ok();
}

std::string ParseFlowControl(const std::string& text, FlowControl* out) {
  const std::string t = Lower(text);
  if (t == "none") {
    *out = FlowControl::kNone;
  } else if (t == "xonxoff" || t == "software") {
    *out = FlowControl::kXonXoff;
  } else if (t == "rtscts" || t == "hardware") {
    *out = FlowControl::kRtsCts;
  } else {
    return "must be none, xonxoff or rtscts";
  }
  return "";
}

std::string ParseParity(const std::string& text, char* out) {
  const std::string t = Lower(text);
  if (t == "none" || t == "n") {
    *out = 'N';
  } else if (t == "even" || t == "e") {
    *out = 'E';
  } else if (t == "odd" || t == "o") {
    *out = 'O';
  } else {
    return "must be none, even or odd";
  }
  return "";
}

const char* FlowControlName(FlowControl flow) {
  switch (flow) {
    case FlowControl::kXonXoff:
      return "xonxoff";
    case FlowControl::kRtsCts:
      return "rtscts";
    case FlowControl::kNone:
      break;
  }
  return "none";
}

std::vector<PortInfo> ListPorts() {
  std::vector<PortInfo> ports;
  for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) {
    PortInfo p;
    p.name = info.portName().toStdString();
    p.system_location = info.systemLocation().toStdString();
    p.description = info.description().toStdString();
    p.manufacturer = info.manufacturer().toStdString();
    p.serial_number = info.serialNumber().toStdString();
    p.has_ids = info.hasVendorIdentifier() && info.hasProductIdentifier();
    p.vendor_id = info.vendorIdentifier();
    p.product_id = info.productIdentifier();
    ports.push_back(p);
  }
  return ports;
}

SerialLink::SerialLink(const robot::LinkSettings& settings, QObject* parent)
    : QObject(parent), port_(new QSerialPort(this)), timer_(new QTimer(this)), protocol_(settings) {
  timer_->setInterval(10);
  connect(port_, &QSerialPort::readyRead, this, [this] { OnReadyRead(); });
  connect(port_, &QSerialPort::errorOccurred, this,
          [this](QSerialPort::SerialPortError e) { OnError(e); });
  connect(timer_, &QTimer::timeout, this, [this] { OnTick(); });
}

SerialLink::~SerialLink() { Close(); }

bool SerialLink::is_open() const { return port_->isOpen(); }

Status SerialLink::Open(const PortSettings& settings) {
  Status s = settings.Check();
  if (!s.ok()) return s;
  settings_ = settings;
  // Errors about the port itself are keyed "port.port" and start with the name as given.
  const std::string flag = settings.port;
  auto error = [](const std::string& message) { return Status::Error("port.port", message); };
  std::string device, tried;
  struct stat st {};
  for (const std::string& candidate : Candidates(settings.port)) {
    tried += (tried.empty() ? "" : " and ") + candidate;
    if (stat(candidate.c_str(), &st) == 0) {
      device = candidate;
      break;
    }
  }
  if (device.empty()) {
    return error(flag + ": no such serial port (tried " + tried +
                 "); the list of serial ports shows the ones found");
  }
  if (!S_ISCHR(st.st_mode)) {
    return error(flag + ": " + device + " is not a serial port (it is " + KindOf(st) + ")");
  }
  if (access(device.c_str(), R_OK | W_OK) != 0 && errno == EACCES) {
    return error(flag + ": permission denied on " + device +
                 " (add your user to the group that owns it, usually 'dialout', and log "
                 "in again)");
  }
  // One program per device, whatever name each gives it; taken before a byte is written.
  if (Status locked = lock_.Acquire(device); !locked) {
    return error(flag + ": " + locked.message());
  }
  // The serial library reads a name without a leading '/' as one under /dev: give it the path.
  std::string absolute = device;
  if (absolute[0] != '/') {
    char cwd[4096];
    if (::getcwd(cwd, sizeof cwd)) absolute = std::string(cwd) + "/" + device;
  }
  port_->setPortName(QString::fromStdString(absolute));
  if (!port_->open(QIODevice::ReadWrite)) {
    lock_.Release();
    const QSerialPort::SerialPortError e = port_->error();
    const std::string qt = port_->errorString().toStdString();
    port_->clearError();
    if (e != QSerialPort::PermissionError && !IsTerminal(device)) {
      return error(flag + ": " + device +
                   " is not a serial port (a character device, but no terminal)");
    }
    if (e == QSerialPort::DeviceNotFoundError) {
      return error(flag + ": no such serial port (" + qt + ")");
    }
    if (e == QSerialPort::PermissionError) {
      return error(flag + ": the port is busy: another program has it open (" + qt + ")");
    }
    return error(flag + ": cannot open the port: " + qt);
  }
  const QSerialPort::Parity parity = settings.parity == 'E'   ? QSerialPort::EvenParity
                                     : settings.parity == 'O' ? QSerialPort::OddParity
                                                              : QSerialPort::NoParity;
  const QSerialPort::FlowControl flow =
      settings.flow == FlowControl::kXonXoff  ? QSerialPort::SoftwareControl
      : settings.flow == FlowControl::kRtsCts ? QSerialPort::HardwareControl
                                              : QSerialPort::NoFlowControl;
  std::string key, refused;  // the setting the port refused, and its value in words
  if (!port_->setBaudRate(settings.baud)) {
    key = "port.baud";
    refused = "the baud rate " + std::to_string(settings.baud);
  }
  if (key.empty() && !port_->setDataBits(static_cast<QSerialPort::DataBits>(settings.data_bits))) {
    key = "port.data_bits";
    refused = "the data bits " + std::to_string(settings.data_bits);
  }
  if (key.empty() && !port_->setParity(parity)) {
    key = "port.parity";
    refused = std::string("the parity ") + settings.parity;
  }
  if (key.empty() &&
      !port_->setStopBits(settings.stop_bits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop)) {
    key = "port.stop_bits";
    refused = "the stop bits " + std::to_string(settings.stop_bits);
  }
  if (key.empty() && !port_->setFlowControl(flow)) {
    key = "port.flow";
    refused = std::string("the flow control ") + FlowControlName(settings.flow);
  }
  if (!key.empty()) {
    const std::string qt = port_->errorString().toStdString();
    port_->close();
    lock_.Release();
    return Status::Error(key, device + " refused " + refused + " (" + qt + ")");
  }
  port_->clear();
  return Status::Ok();
}

void SerialLink::Close() {
  timer_->stop();
  if (port_->isOpen()) {
    port_->flush();
    port_->close();
  }
  lock_.Release();
}

double SerialLink::Now() const {
  const qint64 now = clock_.isValid() ? clock_.nsecsElapsed() : 0;
  const qint64 paused = paused_ns_ + (paused_ ? now - pause_started_ns_ : 0);
  return static_cast<double>(now - paused) * 1e-9;
}

void SerialLink::SetLinkSettings(const robot::LinkSettings& settings) {
  protocol_ = robot::LinkProtocol(settings);
}

void SerialLink::SetPaused(bool paused) {
  if (paused == paused_) return;
  const qint64 now = clock_.isValid() ? clock_.nsecsElapsed() : 0;
  if (paused) {
    pause_started_ns_ = now;
    paused_ = true;
    return;
  }
  paused_ns_ += now - pause_started_ns_;
  paused_ = false;
  if (!held_.isEmpty()) {
    const QByteArray data = held_;
    held_.clear();
    protocol_.OnBytes(std::string_view(data.constData(), static_cast<std::size_t>(data.size())),
                      Now());
  }
  Flush();
}

void SerialLink::Begin(const std::function<void(double now_s)>& start_protocol) {
  clock_.start();
  paused_ = false;
  paused_ns_ = 0;
  held_.clear();
  reported_ = 0;
  finished_sent_ = false;
  start_protocol(Now());
  timer_->start();
  Flush();
}

void SerialLink::Start(std::vector<robot::LinkLine> lines, const std::string& source_name) {
  Begin([&](double now_s) { protocol_.Start(std::move(lines), source_name, now_s); });
}

void SerialLink::StartStream(const std::string& source_name) {
  Begin([&](double now_s) { protocol_.StartStream(source_name, now_s); });
}

void SerialLink::Append(robot::LinkLine line) {
  protocol_.Append(std::move(line), Now());
  Flush();
}

void SerialLink::EndStream() {
  protocol_.EndStream();
  Flush();
}

void SerialLink::Cancel(const std::string& reason) {
  protocol_.Abort(reason);
  Flush();
}

void SerialLink::OnReadyRead() {
  const QByteArray data = port_->readAll();
  for (char c : data) {
    if (c == '\r' || c == '\n') {
      if (!rx_line_.isEmpty()) emit lineReceived(QString::fromLatin1(rx_line_));
      rx_line_.clear();
    } else {
      rx_line_.append(c);
    }
  }
  if (paused_) {
    held_.append(data);
    return;
  }
  if (!data.isEmpty()) {
    protocol_.OnBytes(std::string_view(data.constData(), static_cast<std::size_t>(data.size())),
                      Now());
  }
  Flush();
}

void SerialLink::OnError(QSerialPort::SerialPortError error) {
  if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError) return;
  const std::string qt = port_->errorString().toStdString();
  if (finished_sent_) {
    if (error == QSerialPort::ResourceError) {
      emit portError(QString::fromStdString(settings_.port + ": the connection was lost: " + qt));
    }
    return;
  }
  if (error != QSerialPort::ResourceError && error != QSerialPort::ReadError &&
      error != QSerialPort::WriteError) {
    return;
  }
  // An end of file on the device reads as an error too: the cable, adapter or emulator is gone.
  protocol_.Abort(
      settings_.port + ": the connection was lost (device unplugged, closed or failing): " + qt,
      "port.port");

  Flush();
}

void SerialLink::OnTick() {
  if (paused_) return;
  protocol_.OnTick(Now());
  Flush();
}

void SerialLink::Flush() {
  const std::string out = protocol_.TakeOutput();
  if (!out.empty() && port_->isOpen()) {
    port_->write(out.data(), static_cast<qint64>(out.size()));
  }
  if (protocol_.acknowledged() != reported_) {
    reported_ = protocol_.acknowledged();
    emit progress(static_cast<int>(reported_), static_cast<int>(protocol_.total()));
  }
  if (protocol_.finished() && !finished_sent_) {
    finished_sent_ = true;
    timer_->stop();
    if (port_->isOpen()) port_->waitForBytesWritten(200);
    emit finished(protocol_.state() == robot::LinkState::kDone);
  }
}

}  // namespace armmimic::serial
