// The robot panel's words for an error the robot and serial layers key by setting
// (Status::key()): "Data bits: ...", "Resume at line: ..." instead of a command-line flag.
#pragma once

#include <QString>
#include <string>

#include "armmimic/core/status.h"

namespace armmimic::gui {

// The panel's label for the setting `key` ("port.data_bits" -> "Data bits"), or "".
QString RobotPanelLabel(const std::string& key);

// "<label>: <message>" when the key has a label in the panel, else the message alone.
QString RobotPanelWords(const std::string& key, const std::string& message);
inline QString RobotPanelWords(const Status& status) {
  return RobotPanelWords(status.key(), status.message());
}

}  // namespace armmimic::gui
