// RunToEnd: drives a SerialLink over a list of lines in a local Qt event loop until the protocol
// has finished: the blocking form the command-line tools use (send; mimic's wake-up and WHERE).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "armmimic/robot/link_protocol.h"
#include "armmimic/serial/serial_link.h"

namespace armmimic::serial {

// Returns true when every line was acknowledged. `interrupted` (may be empty) is asked every
// 50 ms; when it returns a reason ("interrupted (Ctrl-C)"), the stream is cancelled with it.
bool RunToEnd(SerialLink& link, std::vector<robot::LinkLine> lines, const std::string& source,
              const std::function<std::string()>& interrupted);

}  // namespace armmimic::serial
