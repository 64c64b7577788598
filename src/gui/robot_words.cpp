#include "robot_words.h"

#include <QCoreApplication>

namespace armmimic::gui {

QString RobotPanelLabel(const std::string& key) {
  static const struct {
    const char* key;
    const char* label;
  } kLabels[] = {
      {"port.port", QT_TRANSLATE_NOOP("RobotPanel", "Port")},
      {"port.baud", QT_TRANSLATE_NOOP("RobotPanel", "Baud")},
      {"port.data_bits", QT_TRANSLATE_NOOP("RobotPanel", "Data bits")},
      {"port.parity", QT_TRANSLATE_NOOP("RobotPanel", "Parity")},
      {"port.stop_bits", QT_TRANSLATE_NOOP("RobotPanel", "Stop bits")},
      {"port.flow", QT_TRANSLATE_NOOP("RobotPanel", "Flow control")},
      // The panel resumes with its Resume button and starts over with Send.
      {"send.mode", QT_TRANSLATE_NOOP("RobotPanel", "Resume or Send")},
      {"send.resume", QT_TRANSLATE_NOOP("RobotPanel", "Resume")},
      {"send.resume_at_line", QT_TRANSLATE_NOOP("RobotPanel", "Resume at line")},
      {"limits.min_deg", QT_TRANSLATE_NOOP("RobotPanel", "Limits")},
      {"limits.max_deg", QT_TRANSLATE_NOOP("RobotPanel", "Limits")},
      {"limits.max_speed_deg_s", QT_TRANSLATE_NOOP("RobotPanel", "Limits (speed)")},
  };
  for (const auto& l : kLabels) {
    if (key == l.key) return QCoreApplication::translate("RobotPanel", l.label);
  }
  return QString();
}

QString RobotPanelWords(const std::string& key, const std::string& message) {
  const QString label = RobotPanelLabel(key);
  const QString text = QString::fromStdString(message);
  return label.isEmpty() ? text : label + ": " + text;
}

}  // namespace armmimic::gui
