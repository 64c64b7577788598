#include "robot_panel.h"

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
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>

#include "arm_view_3d.h"
#include "armmimic/core/atomic_file.h"
#include "armmimic/robot/val_program.h"
#include "armmimic/serial/serial_link.h"
#include "controller_settings.h"
#include "recent_files.h"
#include "robot_link.h"
#include "robot_option_keys.h"
#include "robot_preview.h"
#include "sim_controller.h"
#include "ui_robot_panel.h"
#include "wheel_guard.h"

namespace armmimic::gui {

RobotPanel::RobotPanel(QWidget* parent)
    : QWidget(parent),
      ui_(std::make_unique<Ui::RobotPanelForm>()),
      link_(new RobotLink(this)),
      sim_(new SimController(this)) {
  ui_->setupUi(this);  // the static layout: ui/robot_panel.ui
  controller_ = new ControllerSettings(*ui_, this);
  connect(controller_, &ControllerSettings::errorOccurred, this, &RobotPanel::errorOccurred);
  connect(controller_, &ControllerSettings::profileChanged, this,
          [this](const robot::ControllerProfile& profile) {
            profile_ = profile;
            emit message(tr("Controller profile: %1 (%2 mode)")
                             .arg(QString::fromStdString(profile.name))
                             .arg(robot::SendModeName(profile.mode)));
          });
  preview_ = ui_->robotPreview;
  view3d_ = new ArmView3D;
  ui_->view3dLayout->addWidget(view3d_);
  animate_button_ = ui_->animateButton;
  connect(ui_->compactButton, &QPushButton::toggled, this, [this](bool on) {
    ui_->previewStack->setCurrentIndex(on ? 1 : 0);
    ui_->resetViewButton->setEnabled(!on && view3d_->drawsIn3D());
  });
  connect(ui_->resetViewButton, &QPushButton::clicked, view3d_, &ArmView3D::resetView);
  // Without OpenGL the 3-D page only says why; the compact views show the arm.
  ui_->compactButton->setChecked(!view3d_->drawsIn3D());
  ui_->resetViewButton->setEnabled(view3d_->drawsIn3D() && !ui_->compactButton->isChecked());
  wirePlanBox();
  wireLinkBox();

  animate_.setInterval(40);
  connect(&animate_, &QTimer::timeout, this, [this] {
    anim_t_ += 0.04;
    if (anim_t_ > plan_.trajectory().duration_s()) anim_t_ = 0;
    showArm(plan_.PoseAt(anim_t_), tr("plan t=%1 s").arg(anim_t_, 0, 'f', 1));
  });
  connect(animate_button_, &QPushButton::toggled, this, [this](bool on) {
    if (on) {
      anim_t_ = 0;
      animate_.start();
    } else {
      animate_.stop();
      showPose();
    }
  });
  sim_poll_.setInterval(50);
  connect(&sim_poll_, &QTimer::timeout, this, [this] {
    if (!animate_.isActive() && sim_->isRunning() && link_->isConnected()) {
      showArm(sim_->joints(), tr("simulated controller"));
    }
  });
  connect(link_, &RobotLink::connectedChanged, this, [this](bool on, const QString& dev) {
    emit linkStateChanged(on ? tr("robot: %1").arg(dev) : tr("robot: not connected"));
    emit message(on ? tr("Connected to %1").arg(dev) : tr("Disconnected from %1").arg(dev));
    if (on && sim_->isRunning()) sim_poll_.start();
    updateButtons();
  });
  connect(link_, &RobotLink::error, this, &RobotPanel::errorOccurred);
  connect(link_, &RobotLink::note, this, &RobotPanel::message);
  connect(link_, &RobotLink::received, this,
          [this](const QString& line) { replies_->appendPlainText(line); });
  connect(link_, &RobotLink::progress, this, [this](int done, int total) {
    send_progress_->setRange(0, std::max(1, total));
    send_progress_->setValue(done);
  });
  connect(link_, &RobotLink::finished, this, [this](bool ok, const QString& msg) {
    if (ok || link_->wasAborted()) {  // an abort is the operator's own choice, not a fault
      emit message(msg);
    } else {
      emit errorOccurred(msg);
    }
    emit linkStateChanged(tr("robot: %1").arg(link_->device()));
    updateButtons();
    emit sendingChanged(false);
    emit sendFinished(ok);
  });
  const robot::JointLimits limits = plannerOptions().limits;
  preview_->setLimits(limits);
  view3d_->setLimits(limits);
  GuardWheel(this);
  updateButtons();
}

RobotPanel::~RobotPanel() {
  link_->disconnectPort();
  sim_->stop();
}

void RobotPanel::showArm(const robot::JointArray& joint_deg, const QString& caption) {
  preview_->setPose(joint_deg, caption);
  view3d_->setPose(joint_deg, caption);
}

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

void RobotPanel::wireLinkBox() {
  Ui::RobotPanelForm& u = *ui_;
  port_ = u.portCombo;
  sim_speed_ = u.simSpeed;
  sim_button_ = u.simButton;
  connect_button_ = u.connectButton;
  send_button_ = u.sendButton;
  pause_button_ = u.pauseButton;
  resume_button_ = u.resumeButton;
  abort_button_ = u.abortButton;
  send_progress_ = u.sendProgress;
  replies_ = u.replyLog;
  connect(u.rescanButton, &QPushButton::clicked, this, &RobotPanel::refreshPorts);
  connect(sim_button_, &QPushButton::clicked, this, [this] {
    if (sim_->isRunning()) {
      link_->disconnectPort();
      sim_->stop();
      sim_poll_.stop();
      emit message(tr("Simulated controller stopped"));
      refreshPorts();
      updateButtons();
    } else {
      startSimulator(sim_speed_->value());
    }
  });
  connect(connect_button_, &QPushButton::clicked, this, [this] {
    if (link_->isConnected()) {
      link_->disconnectPort();
    } else {
      connectTo(port_->currentText().section(' ', 0, 0));
    }
  });
  connect(send_button_, &QPushButton::clicked, this, [this] { sendPlan(false); });
  connect(resume_button_, &QPushButton::clicked, this, [this] { resumeSend(false); });
  connect(pause_button_, &QPushButton::toggled, link_, &RobotLink::setPaused);
  connect(abort_button_, &QPushButton::clicked, link_, &RobotLink::abort);
  refreshPorts();
}

void RobotPanel::refreshPorts() {
  const QString current = port_->currentText();
  port_->clear();
  if (sim_->isRunning()) port_->addItem(sim_->devicePath() + " (simulated)");
  for (const serial::PortInfo& info : serial::ListPorts()) {
    const QString description = QString::fromStdString(info.description);
    port_->addItem(QString::fromStdString(info.system_location) +
                   (description.isEmpty() ? QString() : " (" + description + ")"));
  }
  if (!current.isEmpty() && port_->findText(current) < 0 && !sim_->isRunning()) {
    port_->setEditText(current);
  }
}

void RobotPanel::updateButtons() {
  const bool connected = link_->isConnected();
  const bool sending = link_->isSending();
  connect_button_->setText(connected ? tr("Disconnect") : tr("Connect"));
  sim_button_->setText(sim_->isRunning() ? tr("Stop simulated controller")
                                         : tr("Start simulated controller"));
  send_button_->setEnabled(connected && plan_.planned() && !sending);
  resume_button_->setEnabled(connected && plan_.planned() && !sending);
  pause_button_->setEnabled(sending);
  abort_button_->setEnabled(sending);
  if (!sending) {
    const QSignalBlocker block(pause_button_);
    pause_button_->setChecked(false);
  }
  port_->setEnabled(!connected);
  controller_->setPortEditable(!connected);
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
  source_->setText(tr("%1 rows (%2)")
                       .arg(plan_.angles().rows.size())
                       .arg(QString::fromStdString(plan_.angles().Meta("engine", "?"))));
  followFileKind(robot::DetectSourceKind(plan_.angles()));
  replan();
}

bool RobotPanel::setValProgram(const QString& path) {
  animate_button_->setChecked(false);
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
    report_->setText(tr("<font color='#d03b2f'>Not planned: %1</font>")
                         .arg(QString::fromStdString(st.message()).toHtmlEscaped()) +
                     violations);
    // Planning runs on its own after every analysis and settings change: the reason stays in
    // the plan report (red) and is noted once in Messages, without raising an error the
    // operator did not ask for. Sending or exporting a refused plan is the error.
    const QString why = QString::fromStdString(st.message());
    if (why != last_plan_failure_) emit message(tr("Robot plan not made: %1").arg(why));
    last_plan_failure_ = why;
    updateButtons();
    showPose();
    return false;
  }
  last_plan_failure_.clear();
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

void RobotPanel::setVideoFrame(int frame) {
  video_frame_ = frame;
  showPose();
}

void RobotPanel::showPose() {
  if (animate_.isActive()) return;
  if (sim_->isRunning() && link_->isConnected()) return;  // the poll shows the controller
  robot::JointArray j;
  if (plan_.loaded() && plan_.MappedPose(video_frame_, plannerOptions(), &j)) {
    showArm(j, tr("frame %1 (mapped, unfiltered)").arg(video_frame_));
  } else if (plan_.planned()) {
    const int k = plan_.KeyframeForFrame(video_frame_);
    showArm(plan_.trajectory().keyframes[std::max(0, k)].joint_deg,
            tr("plan near frame %1").arg(video_frame_));
  }
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
  if (st) st = WriteFileAtomically(path.toStdString(), text);
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    return false;
  }
  emit message(tr("Exported the VAL program to %1").arg(path));
  return true;
}

void RobotPanel::exportValInteractive(const QString& suggested) {
  if (!plan_.planned()) {
    emit errorOccurred(tr("No plan to export: run the analysis, then check the Robot panel"));
    return;
  }
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export VAL program"),
      suggested.isEmpty() ? RecentFiles::lastDir() + "/program.val" : suggested,
      tr("VAL programs (*.val)"));
  if (!path.isEmpty()) exportVal(path);
}

bool RobotPanel::startSimulator(double time_scale) {
  QString error;
  if (!sim_->start(time_scale, plannerOptions().limits, &error)) {
    emit errorOccurred(tr("simulated controller: %1").arg(error));
    return false;
  }
  emit message(tr("Simulated controller on %1").arg(sim_->devicePath()));
  refreshPorts();
  port_->setCurrentIndex(0);
  updateButtons();
  return true;
}

bool RobotPanel::connectTo(const QString& device) {
  if (device.isEmpty()) {
    emit errorOccurred(tr("No port chosen: pick one or start the simulated controller"));
    return false;
  }
  return link_->connectPort(controller_->portSettings(device));
}

QString RobotPanel::replyLog() const { return replies_->toPlainText(); }

}  // namespace armmimic::gui
