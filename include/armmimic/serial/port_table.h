// The serial port's option table ("port.*", armmimic/core/option_table.h): the device, baud rate,
// data bits, parity, stop bits and flow control that `send`, `mimic` and the robot panel set.
#pragma once

#include <vector>

#include "armmimic/core/option_table.h"
#include "armmimic/serial/serial_link.h"

namespace armmimic::serial {

const std::vector<OptionField<PortSettings>>& PortOptionFields();

}  // namespace armmimic::serial
