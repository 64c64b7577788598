#include "controller_settings.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QPushButton>
#include <QSettings>

#include "armmimic/robot/option_tables.h"
#include "armmimic/serial/port_table.h"
#include "recent_files.h"
#include "ui_robot_panel.h"

namespace armmimic::gui {
namespace {

// The profiles installed with the documentation (docs/profiles/ in the source tree).
QStringList InstalledProfiles() {
  QStringList found;
  const QString app = QCoreApplication::applicationDirPath();
  for (const QString& dir : {app + "/../share/doc/armmimic/profiles", app + "/../docs/profiles"}) {
    for (const QFileInfo& f : QDir(dir).entryInfoList({"*.profile"}, QDir::Files, QDir::Name)) {
      found << f.canonicalFilePath();
    }
  }
  found.removeDuplicates();
  return found;
}

// The names earlier versions saved the port's line settings and the send settings under; they
// are still read, and dropped on the next save.
constexpr const char* kLegacyKeys[] = {"baud", "dataBits", "parity",        "stopBits",
                                       "flow", "profile",  "promptTimeout", "motionTimeout"};

// A saved value as text (an INI file reads a value with commas back as a list).
std::string SavedText(const QVariant& v) {
  return (v.typeId() == QMetaType::QStringList ? v.toStringList().join(',') : v.toString())
      .toStdString();
}

// Reads the rows of `fields` saved under "TABLE.KEY" into `o`; `skip` names a row saved
// elsewhere. An unreadable value (a hand-edited file) keeps the setting as it is.
template <typename O>
void LoadRows(QSettings& s, const std::vector<OptionField<O>>& fields, const std::string& table,
              const std::string& skip, O* o) {
  for (const OptionField<O>& row : fields) {
    const std::string key = table + "." + row.key;
    if (row.key == skip || !s.contains(QString::fromStdString(key))) continue;
    SetOptionText(row, key, SavedText(s.value(QString::fromStdString(key))), o);
  }
}

template <typename O>
void SaveRows(QSettings& s, const std::vector<OptionField<O>>& fields, const std::string& table,
              const std::string& skip, const O& o) {
  for (const OptionField<O>& row : fields) {
    if (row.key == skip) continue;
    s.setValue(QString::fromStdString(table + "." + row.key),
               QString::fromStdString(OptionExactText(row, o)));
  }
}

}  // namespace

ControllerSettings::ControllerSettings(Ui::RobotPanelForm& ui, QWidget* dialog_parent)
    : QObject(dialog_parent), ui_(ui), dialog_parent_(dialog_parent) {
  for (int b : {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200}) {
    ui_.baudCombo->addItem(QString::number(b), b);
  }
  ui_.baudCombo->setCurrentText("9600");
  for (int bits : {5, 6, 7, 8}) ui_.dataBitsCombo->addItem(tr("%1 data bits").arg(bits), bits);
  ui_.dataBitsCombo->setCurrentIndex(3);
  ui_.parityCombo->addItem(tr("no parity"), QChar('N'));
  ui_.parityCombo->addItem(tr("even parity"), QChar('E'));
  ui_.parityCombo->addItem(tr("odd parity"), QChar('O'));
  ui_.stopBitsCombo->addItem(tr("1 stop bit"), 1);
  ui_.stopBitsCombo->addItem(tr("2 stop bits"), 2);
  ui_.flowCombo->addItem(tr("none"), int(serial::FlowControl::kNone));
  ui_.flowCombo->addItem(tr("XON/XOFF (software)"), int(serial::FlowControl::kXonXoff));
  ui_.flowCombo->addItem(tr("RTS/CTS (hardware)"), int(serial::FlowControl::kRtsCts));

  const robot::ControllerProfile builtin;
  ui_.profileCombo->addItem(tr("Built-in: %1").arg(QString::fromStdString(builtin.name)),
                            QString());
  ui_.profileCombo->setItemData(0,
                                tr("The built-in profile (%1 mode): docs/profiles/default.profile")
                                    .arg(robot::SendModeName(builtin.mode)),
                                Qt::ToolTipRole);
  for (const QString& path : InstalledProfiles()) addProfileItem(path);
  connect(ui_.profileCombo, &QComboBox::activated, this, [this](int index) {
    if (!setProfileFile(ui_.profileCombo->itemData(index).toString())) {
      ui_.profileCombo->setCurrentIndex(last_profile_index_);
    }
  });
  connect(ui_.profileButton, &QPushButton::clicked, this, &ControllerSettings::chooseProfileFile);
  ui_.promptTimeout->setValue(0);
  ui_.motionTimeout->setValue(0);
}

void ControllerSettings::addProfileItem(const QString& path) {
  if (ui_.profileCombo->findData(path) >= 0) return;
  ui_.profileCombo->addItem(QFileInfo(path).fileName(), path);
  ui_.profileCombo->setItemData(ui_.profileCombo->count() - 1, path, Qt::ToolTipRole);
}

serial::PortSettings ControllerSettings::portSettings(const QString& device) const {
  serial::PortSettings p;
  p.port = device.toStdString();
  p.baud = ui_.baudCombo->currentData().toInt();
  p.data_bits = ui_.dataBitsCombo->currentData().toInt();
  p.parity = ui_.parityCombo->currentData().toChar().toLatin1();
  p.stop_bits = ui_.stopBitsCombo->currentData().toInt();
  p.flow = static_cast<serial::FlowControl>(ui_.flowCombo->currentData().toInt());
  return p;
}

void ControllerSettings::setPortSettings(const serial::PortSettings& p) {
  auto pick = [](QComboBox* combo, const QVariant& value) {
    const int i = combo->findData(value);
    if (i >= 0) combo->setCurrentIndex(i);
  };
  if (ui_.baudCombo->findData(p.baud) < 0) ui_.baudCombo->addItem(QString::number(p.baud), p.baud);
  pick(ui_.baudCombo, p.baud);
  pick(ui_.dataBitsCombo, p.data_bits);
  pick(ui_.parityCombo, QChar(p.parity));
  pick(ui_.stopBitsCombo, p.stop_bits);
  pick(ui_.flowCombo, int(p.flow));
}

void ControllerSettings::setPortEditable(bool editable) {
  for (QWidget* w :
       {static_cast<QWidget*>(ui_.baudCombo), static_cast<QWidget*>(ui_.dataBitsCombo),
        static_cast<QWidget*>(ui_.parityCombo), static_cast<QWidget*>(ui_.stopBitsCombo),
        static_cast<QWidget*>(ui_.flowCombo)}) {
    w->setEnabled(editable);
  }
}

QString ControllerSettings::shownProfilePath() const {
  return ui_.profileCombo->currentData().toString();
}

robot::SendSettings ControllerSettings::sendSettings() const {
  robot::SendSettings s;
  s.profile_path = shownProfilePath().toStdString();
  s.prompt_timeout_s = ui_.promptTimeout->value();
  s.motion_timeout_s = ui_.motionTimeout->value();
  return s;
}

bool ControllerSettings::loadProfile(robot::ControllerProfile* profile, QString* error) const {
  const Status s = robot::LoadSendProfile(sendSettings(), profile);
  if (!s.ok() && error) *error = QString::fromStdString(s.message());
  return s.ok();
}

bool ControllerSettings::setProfileFile(const QString& path) {
  robot::SendSettings settings;
  settings.profile_path = path.toStdString();
  robot::ControllerProfile profile;
  const Status s = robot::LoadSendProfile(settings, &profile);
  if (!s.ok()) {
    emit errorOccurred(tr("Controller profile: %1").arg(QString::fromStdString(s.message())));
    return false;
  }
  if (!path.isEmpty()) addProfileItem(path);
  ui_.profileCombo->setCurrentIndex(ui_.profileCombo->findData(path));
  last_profile_index_ = ui_.profileCombo->currentIndex();
  emit profileChanged(profile);
  return true;
}

void ControllerSettings::chooseProfileFile() {
  const QString path = QFileDialog::getOpenFileName(
      dialog_parent_, tr("Open controller profile"), RecentFiles::lastDir(),
      tr("Controller profiles (*.profile);;All files (*)"));
  if (!path.isEmpty()) setProfileFile(path);
}

void ControllerSettings::save(QSettings& s) const {
  // Under the keys of the port's and the send's table rows ("port.baud", "send.profile_path");
  // the device itself is the panel's port field, saved by the panel.
  for (const char* legacy : kLegacyKeys) s.remove(legacy);
  SaveRows(s, serial::PortOptionFields(), "port", "port", portSettings(QString()));
  SaveRows(s, robot::SendOptionFields(), "send", "", sendSettings());
}

void ControllerSettings::load(QSettings& s) {
  serial::PortSettings p = portSettings(QString());
  p.baud = s.value("baud", p.baud).toInt();
  p.data_bits = s.value("dataBits", p.data_bits).toInt();
  const QString parity = s.value("parity", "N").toString();
  if (!parity.isEmpty()) p.parity = parity.at(0).toLatin1();
  p.stop_bits = s.value("stopBits", p.stop_bits).toInt();
  serial::ParseFlowControl(s.value("flow", "none").toString().toStdString(), &p.flow);
  LoadRows(s, serial::PortOptionFields(), "port", "port", &p);
  setPortSettings(p);
  robot::SendSettings send;
  send.profile_path = s.value("profile").toString().toStdString();
  send.prompt_timeout_s = s.value("promptTimeout", 0.0).toDouble();
  send.motion_timeout_s = s.value("motionTimeout", 0.0).toDouble();
  LoadRows(s, robot::SendOptionFields(), "send", "", &send);
  ui_.promptTimeout->setValue(send.prompt_timeout_s);
  ui_.motionTimeout->setValue(send.motion_timeout_s);
  const QString profile = QString::fromStdString(send.profile_path);
  // A profile file that went away is named in Messages; the built-in profile is used meanwhile.
  if (!profile.isEmpty() && !setProfileFile(profile)) setProfileFile(QString());
}

}  // namespace armmimic::gui
