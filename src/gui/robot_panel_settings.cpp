// The robot panel's saved settings: the plan's mapping, filter and limits, the port and the
// Controller tab's fields (QSettings group "robot"). Every setting is saved under the key of its
// option table row; the names earlier versions used are still read.
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QVariantList>
#include <string>
#include <utility>
#include <vector>

#include "armmimic/robot/option_tables.h"
#include "controller_settings.h"
#include "robot_option_keys.h"
#include "robot_panel.h"

namespace armmimic::gui {

namespace {

// The planner, mapping and limits values of `o` whose row has a field in `panel`, as
// ("TABLE.KEY", "VALUE") pairs.
std::vector<std::pair<std::string, std::string>> PanelSettings(QWidget* panel,
                                                               const robot::PlannerOptions& o) {
  std::vector<std::pair<std::string, std::string>> all =
      robot::OptionTableValues(robot::PlannerOptionFields(), "planner", o);
  for (auto& kv : robot::OptionTableValues(robot::MappingOptionFields(), "mapping", o.mapping)) {
    all.push_back(std::move(kv));
  }
  for (auto& kv : robot::OptionTableValues(robot::LimitsOptionFields(), "limits", o.limits)) {
    all.push_back(std::move(kv));
  }
  std::vector<std::pair<std::string, std::string>> offered;
  for (auto& kv : all) {
    if (RobotOptionField(panel, QString::fromStdString(kv.first))) {
      offered.push_back(std::move(kv));
    }
  }
  return offered;
}

}  // namespace

void RobotPanel::save(QSettings& s) const {
  const robot::PlannerOptions o = plannerOptions();
  s.beginGroup("robot");
  s.setValue("mappingKind", robot::SourceKindName(mapping_kind_));
  // Every plan setting the panel offers, under the key of its table row ("planner.cutoff_hz");
  // the names earlier versions saved them under are dropped.
  for (const char* legacy : {"mirror", "j1", "j2", "j3", "cutoff", "deadband", "minInterval",
                             "maxGap", "clamp", "limitsMin", "limitsMax", "speedLimits"}) {
    s.remove(legacy);
  }
  for (const auto& [key, value] : PanelSettings(const_cast<RobotPanel*>(this), o)) {
    s.setValue(QString::fromStdString(key), QString::fromStdString(value));
  }
  s.remove("port");  // the name earlier versions used
  s.setValue("port.port", port_->currentText());
  controller_->save(s);
  s.endGroup();
}

void RobotPanel::load(QSettings& s) {
  robot::PlannerOptions o = plannerOptions();
  s.beginGroup("robot");
  // The J1-J3 rows were saved showing this kind's mapping (its defaults, or changes to them).
  const robot::SourceKind saved_kind =
      s.value("mappingKind").toString() ==
              QLatin1String(robot::SourceKindName(robot::SourceKind::kMarker))
          ? robot::SourceKind::kMarker
          : robot::SourceKind::kArm;
  o.mapping.mirror = s.value("mirror", false).toBool();
  robot::JointMap* maps[3] = {&o.mapping.j1, &o.mapping.j2, &o.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    maps[i]->sign = s.value(QString("j%1/sign").arg(i + 1), maps[i]->sign).toDouble() < 0 ? -1 : 1;
    maps[i]->offset_deg = s.value(QString("j%1/offset").arg(i + 1), maps[i]->offset_deg).toDouble();
  }
  o.cutoff_hz = s.value("cutoff", o.cutoff_hz).toDouble();
  o.deadband_deg = s.value("deadband", o.deadband_deg).toDouble();
  o.min_interval_s = s.value("minInterval", o.min_interval_s).toDouble();
  o.max_gap_s = s.value("maxGap", o.max_gap_s).toDouble();
  o.clamp = s.value("clamp", false).toBool();
  const QVariantList mins = s.value("limitsMin").toList();
  const QVariantList maxs = s.value("limitsMax").toList();
  const QVariantList speeds = s.value("speedLimits").toList();
  if (mins.size() == robot::kJoints && maxs.size() == robot::kJoints &&
      speeds.size() == robot::kJoints) {
    for (int j = 0; j < robot::kJoints; ++j) {
      o.limits.min_deg[j] = mins[j].toDouble();
      o.limits.max_deg[j] = maxs[j].toDouble();
      o.limits.max_speed_deg_s[j] = speeds[j].toDouble();
    }
  }
  // The table keys last, over the names of earlier versions.
  for (const auto& [key, value] : PanelSettings(this, o)) {
    const QString name = QString::fromStdString(key);
    if (!s.contains(name)) continue;
    const QVariant v = s.value(name);
    const QString text =
        v.typeId() == QMetaType::QStringList ? v.toStringList().join(',') : v.toString();
    // An unreadable value (a hand-edited file) keeps the setting as it is.
    robot::SetPlannerSetting(key + "=" + text.toStdString(), &o);
  }
  const QString port = s.value(s.contains("port.port") ? "port.port" : "port").toString();
  controller_->load(s);
  s.endGroup();
  setMappingKind(saved_kind);
  setPlannerOptions(o);
  if (plan_.loaded()) {
    followFileKind(robot::DetectSourceKind(plan_.angles()));
    replan();
  }
  if (!port.isEmpty() && !port.contains("(simulated)")) port_->setEditText(port);
}

}  // namespace armmimic::gui
