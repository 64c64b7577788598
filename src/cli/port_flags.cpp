#include "port_flags.h"

#include "armmimic/serial/port_table.h"

namespace armmimic::cli {

void AddPortFlags(ArgParser& p, serial::PortSettings* port) {
  p.String("--port", &port->port, "DEVICE",
           "serial port, e.g. /dev/ttyUSB0; a bare name is tried as ./NAME, then /dev/NAME");
  p.Int("--baud", &port->baud, "N", "baud rate (default 9600)", 1, 4000000);
  p.Int("--data-bits", &port->data_bits, "N", "data bits 5..8 (default 8)", 5, 8);
  p.Custom("--parity", "P", "none, even or odd (default none)",
           [port](const std::string& v) { return serial::ParseParity(v, &port->parity); });
  p.Int("--stop-bits", &port->stop_bits, "N", "stop bits 1 or 2 (default 1)", 1, 2);
  p.Custom("--flow", "MODE", "flow control: none, xonxoff or rtscts (default none)",
           [port](const std::string& v) { return serial::ParseFlowControl(v, &port->flow); });
  for (const auto& f : serial::PortOptionFields()) p.BindKey("port." + f.key, f.flag);
}

}  // namespace armmimic::cli
