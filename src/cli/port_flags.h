// The serial port flags `send` and `mimic` share: --port, --baud, --data-bits, --parity,
// --stop-bits and --flow, parsed into serial::PortSettings.
#pragma once

#include "args.h"
#include "armmimic/serial/serial_link.h"

namespace armmimic::cli {

void AddPortFlags(ArgParser& p, serial::PortSettings* port);

}  // namespace armmimic::cli
