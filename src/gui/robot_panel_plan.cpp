// The robot panel's plan box: the mapping, filter and limits fields, the angle file or VAL
// program they plan, the plan report and the VAL export.
#include <cmath>
#include <memory>
#include <vector>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>

#include "arm_view_3d.h"
#include "armmimic/core/output_file.h"
#include "field_error.h"
#include "recent_files.h"
#include "robot_option_keys.h"
#include "robot_panel.h"
#include "robot_preview.h"
#include "robot_words.h"
#include "ui_robot_panel.h"

namespace armmimic::gui {

void RobotPanel::wirePlanBox() {
  Ui::RobotPanelForm& u = *ui_;
  source_ = u.source;
  mirror_ = u.mirror;
  QComboBox* signs[3] = {u.sign1, u.sign2, u.sign3};
  QDoubleSpinBox* offsets[3] = {u.offset1, u.offset2, u.offset3};
  QLabel* labels[3] = {u.map1Label, u.map2Label, u.map3Label};
  for (int i = 0; i < 3; ++i) {
    sign_[i] = signs[i];
    sign_[i]->setItemData(0, 1.0);
    sign_[i]->setItemData(1, -1.0);
    offset_[i] = offsets[i];
    map_labels_[i] = labels[i];
  }
  cutoff_ = u.cutoff;
  deadband_ = u.deadband;
  min_interval_ = u.minInterval;
  max_gap_ = u.maxGap;
  clamp_ = u.clamp;
  limits_ = u.limitsTable;
  report_ = u.planReport;
  BindRobotOptionKeys(this);
  for (int j = 0; j < robot::kJoints; ++j) {
    for (int c = 0; c < 3; ++c) limits_->setItem(j, c, new QTableWidgetItem);
  }
  limits_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  limits_->setMinimumHeight(limits_->verticalHeader()->defaultSectionSize() * 7 + 4);
  showPlannerDefaults();
  auto replan_later = [this] {
    if (plan_.loaded() || plan_.fromProgram()) replan();
  };
  for (auto* s : u.planBox->findChildren<QDoubleSpinBox*>()) {
    connect(s, &QDoubleSpinBox::valueChanged, this, replan_later);
  }
  for (auto* c : u.planBox->findChildren<QComboBox*>()) {
    connect(c, &QComboBox::currentIndexChanged, this, replan_later);
  }
  for (auto* c : u.planBox->findChildren<QCheckBox*>()) {
    connect(c, &QCheckBox::toggled, this, replan_later);
  }
  connect(u.planDefaultsButton, &QPushButton::clicked, this, &RobotPanel::resetPlannerDefaults);
  connect(limits_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    // A cell holds a number of degrees (or degrees per second); anything else is put back.
    double* columns[3] = {shown_limits_.min_deg.data(), shown_limits_.max_deg.data(),
                          shown_limits_.max_speed_deg_s.data()};
    double& kept = columns[item->column()][item->row()];
    bool ok = false;
    const double v = item->text().trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
      const QString typed = item->text();
      {
        const QSignalBlocker block(limits_);
        item->setText(QString::number(kept));
      }
      emit errorOccurred(tr("Limits: '%1' is not a number; J%2 %3 stays %4")
                             .arg(typed)
                             .arg(item->row() + 1)
                             .arg(limits_->horizontalHeaderItem(item->column())->text())
                             .arg(kept));
      return;
    }
    kept = v;
    if (plan_.loaded() || plan_.fromProgram()) replan();
  });
}

// The planner's documented defaults, for the kind of angles shown (replans a loaded plan once).
void RobotPanel::showPlannerDefaults() {
  robot::PlannerOptions d;
  d.mapping = robot::MappingOptions::Default(mapping_kind_);
  std::vector<std::unique_ptr<QSignalBlocker>> quiet;  // one replan at the end, not one per field
  for (QWidget* w : ui_->planBox->findChildren<QWidget*>()) {
    quiet.push_back(std::make_unique<QSignalBlocker>(w));
  }
  setPlannerOptions(d);
}

void RobotPanel::resetPlannerDefaults() {
  showPlannerDefaults();
  if (!plan_.loaded() && !plan_.fromProgram()) {
    preview_->setLimits(plannerOptions().limits);
    view3d_->setLimits(plannerOptions().limits);
  }
  emit message(tr("Robot plan settings and limits reset to their defaults"));
}

robot::PlannerOptions RobotPanel::plannerOptions() const {
  robot::PlannerOptions o;
  o.mapping = robot::MappingOptions::Default(
      plan_.loaded() ? robot::DetectSourceKind(plan_.angles()) : robot::SourceKind::kArm);
  robot::JointMap* maps[3] = {&o.mapping.j1, &o.mapping.j2, &o.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    maps[i]->sign = sign_[i]->currentData().toDouble();
    maps[i]->offset_deg = offset_[i]->value();
  }
  o.mapping.mirror = mirror_->isChecked();
  o.cutoff_hz = cutoff_->value();
  o.deadband_deg = deadband_->value();
  o.min_interval_s = min_interval_->value();
  o.max_interval_s = std::max(o.max_interval_s, o.min_interval_s);
  o.max_gap_s = max_gap_->value();
  o.clamp = clamp_->isChecked();
  for (int j = 0; j < robot::kJoints; ++j) {
    o.limits.min_deg[j] = limits_->item(j, 0)->text().toDouble();
    o.limits.max_deg[j] = limits_->item(j, 1)->text().toDouble();
    o.limits.max_speed_deg_s[j] = limits_->item(j, 2)->text().toDouble();
  }
  return o;
}

void RobotPanel::setPlannerOptions(const robot::PlannerOptions& o) {
  const robot::JointMap maps[3] = {o.mapping.j1, o.mapping.j2, o.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    sign_[i]->setCurrentIndex(maps[i].sign > 0 ? 0 : 1);
    offset_[i]->setValue(maps[i].offset_deg);
  }
  mirror_->setChecked(o.mapping.mirror);
  cutoff_->setValue(o.cutoff_hz);
  deadband_->setValue(o.deadband_deg);
  min_interval_->setValue(o.min_interval_s);
  max_gap_->setValue(o.max_gap_s);
  clamp_->setChecked(o.clamp);
  const QSignalBlocker block(limits_);
  shown_limits_ = o.limits;
  for (int j = 0; j < robot::kJoints; ++j) {
    limits_->item(j, 0)->setText(QString::number(o.limits.min_deg[j]));
    limits_->item(j, 1)->setText(QString::number(o.limits.max_deg[j]));
    limits_->item(j, 2)->setText(QString::number(o.limits.max_speed_deg_s[j]));
  }
  if (plan_.loaded() || plan_.fromProgram()) replan();
}

void RobotPanel::setAngleFile(const QString& path) {
  animate_button_->setChecked(false);
  angles_changing_ = false;
  resume_offered_ = false;
  if (path.isEmpty()) {
    plan_.Clear();
    source_->setText(tr("no angles yet: run the analysis"));
    report_->clear();
    updateButtons();
    return;
  }
  const Status st = plan_.Load(path.toStdString());
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    updateButtons();
    return;
  }
  // The arm a pose file follows (one of the two files of side both, or the one arm named).
  const std::string side = plan_.angles().Meta("pose.side", "");
  const QString arm = side == "left"    ? tr(", the left arm")
                      : side == "right" ? tr(", the right arm")
                                        : QString();
  source_->setText(tr("%1 rows (%2%3)")
                       .arg(plan_.angles().rows.size())
                       .arg(QString::fromStdString(plan_.angles().Meta("engine", "?")), arm));
  followFileKind(robot::DetectSourceKind(plan_.angles()));
  replan();
  offerResume();
}

bool RobotPanel::setValProgram(const QString& path) {
  animate_button_->setChecked(false);
  angles_changing_ = false;
  const Status st = plan_.LoadProgram(path.toStdString(), profile_);
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    source_->setText(tr("no angles yet: run the analysis"));
    report_->clear();
    updateButtons();
    return false;
  }
  emit message(tr("Opened the VAL program %1").arg(path));
  replan();
  source_->setText(tr("%1: %2 moves, sent as written (the plan settings do not apply)")
                       .arg(QFileInfo(path).fileName())
                       .arg(plan_.trajectory().keyframes.size()));
  offerResume();
  return plan_.planned();
}

void RobotPanel::setMappingKind(robot::SourceKind kind) {
  mapping_kind_ = kind;
  const bool marker = kind == robot::SourceKind::kMarker;
  map_labels_[1]->setText(marker ? tr("J2 = bend") : tr("J2 = elevation"));
  map_labels_[2]->setText(marker ? tr("J3 (held)") : tr("J3 = flexion"));
}

// As `plan` does on the command line: mapping rows left at one kind's defaults switch to the
// defaults of the new file's kind (marker views drive J2 by the bend, arm files by the
// elevation). Rows the operator changed are kept, and Messages says so.
void RobotPanel::followFileKind(robot::SourceKind kind) {
  if (kind == mapping_kind_) return;
  const robot::MappingOptions old_defaults = robot::MappingOptions::Default(mapping_kind_);
  const robot::JointMap old_maps[3] = {old_defaults.j1, old_defaults.j2, old_defaults.j3};
  bool untouched = true;
  for (int i = 0; i < 3; ++i) {
    untouched = untouched && sign_[i]->currentData().toDouble() == old_maps[i].sign &&
                offset_[i]->value() == old_maps[i].offset_deg;
  }
  setMappingKind(kind);
  const bool marker = kind == robot::SourceKind::kMarker;
  if (!untouched) {
    emit message(tr("Robot mapping: your J1-J3 settings are kept for this %1 file; the defaults "
                    "for it differ")
                     .arg(marker ? tr("marker") : tr("arm")));
    return;
  }
  const robot::MappingOptions d = robot::MappingOptions::Default(kind);
  const robot::JointMap maps[3] = {d.j1, d.j2, d.j3};
  for (int i = 0; i < 3; ++i) {
    const QSignalBlocker block_sign(sign_[i]), block_offset(offset_[i]);
    sign_[i]->setCurrentIndex(maps[i].sign > 0 ? 0 : 1);
    offset_[i]->setValue(maps[i].offset_deg);
  }
}

bool RobotPanel::replan() {
  const robot::PlannerOptions options = plannerOptions();
  preview_->setLimits(options.limits);
  view3d_->setLimits(options.limits);
  const std::vector<LimitViolation> bad = plan_.Violations(options);
  QString violations;
  if (!bad.empty()) {
    violations = tr("<br><font color='#d03b2f'>%1 frame(s) map outside the limits, first: frame "
                    "%2 J%3 = %4°</font>")
                     .arg(bad.size())
                     .arg(bad.front().frame)
                     .arg(bad.front().joint + 1)
                     .arg(bad.front().deg, 0, 'f', 1);
  }
  const Status st = options.Check() ? plan_.Plan(options) : options.Check();
  view3d_->setPath(plan_.planned() ? plan_.trajectory() : robot::Trajectory());
  if (!st) {
    // In the panel's words: the field's label (Status::key()), never a command-line flag.
    QWidget* field = RobotOptionField(this, QString::fromStdString(st.key()));
    const QString why = field ? FieldLabel(field) + ": " + QString::fromStdString(st.message())
                              : RobotPanelWords(st);
    report_->setText(tr("<font color='#d03b2f'>Not planned: %1</font>").arg(why.toHtmlEscaped()) +
                     violations);
    // Planning runs on its own after every analysis and settings change: the reason stays in
    // the plan report (red) and is noted once in Messages, without raising an error the
    // operator did not ask for. Sending or exporting a refused plan is the error, and frames
    // the field.
    last_plan_failure_key_ = QString::fromStdString(st.key());
    if (why != last_plan_failure_) emit message(tr("Robot plan not made: %1").arg(why));
    last_plan_failure_ = why;
    updateButtons();
    showPose();
    return false;
  }
  last_plan_failure_.clear();
  last_plan_failure_key_.clear();
  const robot::PlanReport& r = plan_.report();
  report_->setText(tr("%1 moves over %2 s (%3 rows used, %4 filled, %5 clamped, +%6 s for speed)")
                       .arg(plan_.trajectory().keyframes.size())
                       .arg(plan_.trajectory().duration_s(), 0, 'f', 1)
                       .arg(r.used_rows)
                       .arg(r.filled_rows)
                       .arg(r.clamped_rows)
                       .arg(r.stretch_s, 0, 'f', 1) +
                   // Still images (marker views) have no frame rate: the planner leaves
                   // them unfiltered, whatever the cutoff setting.
                   (r.filter_cutoff_hz == 0 && options.cutoff_hz > 0
                        ? tr("<br>Still images: no low-pass filter.")
                        : QString()) +
                   violations);
  updateButtons();
  showPose();
  return true;
}

bool RobotPanel::exportVal(const QString& path) {
  std::vector<NamedPath> inputs = inputs_ ? inputs_() : std::vector<NamedPath>();
  if (!plan_.angle_path().empty()) inputs.push_back({"the angle file", plan_.angle_path()});
  Status st = CheckOutputsAreNotInputs(inputs, {{"the VAL program", path.toStdString()}});
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    return false;
  }
  std::string text;
  st = plan_.ValText(profile_, &text);
  if (st) st = WriteOutputFile(path.toStdString(), text);
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    return false;
  }
  emit message(tr("Exported the VAL program to %1").arg(path));
  return true;
}

void RobotPanel::exportValInteractive(const QString& suggested) {
  if (!plan_.planned()) {
    MarkFieldError(RobotOptionField(this, last_plan_failure_key_));
    emit errorOccurred(
        last_plan_failure_.isEmpty()
            ? tr("No plan to export: run the analysis, then check the Robot panel")
            : tr("No plan to export: the plan was refused: %1").arg(last_plan_failure_));
    return;
  }
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export VAL program"),
      suggested.isEmpty() ? RecentFiles::lastDir() + "/program.val" : suggested,
      tr("VAL programs (*.val)"));
  if (!path.isEmpty()) exportVal(path);
}

}  // namespace armmimic::gui
