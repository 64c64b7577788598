#include "robot_option_keys.h"

#include <QDoubleSpinBox>
#include <QVariant>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "armmimic/robot/option_tables.h"
#include "armmimic/serial/port_table.h"

namespace armmimic::gui {
namespace {

// Table key -> the Designer name of the field that edits it. A joint map's field is its offset
// (its sign is the combo box beside it); the limits are the rows of one table; the port's
// fields are on the Link and Controller tabs, the profile and the timeouts on the Controller tab.
const std::vector<std::pair<const char*, const char*>>& FieldNames() {
  static const std::vector<std::pair<const char*, const char*>> names = {
      {"planner.cutoff_hz", "cutoff"},
      {"planner.deadband_deg", "deadband"},
      {"planner.min_interval_s", "minInterval"},
      {"planner.max_gap_s", "maxGap"},
      {"planner.clamp", "clamp"},
      {"mapping.mirror", "mirror"},
      {"mapping.j1", "offset1"},
      {"mapping.j2", "offset2"},
      {"mapping.j3", "offset3"},
      {"limits.min_deg", "limitsTable"},
      {"limits.max_deg", "limitsTable"},
      {"limits.max_speed_deg_s", "limitsTable"},
      {"port.port", "portCombo"},
      {"port.baud", "baudCombo"},
      {"port.data_bits", "dataBitsCombo"},
      {"port.parity", "parityCombo"},
      {"port.stop_bits", "stopBitsCombo"},
      {"port.flow", "flowCombo"},
      {"send.profile_path", "profileCombo"},
      {"send.prompt_timeout_s", "promptTimeout"},
      {"send.motion_timeout_s", "motionTimeout"},
  };
  return names;
}

// The help and unit of the row `key` ("planner.cutoff_hz"), "" when there is no such row.
template <typename O>
QString RowTip(const std::vector<OptionField<O>>& fields, const std::string& table,
               const std::string& key) {
  if (key.rfind(table + ".", 0) != 0) return QString();
  const OptionField<O>* f = FindOptionField(fields, key.substr(table.size() + 1));
  if (!f) return QString();
  QString tip = QString::fromStdString(f->help);
  if (!f->unit.empty()) tip += QString(" (%1)").arg(QString::fromStdString(f->unit));
  return tip + QString("\nDefault %1").arg(QString::fromStdString(OptionDefaultText(*f)));
}

// A spin box that edits the number row `key` takes the row's decimals and range: the panel
// offers exactly what Check() accepts (an exclusive bound is one step inside; no upper bound
// keeps the form's, since a spin box needs one). False when `key` is no number row of `fields`.
template <typename O>
bool ApplyRowRange(const std::vector<OptionField<O>>& fields, const std::string& table,
                   const std::string& key, QDoubleSpinBox* box) {
  if (key.rfind(table + ".", 0) != 0) return false;
  const OptionField<O>* f = FindOptionField(fields, key.substr(table.size() + 1));
  if (!f || f->kind != OptionKind::kDouble) return false;
  box->setDecimals(f->decimals);
  box->setMinimum(f->min_exclusive ? f->min + std::pow(10.0, -f->decimals) : f->min);
  if (!std::isinf(f->max)) box->setMaximum(f->max);
  return true;
}

void ApplyRowRange(const std::string& key, QDoubleSpinBox* box) {
  if (ApplyRowRange(robot::PlannerOptionFields(), "planner", key, box)) return;
  ApplyRowRange(robot::SendOptionFields(), "send", key, box);
}

}  // namespace

void BindRobotOptionKeys(QWidget* panel) {
  for (const auto& [key, name] : FieldNames()) {
    QWidget* w = panel->findChild<QWidget*>(name);
    if (!w) continue;
    QStringList keys = w->property("optionKeys").toStringList();
    keys << key;
    w->setProperty("optionKeys", keys);
    w->setProperty("optionKey", keys.front());
    const std::string k = key;
    QString tip = RowTip(robot::PlannerOptionFields(), "planner", k);
    if (tip.isEmpty()) tip = RowTip(robot::MappingOptionFields(), "mapping", k);
    if (tip.isEmpty()) tip = RowTip(robot::LimitsOptionFields(), "limits", k);
    if (tip.isEmpty()) tip = RowTip(serial::PortOptionFields(), "port", k);
    if (tip.isEmpty()) tip = RowTip(robot::SendOptionFields(), "send", k);
    if (keys.size() == 1 && !tip.isEmpty()) {
      w->setToolTip(w->toolTip().isEmpty() ? tip : w->toolTip() + "\n" + tip);
    }
    if (auto* box = qobject_cast<QDoubleSpinBox*>(w)) ApplyRowRange(k, box);
  }
}

QWidget* RobotOptionField(QWidget* root, const QString& key) {
  for (QWidget* w : root->findChildren<QWidget*>()) {
    if (w->property("optionKeys").toStringList().contains(key)) return w;
  }
  return nullptr;
}

}  // namespace armmimic::gui
