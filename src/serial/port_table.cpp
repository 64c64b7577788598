// The serial port's settings, one row each (port_table.h); defaults are PortSettings' own.
#include "armmimic/serial/port_table.h"

#include <string>

#include "armmimic/core/option_rows.h"

namespace armmimic::serial {
namespace {

using namespace option_rows;  // NOLINT(google-build-using-namespace): the row builders
using S = PortSettings;

std::string ParityName(char parity) {
  return parity == 'E' ? "even" : parity == 'O' ? "odd" : "none";
}

}  // namespace

const std::vector<OptionField<PortSettings>>& PortOptionFields() {
  static const std::vector<OptionField<S>> fields = {
      Text<S>(
          "port", "", [](const S& o) { return o.port; },
          [](const std::string& text, S* o) {
            o->port = text;
            return std::string();
          },
          "Port", "serial port, e.g. /dev/ttyUSB0; a bare name is tried as ./NAME, then /dev/NAME")
          .Flag("--port")
          .Main(),
      Int<S>("baud", &S::baud, 9600, 1, 4000000, "Baud rate", "baud rate").Flag("--baud").Main(),
      Int<S>("data_bits", &S::data_bits, 8, 5, 8, "Data bits", "data bits 5..8")
          .Flag("--data-bits"),
      Text<S>(
          "parity", "none", [](const S& o) { return ParityName(o.parity); },
          [](const std::string& text, S* o) { return ParseParity(text, &o->parity); }, "Parity",
          "none, even or odd")
          .Flag("--parity"),
      Int<S>("stop_bits", &S::stop_bits, 1, 1, 2, "Stop bits", "stop bits 1 or 2")
          .Flag("--stop-bits"),
      Enum<S>("flow", &S::flow, FlowControl::kNone, {"none", "xonxoff", "rtscts"}, "Flow control",
              "flow control: none, xonxoff or rtscts")
          .Flag("--flow"),
  };
  return fields;
}

}  // namespace armmimic::serial
