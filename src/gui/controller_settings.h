// ControllerSettings: the robot panel's Controller tab fields that say how to talk to the
// controller, as `armmimic-cli send` takes them: the port's baud, data bits, parity, stop bits
// and flow control (serial::PortSettings), the controller profile (the built-in one or a file),
// and the two timeouts. It fills the same structs the CLI's flags fill and loads the profile
// through robot::LoadSendProfile, so both shells read a profile file the same way. Its fields are
// saved under the keys of their table rows ("port.baud", "send.prompt_timeout_s"); the names
// earlier versions used are still read.
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

#include "armmimic/robot/profile.h"
#include "armmimic/robot/send_setup.h"
#include "armmimic/serial/serial_link.h"

class QSettings;
namespace Ui {
class RobotPanelForm;
}

namespace armmimic::gui {

class ControllerSettings : public QObject {
  Q_OBJECT
 public:
  ControllerSettings(Ui::RobotPanelForm& ui, QWidget* dialog_parent);

  // The port fields for `device`.
  serial::PortSettings portSettings(const QString& device) const;
  void setPortSettings(const serial::PortSettings& port);
  // The profile file ("" for the built-in one) and the timeouts (0: the profile's).
  robot::SendSettings sendSettings() const;
  // The profile those settings give (read again from its file, so an edited file counts).
  // False, with the message naming file:line, when it cannot be read.
  bool loadProfile(robot::ControllerProfile* profile, QString* error) const;
  // Picks a profile file (added to the list); false, with errorOccurred, when it cannot be read,
  // and the choice stays as it was. "" picks the built-in profile.
  bool setProfileFile(const QString& path);
  // Asks for a profile file.
  void chooseProfileFile();
  // While connected, the port fields cannot change.
  void setPortEditable(bool editable);

  void save(QSettings& settings) const;
  void load(QSettings& settings);

 signals:
  // The profile in use changed (the built-in one, or a file that was read).
  void profileChanged(const robot::ControllerProfile& profile);
  void errorOccurred(const QString& text);

 private:
  void addProfileItem(const QString& path);
  QString shownProfilePath() const;

  Ui::RobotPanelForm& ui_;
  QWidget* dialog_parent_;
  int last_profile_index_ = 0;
};

}  // namespace armmimic::gui
