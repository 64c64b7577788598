// The robot panel's saved settings: the plan's mapping, filter and limits, the port and the
// Controller tab's fields (QSettings group "robot").
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QVariantList>

#include "controller_settings.h"
#include "robot_panel.h"

namespace armmimic::gui {

void RobotPanel::save(QSettings& s) const {
  const robot::PlannerOptions o = plannerOptions();
  s.beginGroup("robot");
  s.setValue("mappingKind", robot::SourceKindName(mapping_kind_));
  s.setValue("mirror", o.mapping.mirror);
  const robot::JointMap maps[3] = {o.mapping.j1, o.mapping.j2, o.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    s.setValue(QString("j%1/sign").arg(i + 1), maps[i].sign);
    s.setValue(QString("j%1/offset").arg(i + 1), maps[i].offset_deg);
  }
  s.setValue("cutoff", o.cutoff_hz);
  s.setValue("deadband", o.deadband_deg);
  s.setValue("minInterval", o.min_interval_s);
  s.setValue("maxGap", o.max_gap_s);
  s.setValue("clamp", o.clamp);
  QVariantList mins, maxs, speeds;
  for (int j = 0; j < robot::kJoints; ++j) {
    mins << o.limits.min_deg[j];
    maxs << o.limits.max_deg[j];
    speeds << o.limits.max_speed_deg_s[j];
  }
  s.setValue("limitsMin", mins);
  s.setValue("limitsMax", maxs);
  s.setValue("speedLimits", speeds);
  s.setValue("port", port_->currentText());
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
  const QString port = s.value("port").toString();
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
